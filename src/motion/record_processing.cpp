#include "motion/record_processing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "motion/intensity_measures.hpp"
#include "motion/records/ground_motion_record.hpp"

namespace blockdem {
namespace {

struct MethodName {
    BaselineMethod method;
    std::string_view name;
};
constexpr std::array method_names{
    MethodName{BaselineMethod::none, "none"},
    MethodName{BaselineMethod::mean, "mean"},
    MethodName{BaselineMethod::linear, "linear"},
    MethodName{BaselineMethod::polynomial, "polynomial"},
    MethodName{BaselineMethod::displacement_polynomial, "displacement_polynomial"},
};

// Solves the square system m x = rhs by Gaussian elimination with partial pivoting.
std::vector<double> solve(std::vector<std::vector<double>> m, std::vector<double> rhs) {
    const std::size_t n = rhs.size();
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
        if (m[pivot][col] == 0.0) throw std::invalid_argument("baseline fit: singular system (record too short for this order)");
        std::swap(m[col], m[pivot]);
        std::swap(rhs[col], rhs[pivot]);
        for (std::size_t r = col + 1; r < n; ++r) {
            const double f = m[r][col] / m[col][col];
            for (std::size_t c = col; c < n; ++c) m[r][c] -= f * m[col][c];
            rhs[r] -= f * rhs[col];
        }
    }
    std::vector<double> x(n);
    for (std::size_t r = n; r-- > 0;) {
        double sum = rhs[r];
        for (std::size_t c = r + 1; c < n; ++c) sum -= m[r][c] * x[c];
        x[r] = sum / m[r][r];
    }
    return x;
}

// min |sum_j c_j fit_j - target|^2 subject to sum_j c_j ends_j[i] = end_values[i] (Lagrange
// multipliers: the KKT system [A^T A, C^T; C, 0]).
std::vector<double> constrained_fit(const std::vector<std::vector<double>>& fit, const std::vector<double>& target,
                                    const std::vector<std::array<double, 2>>& ends, const std::array<double, 2>& end_values) {
    const std::size_t m = fit.size();
    std::vector<std::vector<double>> kkt(m + 2, std::vector<double>(m + 2, 0.0));
    std::vector<double> rhs(m + 2, 0.0);
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = 0; j < m; ++j) kkt[i][j] = std::inner_product(fit[i].begin(), fit[i].end(), fit[j].begin(), 0.0);
        rhs[i] = std::inner_product(fit[i].begin(), fit[i].end(), target.begin(), 0.0);
        for (std::size_t e = 0; e < 2; ++e) kkt[i][m + e] = kkt[m + e][i] = ends[i][e];
    }
    rhs[m] = end_values[0];
    rhs[m + 1] = end_values[1];
    std::vector<double> x = solve(std::move(kkt), std::move(rhs));
    x.resize(m);
    return x;
}

// Acceleration corrections psi_p = d^n/dt^n tau^p (tau = t / T), p = lowest..order, where n = 1
// for a velocity fit and 2 for a displacement fit. Each is integrated exactly as the table does,
// so the end conditions hold to rounding, not just to O(dt^2).
std::vector<double> subtract_fitted_drift(std::span<const double> a, double dt, int lowest, int order, int derivative) {
    const double total = static_cast<double>(a.size() - 1) * dt;  // [s]
    const RecordKinematics record = integrate_record(a, dt);
    std::vector<std::vector<double>> psi, fit;
    std::vector<std::array<double, 2>> ends;
    for (int p = lowest; p <= order; ++p) {
        std::vector<double> col(a.size());
        const double falling = derivative == 1 ? p : p * (p - 1);  // d^n/dtau^n tau^p = falling tau^(p - n)
        for (std::size_t k = 0; k < a.size(); ++k)
            col[k] = falling * std::pow(static_cast<double>(k) * dt / total, p - derivative) / std::pow(total, derivative);
        const RecordKinematics k = integrate_record(col, dt);
        fit.push_back(derivative == 1 ? k.velocity_m_s : k.displacement_m);
        ends.push_back({k.velocity_m_s.back(), k.displacement_m.back()});
        psi.push_back(std::move(col));
    }
    const auto& target = derivative == 1 ? record.velocity_m_s : record.displacement_m;
    const auto c = constrained_fit(fit, target, ends, {record.velocity_m_s.back(), record.displacement_m.back()});
    std::vector<double> out(a.begin(), a.end());
    for (std::size_t j = 0; j < psi.size(); ++j)
        for (std::size_t k = 0; k < a.size(); ++k) out[k] -= c[j] * psi[j][k];
    return out;
}

