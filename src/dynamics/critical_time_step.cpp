#include "dynamics/critical_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace blockdem {

namespace {

// 1/m + r^2/I: the inverse of the smallest effective mass at any corner of body i.
double corner_inverse_mass(const Bodies& bodies, std::size_t i) {
    const double r = bodies.bounding_radius_m[i];
    return bodies.inv_mass_1_kg[i] + r * r * bodies.inv_inertia_1_kg_m2[i];
}

}  // namespace

CriticalTimeStep critical_time_step(const Bodies& bodies, const MaterialPairs& contact) {
    // The two largest corner inverse masses among dynamic bodies: a body's partner in a contact
    // can be any other dynamic body, whose own compliance adds to the contact's frequency.
    double largest = 0.0, second = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies.kind[i] != BodyKind::dynamic) continue;
        const double inv = corner_inverse_mass(bodies, i);
        if (inv > largest) {
            second = largest;
            largest = inv;
        } else {
            second = std::max(second, inv);
        }
    }
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
        const double own = corner_inverse_mass(bodies, i);
        const double partner = own == largest ? second : largest;
        const double inverse_mass = own + partner;
        const double omega = std::sqrt(k_max * inverse_mass);
        if (omega <= 0.0) continue;
        // The dashpot uses at most the body's own mass m, but acts on the pair's effective mass
        // 1 / inverse_mass, so the mode's damping ratio can reach h sqrt(m inverse_mass).
        const double h = h_max * std::sqrt(bodies.mass_kg[i] * inverse_mass);
        const double dt = 2.0 / omega * (std::sqrt(1.0 + h * h) - h);
        if (dt < best.dt_s) best = {dt, bodies.name[i], omega, h};
    }
    return best;
}

}  // namespace blockdem
