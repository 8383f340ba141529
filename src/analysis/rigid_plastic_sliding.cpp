#include "analysis/rigid_plastic_sliding.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem {

std::vector<SlidingPoint> rigid_plastic_sliding(const ComponentMotion& table, double mu, double g, double end_s,
                                                double dt) {
    const double limit = mu * g;  // [m/s^2] largest acceleration friction can give the block
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
    out.push_back({0.0, 0.0, 0.0, sample(table, 0.0).acceleration_m_s2});
    for (long n = 0; n < steps; ++n) {
        const double t0 = n * dt;
        const double t1 = t0 + dt;
        const double a0 = sample(table, t0).acceleration_m_s2;
        const double a1 = sample(table, t1).acceleration_m_s2;
        if (sliding == 0 && std::abs(a1) > limit) sliding = a1 > 0 ? -1 : 1;  // the block lags behind
        double block_acc = a1;
        if (sliding != 0) {
            // Relative acceleration = -sliding * limit - a_table; trapezoid over the step.
            const double rel0 = -sliding * limit - a0;
            const double rel1 = -sliding * limit - a1;
            const double v1 = v + 0.5 * (rel0 + rel1) * dt;
            if (v1 * sliding <= 0.0 && v * sliding > 0.0) {
                // Relative velocity reached zero inside the step: stop there.
                const double f = v / (v - v1);
                u += 0.5 * v * f * dt;
                v = 0.0;
                sliding = std::abs(a1) > limit ? (a1 > 0 ? -1 : 1) : 0;
            } else {
                u += 0.5 * (v + v1) * dt;
                v = v1;
            }
            block_acc = sliding != 0 ? -sliding * limit : a1;
        }
        out.push_back({t1, u, v, block_acc});
    }
    return out;
}

}  // namespace blockdem
