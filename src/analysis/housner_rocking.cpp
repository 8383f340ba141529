#include "analysis/housner_rocking.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <numbers>

namespace blockdem {

double HousnerBlock::alpha_rad() const { return std::atan(half_width_m / half_height_m); }
double HousnerBlock::p_rad_s() const {
    const double radius_m = std::hypot(half_width_m, half_height_m);
    if (corner_inertia_ratio > 0.0) return std::sqrt(gravity_m_s2 / (corner_inertia_ratio * radius_m));
    return std::sqrt(3.0 * gravity_m_s2 / (4.0 * radius_m));
}
// Angular momentum about the new corner kept through the impact: I_c w+ = (I_c - 2 m R^2 sin^2
// alpha) w-, so r = 1 - 2 sin^2 alpha / ratio (1 - 1.5 sin^2 alpha for the rectangle).
double HousnerBlock::housner_restitution() const {
    const double s = std::sin(alpha_rad());
    if (corner_inertia_ratio > 0.0) return 1.0 - 2.0 * s * s / corner_inertia_ratio;
    return 1.0 - 1.5 * s * s;
}

namespace {

// Angular acceleration on the corner selected by side (+1: left corner, theta >= 0).
double angular_acceleration(const HousnerBlock& b, double side, double theta, double a_g) {
    const double p = b.p_rad_s();
    const double alpha = b.alpha_rad();
    return -p * p * (side * std::sin(alpha - side * theta) - a_g / b.gravity_m_s2 * std::cos(alpha - side * theta));
}

}  // namespace

RockingResult housner_rocking(const HousnerBlock& block, const ComponentMotion& base, double theta0, double omega0,
                              double end_s, double dt) {
    const double r = block.restitution >= 0.0 ? block.restitution : block.housner_restitution();
    const double tan_alpha = std::tan(block.alpha_rad());
    RockingResult out;
    double theta = theta0;
    double omega = omega0;
    bool rocking = theta0 != 0.0 || omega0 != 0.0;
    double side = theta0 != 0.0 ? std::copysign(1.0, theta0) : std::copysign(1.0, omega0);
    // Counted as a double before the cast: every step is kept in the history.
    const double step_count = std::round(end_s / dt);
    if (!(step_count <= 1e8))
        throw std::invalid_argument(fmt::format("Housner rocking: {:g} s at dt = {:g} s is {:g} steps; at most 1e8", end_s, dt,
                                                step_count));
    const auto steps = static_cast<long>(step_count);
    out.history.push_back({0.0, theta, omega});
    for (long n = 0; n < steps; ++n) {
        const double t = n * dt;
        if (!rocking) {
            const double a = sample(base, t).acceleration_m_s2;
            if (std::abs(a) > block.gravity_m_s2 * tan_alpha) {
                rocking = true;
                side = a > 0.0 ? 1.0 : -1.0;
            }
        }
        if (rocking) {
            auto f = [&](double tt, double th) { return angular_acceleration(block, side, th, sample(base, tt).acceleration_m_s2); };
            const double k1t = omega, k1w = f(t, theta);
            const double k2t = omega + 0.5 * dt * k1w, k2w = f(t + 0.5 * dt, theta + 0.5 * dt * k1t);
            const double k3t = omega + 0.5 * dt * k2w, k3w = f(t + 0.5 * dt, theta + 0.5 * dt * k2t);
            const double k4t = omega + dt * k3w, k4w = f(t + dt, theta + dt * k3t);
            const double theta_next = theta + dt / 6.0 * (k1t + 2 * k2t + 2 * k3t + k4t);
            const double omega_next = omega + dt / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
            if (theta_next * side < 0.0) {
                // Impact inside the step: stop at theta = 0, switch corner, keep r of the speed.
                const double f0 = theta / (theta - theta_next);
                const double omega_impact = omega + f0 * (omega_next - omega);
                out.impact_times_s.push_back(t + f0 * dt);
                theta = 0.0;
                omega = r * omega_impact;
                side = -side;
            } else {
                theta = theta_next;
                omega = omega_next;
            }
            // A block at rest on its base with a small base acceleration stops rocking.
            if (theta == 0.0 && std::abs(omega) < 1e-9) rocking = false;
        }
        out.peak_abs_theta_rad = std::max(out.peak_abs_theta_rad, std::abs(theta));
        out.history.push_back({t + dt, theta, omega});
        if (std::abs(theta) >= std::numbers::pi / 2.0) {
            out.overturned = true;
            break;
        }
    }
    return out;
}

}  // namespace blockdem
