#include "world/model_domain.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "world/world.hpp"

namespace blockdem {
namespace {

Aabb empty_box() { return {{INFINITY, INFINITY}, {-INFINITY, -INFINITY}}; }

void grow(Aabb& box, const Aabb& other) {
    box.lo = {std::min(box.lo.x, other.lo.x), std::min(box.lo.y, other.lo.y)};
    box.hi = {std::max(box.hi.x, other.hi.x), std::max(box.hi.y, other.hi.y)};
}

bool contains(const Aabb& outer, const Aabb& inner) {
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y;
}

// The range of the table's displacement over the run [m]: lo and hi of (x, y). Sampled every
// millisecond (the displacement is smooth; the margin is a body size), and at most 1e5 times, so
// that a run set to go on "for ever" (duration 1e9 s) costs no more.
Aabb table_displacement_range(const World& w) {
    Aabb range{{0.0, 0.0}, {0.0, 0.0}};
    const double duration_s = w.settings.duration_s;
    const double interval_s = std::max(1e-3, duration_s / 1e5);
    const auto samples = static_cast<std::int64_t>(std::ceil(duration_s / interval_s));
    for (std::int64_t k = 0; k <= samples; ++k) {
        const double t = std::min(duration_s, static_cast<double>(k) * interval_s);
        const Vec2 d{sample(w.table_motion.horizontal, t).displacement_m, sample(w.table_motion.vertical, t).displacement_m};
        grow(range, {d, d});
    }
    return range;
}

ModelDomain derived_domain(const World& w) {
    const Bodies& b = w.bodies;
    const Aabb swept = table_displacement_range(w);
    Aabb box = empty_box();
    double largest_radius_m = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        Aabb body = body_box(b, i);
        if (b.kind[i] == BodyKind::driven) body = {body.lo + swept.lo, body.hi + swept.hi};
        if (b.kind[i] == BodyKind::dynamic) largest_radius_m = std::max(largest_radius_m, b.bounding_radius_m[i]);
        grow(box, body);
    }
    ModelDomain d;
    d.margin_m = 2.0 * largest_radius_m;
    d.box_m = {box.lo - Vec2{d.margin_m, d.margin_m}, {box.hi.x + d.margin_m, INFINITY}};
    return d;
}

}  // namespace

void init_model_domain(World& w) {
    const Bodies& b = w.bodies;
    if (w.settings.domain) {
        w.domain = ModelDomain{};
        w.domain.from_scenario = true;
        w.domain.box_m = {w.settings.domain->lo_m, w.settings.domain->hi_m};
        for (std::size_t i = 0; i < b.size(); ++i)
            if (!contains(w.domain.box_m, body_box(b, i)))
                throw ModelError(fmt::format("simulation.domain [[{:g}, {:g}], [{:g}, {:g}]] m does not contain body '{}' "
                                             "at t = 0 (its box is [[{:g}, {:g}], [{:g}, {:g}]] m)",
                                             w.domain.box_m.lo.x, w.domain.box_m.lo.y, w.domain.box_m.hi.x,
                                             w.domain.box_m.hi.y, b.name[i], body_box(b, i).lo.x, body_box(b, i).lo.y,
                                             body_box(b, i).hi.x, body_box(b, i).hi.y));
    } else {
        w.domain = derived_domain(w);
    }
    w.domain.active = true;
}

bool is_taken_out(const Bodies& b, std::size_t i) {
    return b.kind[i] == BodyKind::dynamic && b.is_static[i];
}

std::size_t take_out_bodies_outside_domain(World& w) {
    if (!w.domain.active) return 0;
    Bodies& b = w.bodies;
    const Vec2 g = w.gravity_now_m_s2;
    std::size_t now = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic || b.is_static[i] || overlaps(body_box(b, i), w.domain.box_m)) continue;
        const Vec2 v = b.velocity_m_s[i];
        const double omega = b.angular_velocity_rad_s[i];
        w.energy.removed_j += 0.5 * b.mass_kg[i] * dot(v, v) + 0.5 * b.inertia_kg_m2[i] * omega * omega +
                              -b.mass_kg[i] * dot(g, b.position_m[i]);
        w.domain.left.push_back({static_cast<std::uint32_t>(i), w.time_s, b.position_m[i], v});
        // Frozen: no velocity, and no acceleration from any force (gravity included).
        b.velocity_m_s[i] = b.velocity_at_t_m_s[i] = {};
        b.angular_velocity_rad_s[i] = b.angular_velocity_at_t_rad_s[i] = 0.0;
        b.inv_mass_1_kg[i] = 0.0;
        b.inv_inertia_1_kg_m2[i] = 0.0;
        b.is_static[i] = 1;   // with another static body, never a candidate pair
        ++now;
    }
    if (w.domain.left.empty()) return now;
    // (Candidate pairs are pairs of parts.)
    std::erase_if(w.candidate_pairs, [&](const BodyPair& p) {
        return is_taken_out(b, b.part_body[p.first]) || is_taken_out(b, b.part_body[p.second]);
    });
    return now;
}

}  // namespace blockdem
