#include "motion/record_processing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "motion/intensity_measures.hpp"

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

// Least squares min |sum_j c_j columns_j - rhs| by modified Gram-Schmidt (well conditioned
// enough for the few normalized monomials used here).
std::vector<double> least_squares(std::vector<std::vector<double>> columns, std::vector<double> rhs) {
    const std::size_t m = columns.size();
    std::vector<std::vector<double>> r(m, std::vector<double>(m, 0.0));
    for (std::size_t j = 0; j < m; ++j) {
        for (std::size_t i = 0; i < j; ++i) {
            r[i][j] = std::inner_product(columns[i].begin(), columns[i].end(), columns[j].begin(), 0.0);
            for (std::size_t k = 0; k < rhs.size(); ++k) columns[j][k] -= r[i][j] * columns[i][k];
        }
        r[j][j] = std::sqrt(std::inner_product(columns[j].begin(), columns[j].end(), columns[j].begin(), 0.0));
        if (r[j][j] == 0.0) throw std::invalid_argument("baseline fit: the record is too short for this order");
        for (double& x : columns[j]) x /= r[j][j];
    }
    std::vector<double> qtb(m);
    for (std::size_t j = 0; j < m; ++j) qtb[j] = std::inner_product(columns[j].begin(), columns[j].end(), rhs.begin(), 0.0);
    std::vector<double> c(m);
    for (std::size_t j = m; j-- > 0;) {
        double s = qtb[j];
        for (std::size_t i = j + 1; i < m; ++i) s -= r[j][i] * c[i];
        c[j] = s / r[j][j];
    }
    return c;
}

// Fits y(t) ~ sum_{p = lowest..order} c_p tau^p with tau = t / T and subtracts the `derivative`-th
// time derivative of the fit from a (derivative 1 for velocity, 2 for displacement).
std::vector<double> subtract_fitted_drift(std::span<const double> a, double dt, const std::vector<double>& y, int lowest,
                                          int order, int derivative) {
    const double total = static_cast<double>(a.size() - 1) * dt;  // [s]
    std::vector<std::vector<double>> columns;
    for (int p = lowest; p <= order; ++p) {
        std::vector<double> col(a.size());
        for (std::size_t k = 0; k < a.size(); ++k) col[k] = std::pow(static_cast<double>(k) * dt / total, p);
        columns.push_back(std::move(col));
    }
    const std::vector<double> c = least_squares(columns, y);
    std::vector<double> out(a.begin(), a.end());
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double tau = static_cast<double>(k) * dt / total;
        for (int p = lowest; p <= order; ++p) {
            const double falling = derivative == 1 ? p : p * (p - 1);  // d^n/dtau^n tau^p = falling * tau^(p-n)
            out[k] -= c[static_cast<std::size_t>(p - lowest)] * falling * std::pow(tau, p - derivative) / std::pow(total, derivative);
        }
    }
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
        case BaselineMethod::linear:
            return subtract_fitted_drift(a, dt, integrate_record(a, dt).velocity_m_s, 1, 1, 1);
        case BaselineMethod::polynomial:
            check_order(correction, 1);
            return subtract_fitted_drift(a, dt, integrate_record(a, dt).velocity_m_s, 1, correction.order, 1);
        case BaselineMethod::displacement_polynomial:
            check_order(correction, 2);
            return subtract_fitted_drift(a, dt, integrate_record(a, dt).displacement_m, 2, correction.order, 2);
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
    const auto first = static_cast<std::size_t>(std::max(0.0, std::ceil(start_s / dt - tolerance)));
    std::size_t last = a.empty() ? 0 : a.size() - 1;
    if (duration_s > 0.0) last = std::min(last, static_cast<std::size_t>(std::floor((start_s + duration_s) / dt + tolerance)));
    if (first >= a.size() || last < first + 1)
        throw std::invalid_argument(fmt::format("the window {} s + {} s leaves fewer than 2 samples of a {} s record", start_s,
                                                duration_s, static_cast<double>(a.size() - 1) * dt));
    return {a.begin() + static_cast<std::ptrdiff_t>(first), a.begin() + static_cast<std::ptrdiff_t>(last) + 1};
}

void apply_cosine_taper(std::vector<double>& a, double dt, double taper_s) {
    const auto n = std::min(a.size() / 2, static_cast<std::size_t>(std::llround(taper_s / dt)));
    for (std::size_t k = 0; k < n; ++k) {
        const double w = 0.5 * (1.0 - std::cos(std::numbers::pi * static_cast<double>(k) / static_cast<double>(n)));
        a[k] *= w;
        a[a.size() - 1 - k] *= w;
    }
}

void pad_with_zeros(std::vector<double>& a, double dt, double pad_s) {
    if (pad_s > 0.0) a.resize(a.size() + static_cast<std::size_t>(std::llround(pad_s / dt)), 0.0);
}

std::vector<double> process_record(std::span<const double> a, double dt, const RecordProcessing& steps) {
    std::vector<double> out = time_window(a, dt, steps.start_s, steps.duration_s);
    apply_cosine_taper(out, dt, steps.taper_s);
    out = correct_baseline(out, dt, steps.baseline);
    const double factor = steps.target_pga_m_s2 ? scale_factor_for_pga(out, *steps.target_pga_m_s2) : steps.scale;
    for (double& x : out) x *= factor;
    pad_with_zeros(out, dt, steps.pad_s);
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
