#include "analysis/rigid_plastic_sliding.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem {
namespace {

// The sliding direction friction cannot prevent, from the demand on it: the block's relative
// acceleration if it were free, g_s - a (0: friction holds it).
int slip_direction(double demand_m_s2, double limit_m_s2) {
    if (std::abs(demand_m_s2) <= limit_m_s2) return 0;
    return demand_m_s2 > 0.0 ? 1 : -1;
}

}  // namespace

SlidingSurface incline_surface(double mu, double slope_rad, double gravity_m_s2) {
    return {mu, -gravity_m_s2 * std::sin(slope_rad), gravity_m_s2 * std::cos(slope_rad)};
}

std::vector<SlidingPoint> rigid_plastic_sliding(const ComponentMotion& table, const SlidingSurface& surface, double end_s,
                                                double dt) {
    const double limit = surface.mu * surface.gravity_into_m_s2;  // [m/s^2] the most friction can give the block
    const double g_s = surface.gravity_along_m_s2;
    std::vector<SlidingPoint> out;
    double u = 0.0;      // relative displacement [m]
    double v = 0.0;      // relative velocity [m/s]
    int sliding = 0;     // 0 stuck, +1 sliding with v > 0, -1 with v < 0
    // Counted as a double before the cast: every step is kept in the history.
    const double step_count = std::round(end_s / dt);
    if (!(step_count <= 1e8))
        throw std::invalid_argument(fmt::format("rigid-plastic sliding: {:g} s at dt = {:g} s is {:g} steps; at most 1e8", end_s, dt,
                                                step_count));
    const auto steps = static_cast<long>(step_count);
    const double a_start = sample(table, 0.0).acceleration_m_s2;
    out.push_back({0.0, 0.0, 0.0, slip_direction(g_s - a_start, limit) != 0 ? g_s - limit * (g_s > a_start ? 1 : -1) : a_start});
    for (long n = 0; n < steps; ++n) {
        const double t0 = n * dt;
        const double t1 = t0 + dt;
        const double a0 = sample(table, t0).acceleration_m_s2;
        const double a1 = sample(table, t1).acceleration_m_s2;
        if (sliding == 0) sliding = slip_direction(g_s - a1, limit);
        double block_acc = a1;
        if (sliding != 0) {
            // Relative acceleration = g_s - a_table - sliding * limit; trapezoid over the step.
            const double rel0 = g_s - a0 - sliding * limit;
            const double rel1 = g_s - a1 - sliding * limit;
            const double v1 = v + 0.5 * (rel0 + rel1) * dt;
            if (v1 * sliding <= 0.0 && v * sliding > 0.0) {
                // Relative velocity reached zero inside the step: stop there.
                const double f = v / (v - v1);
                u += 0.5 * v * f * dt;
                v = 0.0;
                sliding = slip_direction(g_s - a1, limit);
            } else {
                u += 0.5 * (v + v1) * dt;
                v = v1;
            }
            block_acc = sliding != 0 ? g_s - sliding * limit : a1;
        }
        out.push_back({t1, u, v, block_acc});
    }
    return out;
}

std::vector<SlidingPoint> rigid_plastic_sliding(const ComponentMotion& table, double mu, double gravity_m_s2, double end_s,
                                                double dt_s) {
    return rigid_plastic_sliding(table, SlidingSurface{mu, 0.0, gravity_m_s2}, end_s, dt_s);
}

}  // namespace blockdem