// v ends at 0: subtract the constant acceleration v_end / T.
std::vector<double> subtract_end_velocity(std::span<const double> a, double dt) {
    const double slope = integrate_record(a, dt).velocity_m_s.back() / (static_cast<double>(a.size() - 1) * dt);
    std::vector<double> out(a.begin(), a.end());
    for (double& x : out) x -= slope;
    return out;
}

void check_order(const BaselineCorrection& c, int lowest) {
    if (c.order < lowest || c.order > 6)
        throw std::invalid_argument(fmt::format("baseline order {} is out of range {}..6 for {}", c.order, lowest,
                                                baseline_method_name(c.method)));
}

}  // namespace

BaselineMethod parse_baseline_method(std::string_view name) {
    for (const auto& m : method_names)
        if (m.name == name) return m.method;
    throw std::invalid_argument(fmt::format("unknown baseline correction '{}'; use one of: {}", name, baseline_method_names()));
}

std::string_view baseline_method_name(BaselineMethod method) {
    for (const auto& m : method_names)
        if (m.method == method) return m.name;
    return "unknown";
}

std::string baseline_method_names() { return "none, mean, linear, polynomial, displacement_polynomial"; }

std::vector<double> correct_baseline(std::span<const double> a, double dt, BaselineCorrection correction) {
    if (a.size() < 3 || correction.method == BaselineMethod::none) return {a.begin(), a.end()};
    switch (correction.method) {
        case BaselineMethod::mean: {
            const double mean = std::accumulate(a.begin(), a.end(), 0.0) / static_cast<double>(a.size());
            std::vector<double> out(a.begin(), a.end());
            for (double& x : out) x -= mean;
            return out;
        }
        case BaselineMethod::linear: return subtract_end_velocity(a, dt);
        case BaselineMethod::polynomial:
            check_order(correction, 2);
            return subtract_fitted_drift(a, dt, 1, correction.order, 1);
        case BaselineMethod::displacement_polynomial:
            check_order(correction, 3);
            return subtract_fitted_drift(a, dt, 2, correction.order, 2);
        case BaselineMethod::none: break;
    }
    return {a.begin(), a.end()};
}

double scale_factor_for_pga(std::span<const double> a, double target_pga_m_s2) {
    double peak = 0.0;
    for (double x : a) peak = std::max(peak, std::abs(x));
    if (peak == 0.0) throw std::invalid_argument("cannot scale a record of zeros to a target PGA");
    return target_pga_m_s2 / peak;
}

std::vector<double> time_window(std::span<const double> a, double dt, double start_s, double duration_s) {
    const double tolerance = 1e-9;  // in samples: a start given as 2.15 s must include t = 2.15 s
    // Sample indices are found as real numbers and compared with the record before any cast:
    // start = 1e19 s must be refused, not wrapped to sample 0.
    const double samples = static_cast<double>(a.size());
    const double first_index = std::max(0.0, std::ceil(start_s / dt - tolerance));
    double last_index = samples - 1.0;
    if (duration_s > 0.0) last_index = std::min(last_index, std::floor((start_s + duration_s) / dt + tolerance));
    if (!(first_index < samples) || !(last_index >= first_index + 1.0))
        throw std::invalid_argument(fmt::format("the window {} s + {} s leaves fewer than 2 samples of a {} s record", start_s,
                                                duration_s, static_cast<double>(a.size() - 1) * dt));
    const auto first = static_cast<std::ptrdiff_t>(first_index);
    const auto last = static_cast<std::ptrdiff_t>(last_index);
    return {a.begin() + first, a.begin() + last + 1};
}

