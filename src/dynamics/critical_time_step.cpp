#include "dynamics/critical_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace blockdem {

CriticalTimeStep critical_time_step(const Bodies& bodies, const MaterialPairs& contact) {
    CriticalTimeStep best;
    best.dt_s = std::numeric_limits<double>::infinity();
    const std::uint32_t materials = static_cast<std::uint32_t>(contact.materials.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies.kind[i] != BodyKind::dynamic) continue;
        double k_max = 0.0;
        double h_max = 0.0;
        for (std::uint32_t other = 0; other < materials; ++other) {
            const ContactParameters& p = contact.at(bodies.material[i], other);
            k_max = std::max({k_max, p.kn_N_m, p.ks_N_m});
            h_max = std::max({h_max, p.h_n, p.h_s});
        }
        const double r = bodies.bounding_radius_m[i];
        const double inverse_mass = bodies.inv_mass_1_kg[i] + r * r * bodies.inv_inertia_1_kg_m2[i];
        const double omega = std::sqrt(k_max * inverse_mass);
        if (omega <= 0.0) continue;
        // The dashpot uses at most the body's own mass m, but acts on the corner's effective mass
        // 1 / inverse_mass, so the corner mode's damping ratio can reach h sqrt(m inverse_mass).
        const double h = h_max * std::sqrt(bodies.mass_kg[i] * inverse_mass);
        const double dt = 2.0 / omega * (std::sqrt(1.0 + h * h) - h);
        if (dt < best.dt_s) best = {dt, bodies.name[i], omega, h};
    }
    return best;
}

}  // namespace blockdem
