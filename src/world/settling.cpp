#include "world/settling.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/central_difference.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// The lowest corner of any dynamic body [m], and their total mass [kg].
std::pair<double, double> lowest_point_and_mass(const World& w) {
    const Bodies& b = w.bodies;
    double low = INFINITY;
    double mass = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic) continue;
        mass += b.mass_kg[i];
        for (std::uint32_t k = 0; k < b.vertex_count[i]; ++k)
            low = std::min(low, b.world_vertices_m[b.vertex_begin[i] + k].y);
    }
    return {low, mass};
}

void restart_clock(World& w) {
    w.time_s = 0.0;
    w.step_index = 0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies.kind[i] == BodyKind::dynamic) w.bodies.initial_position_m[i] = w.bodies.position_m[i];
    place_driven_bodies(w, 0.0);
    w.energy = EnergyLedger{};
    initialise_energy(w);
}

}  // namespace

SettlingReport settle(World& w, const SettlingSettings& settings) {
    const TableMotion shaking = w.table_motion;
    w.table_motion = TableMotion{};
    update_body_geometry(w);
    const auto [low_m, mass_kg] = lowest_point_and_mass(w);
    // Clamped as a double before the cast (window = 1e300 s).
    const auto steps_per_window = static_cast<std::int64_t>(std::clamp(std::round(settings.window_s / w.dt_s), 1.0, 1e18));
    SettlingReport report;
    double window_max = 0.0;
    for (std::int64_t n = 1;; ++n) {
        step_begin(w);
        const double potential_j = w.energy.gravitational_j - mass_kg * w.settings.gravity_m_s2 * low_m;
        window_max = std::max(window_max, w.energy.kinetic_j / std::max(potential_j, 1e-300));
        step_end(w);
        if (n % steps_per_window == 0) {
            report.kinetic_ratio = window_max;
            report.settled = window_max < settings.kinetic_ratio;
            window_max = 0.0;
        }
        if (report.settled || w.time_s >= settings.max_time_s) {
            report.steps = n;
            report.time_s = w.time_s;
            break;
        }
    }
    w.table_motion = shaking;
    restart_clock(w);
    return report;
}

}  // namespace blockdem
