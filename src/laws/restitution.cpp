#include "laws/restitution.hpp"

#include <cmath>
#include <numbers>

namespace blockdem {

namespace {
using std::numbers::pi;
}

double damping_ratio_paper(double e) {
    const double l = std::log(e);
    return -l / std::sqrt(pi * pi + l * l);
}

double restitution_paper(double h_n) { return std::exp(-pi * h_n / std::sqrt(1.0 - h_n * h_n)); }

// Schwager and Poeschel (2007): with beta = h w0 and w = w0 sqrt(1 - h^2), the force
// k x + c x' vanishes before the overlap does, and the rebound is
//   e = exp(-(beta / w) (pi - atan(2 beta w / (w0^2 - 2 beta^2))))  for h < 1/sqrt(2),
//   e = exp(-(beta / w) atan(2 beta w / (2 beta^2 - w0^2)))         for 1/sqrt(2) < h < 1,
//   e = exp(-(beta / w) pi / 2)                                     at h = 1/sqrt(2),
// and for h >= 1 (overdamped) the force vanishes at once on a separation time found from the
// exponential solution; we write all three cases in terms of h with w0 = 1.
double restitution_no_tension(double h) {
    if (h <= 0.0) return 1.0;
    if (h < 1.0) {
        const double w = std::sqrt(1.0 - h * h);
        const double ratio = h / w;
        const double denominator = 1.0 - 2.0 * h * h;
        double angle;
        if (std::abs(denominator) < 1e-14)
            angle = pi / 2.0;
        else if (denominator > 0.0)
            angle = pi - std::atan(2.0 * h * w / denominator);
        else
            angle = std::atan(2.0 * h * w / -denominator);
        return std::exp(-ratio * angle);
    }
    // Overdamped: x = A (exp(r1 t) - exp(r2 t)), r1,2 = -h +- sqrt(h^2 - 1). The force
    // 2 h x' + x is zero at t* where ((2 h r1 + 1)/(2 h r2 + 1)) = exp((r2 - r1) t*), and
    // e = |x'(t*)| / x'(0).
    if (h == 1.0) {
        // Critically damped: x = t exp(-t); force zero where 2(1 - t) + t = 0, t = 2.
        const double t = 2.0;
        return std::abs((1.0 - t) * std::exp(-t));
    }
    const double s = std::sqrt(h * h - 1.0);
    const double r1 = -h + s;
    const double r2 = -h - s;
    const double t = std::log((2.0 * h * r1 + 1.0) / (2.0 * h * r2 + 1.0)) / (r2 - r1);
    const double velocity = (r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)) / (r1 - r2);
    return std::abs(velocity);
}

double damping_ratio_rebound(double e) {
    if (e >= 1.0) return 0.0;
    // restitution_no_tension falls monotonically from 1 (h = 0) towards 0 (h -> infinity).
    double lo = 0.0;
    double hi = 1.0;
    while (restitution_no_tension(hi) > e) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (restitution_no_tension(mid) > e)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

double damping_ratio_for(double e, RestitutionMeaning meaning) {
    return meaning == RestitutionMeaning::paper ? damping_ratio_paper(e) : damping_ratio_rebound(e);
}

double damping_ratio_for(double e, RestitutionMeaning meaning, ContactTermination termination) {
    if (termination == ContactTermination::zero_overlap) return damping_ratio_paper(e);
    return damping_ratio_for(e, meaning);
}

double restitution_of(double h_n, ContactTermination termination) {
    if (termination == ContactTermination::no_tension) return restitution_no_tension(h_n);
    return h_n < 1.0 ? restitution_paper(h_n) : 0.0;
}

}  // namespace blockdem
