#pragma once
// Small helpers for tests: build bodies and worlds in code, and step to a condition.
#include <functional>
#include <string>

#include "geometry/polygon.hpp"
#include "laws/restitution.hpp"
#include "world/model.hpp"
#include "world/step.hpp"
#include "world/world.hpp"

namespace blockdem::testing {

inline BodyDef rectangle_body(const std::string& name, BodyKind kind, double width, double height, Vec2 center,
                              double rotation_rad = 0.0, double mass_kg = 1.0) {
    BodyDef b;
    b.name = name;
    b.kind = kind;
    b.vertices_m = rectangle_vertices(width, height, center, rotation_rad);
    b.mass_kg = mass_kg;
    return b;
}

inline ContactParameters contact(double kn, double mu, double h_n, double h_s, double ks = -1.0) {
    ContactParameters p;
    p.kn_N_m = kn;
    p.ks_N_m = ks < 0.0 ? kn : ks;
    p.mu = mu;
    p.h_n = h_n;
    p.h_s = h_s;
    return p;
}

inline Model model_with(std::vector<BodyDef> bodies, const ContactParameters& c, double dt, double gravity,
                        double duration = 1.0) {
    Model m;
    m.bodies = std::move(bodies);
    m.contact = MaterialPairs::uniform(c);
    m.settings.dt_s = dt;
    m.settings.gravity_m_s2 = gravity;
    m.settings.duration_s = duration;
    return m;
}

/// Steps until done(w) or max_time; returns true if done.
inline bool step_until(World& w, double max_time_s, const std::function<bool(const World&)>& done) {
    while (w.time_s < max_time_s) {
        step_begin(w);
        if (done(w)) return true;
        step_end(w);
    }
    return false;
}

/// Total number of closed contact points touching body id.
inline int contact_points_of(const World& w, std::uint32_t id) {
    int n = 0;
    for (const auto& pair : w.contacts)
        if (pair.a == id || pair.b == id) n += static_cast<int>(pair.count);
    return n;
}

}  // namespace blockdem::testing
