#include "motion/intensity_measures.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "motion/records/acceleration_units.hpp"

namespace blockdem {
namespace {

struct Peak {
    double value = 0.0;  // signed value at the peak
    std::size_t index = 0;
};

// The first sample with the largest magnitude.
Peak peak_of(std::span<const double> x) {
    Peak p;
    for (std::size_t k = 0; k < x.size(); ++k)
        if (std::abs(x[k]) > std::abs(p.value)) p = {x[k], k};
    return p;
}

// Index of the first sample whose cumulative value reaches fraction * total.
std::size_t first_reaching(const std::vector<double>& cumulative, double fraction) {
    const double level = fraction * cumulative.back();
    for (std::size_t k = 0; k < cumulative.size(); ++k)
        if (cumulative[k] >= level) return k;
    return cumulative.size() - 1;
}

void fill_durations(std::span<const double> a, double dt, IntensityMeasures& m) {
    std::vector<double> cumulative(a.size(), 0.0);  // [m^2/s^3] int a^2 dt
    for (std::size_t k = 1; k < a.size(); ++k) cumulative[k] = cumulative[k - 1] + 0.5 * (a[k - 1] * a[k - 1] + a[k] * a[k]) * dt;
    m.arias_m_s = std::numbers::pi / (2.0 * standard_gravity_m_s2) * cumulative.back();
    if (cumulative.back() <= 0.0) return;
    m.t5_s = static_cast<double>(first_reaching(cumulative, 0.05)) * dt;
    m.t75_s = static_cast<double>(first_reaching(cumulative, 0.75)) * dt;
    m.t95_s = static_cast<double>(first_reaching(cumulative, 0.95)) * dt;
    m.d5_95_s = m.t95_s - m.t5_s;
    m.d5_75_s = m.t75_s - m.t5_s;
}

void fill_bracketed(std::span<const double> a, double dt, IntensityMeasures& m) {
    const double level = 0.05 * standard_gravity_m_s2;
    std::size_t first = a.size(), last = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::abs(a[k]) >= level) {
            first = std::min(first, k);
            last = k;
        }
    m.bracketed_duration_s = first < a.size() ? static_cast<double>(last - first) * dt : 0.0;
}

}  // namespace

RecordKinematics integrate_record(std::span<const double> a, double dt) {
    RecordKinematics k{std::vector<double>(a.size(), 0.0), std::vector<double>(a.size(), 0.0)};
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        k.velocity_m_s[i + 1] = k.velocity_m_s[i] + 0.5 * (a[i] + a[i + 1]) * dt;
        k.displacement_m[i + 1] = k.displacement_m[i] + k.velocity_m_s[i] * dt + (a[i] / 3.0 + a[i + 1] / 6.0) * dt * dt;
    }
    return k;
}

IntensityMeasures intensity_measures(std::span<const double> a, double dt) {
    if (a.size() < 2 || !(dt > 0.0)) throw std::invalid_argument("intensity measures need 2 samples and dt > 0");
    IntensityMeasures m;
    const Peak pga = peak_of(a);
    m.pga_m_s2 = std::abs(pga.value);
    m.pga_signed_m_s2 = pga.value;
    m.pga_time_s = static_cast<double>(pga.index) * dt;
    const RecordKinematics k = integrate_record(a, dt);
    const Peak pgv = peak_of(k.velocity_m_s);
    m.pgv_m_s = std::abs(pgv.value);
    m.pgv_time_s = static_cast<double>(pgv.index) * dt;
    const Peak pgd = peak_of(k.displacement_m);
    m.pgd_m = std::abs(pgd.value);
    m.pgd_time_s = static_cast<double>(pgd.index) * dt;
    m.final_velocity_m_s = k.velocity_m_s.back();
    m.final_displacement_m = k.displacement_m.back();
    fill_durations(a, dt, m);
    fill_bracketed(a, dt, m);
    return m;
}

}  // namespace blockdem