void apply_cosine_taper(std::vector<double>& a, double dt, double taper_s) {
    const auto n = static_cast<std::size_t>(std::min(static_cast<double>(a.size() / 2), std::round(taper_s / dt)));
    for (std::size_t k = 0; k < n; ++k) {
        const double w = 0.5 * (1.0 - std::cos(std::numbers::pi * static_cast<double>(k) / static_cast<double>(n)));
        a[k] *= w;
        a[a.size() - 1 - k] *= w;
    }
}

std::size_t padding_samples(std::size_t samples, double dt, double pad_s) {
    const double added = pad_s > 0.0 ? std::round(pad_s / dt) : 0.0;
    if (!(added <= static_cast<double>(max_record_samples - std::min(samples, max_record_samples))))
        throw std::invalid_argument(fmt::format("{:g} s of padding at dt = {:g} s adds {:g} samples to {}; a motion may have at "
                                                "most {} samples",
                                                pad_s, dt, added, samples, max_record_samples));
    return static_cast<std::size_t>(added);
}

void pad_with_zeros(std::vector<double>& a, double dt, double pad_s) {
    a.resize(a.size() + padding_samples(a.size(), dt, pad_s), 0.0);
}

std::vector<double> process_record(std::span<const double> a, double dt, const RecordProcessing& steps) {
    std::vector<double> out = time_window(a, dt, steps.start_s, steps.duration_s);
    apply_cosine_taper(out, dt, steps.taper_s);
    // Padding before the correction: the end conditions then hold at the very end of the series,
    // after which the table stays at rest (a last sample ramping to zero would otherwise leave
    // a velocity of a_end dt / 2).
    pad_with_zeros(out, dt, steps.pad_s);
    out = correct_baseline(out, dt, steps.baseline);
    const double factor = steps.target_pga_m_s2 ? scale_factor_for_pga(out, *steps.target_pga_m_s2) : steps.scale;
    for (double& x : out) x *= factor;
    return out;
}

ResampledRecord resample_keeping_samples(std::span<const double> a, double dt, double step, double start_time_s) {
    if (a.size() < 2 || !(dt > 0.0) || !(step > 0.0)) throw std::invalid_argument("resampling needs 2 samples, dt > 0, step > 0");
    ResampledRecord out;
    const double end = static_cast<double>(a.size() - 1) * dt;
    std::size_t grid = 0;
    for (std::size_t k = 0; k + 1 < a.size(); ++k) {
        const double t0 = static_cast<double>(k) * dt;
        out.time_s.push_back(start_time_s + t0);
        out.acceleration_m_s2.push_back(a[k]);
        while (static_cast<double>(grid) * step <= t0 + 1e-9 * dt) ++grid;  // grid points past this sample
        for (double t = static_cast<double>(grid) * step; t < t0 + dt - 1e-9 * dt; t = static_cast<double>(++grid) * step) {
            out.time_s.push_back(start_time_s + t);
            out.acceleration_m_s2.push_back(a[k] + (a[k + 1] - a[k]) * (t - t0) / dt);
        }
    }
    out.time_s.push_back(start_time_s + end);
    out.acceleration_m_s2.push_back(a.back());
    return out;
}

double step_dividing(double dt, double max_step) {
    if (!(dt > 0.0) || !(max_step > 0.0)) throw std::invalid_argument("step_dividing needs dt > 0 and max_step > 0");
    return dt / std::ceil(dt / max_step * (1.0 - 1e-12));
}

}  // namespace blockdem
