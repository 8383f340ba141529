#include "world/model_domain_3d.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "world/world.hpp"  // ModelError
#include "world/world_3d.hpp"

namespace blockdem {
namespace {

void grow(Aabb3d& box, const Aabb3d& other) {
    box.lo = {std::min(box.lo.x, other.lo.x), std::min(box.lo.y, other.lo.y), std::min(box.lo.z, other.lo.z)};
    box.hi = {std::max(box.hi.x, other.hi.x), std::max(box.hi.y, other.hi.y), std::max(box.hi.z, other.hi.z)};
}

bool contains(const Aabb3d& outer, const Aabb3d& inner) {
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

// A body's box where the start puts it [m] (the centroid plus its turned vertices).
Aabb3d start_box(const RigidBody3d& b) {
    Aabb3d box{b.position_m, b.position_m};
    for (const Vec3& v : b.shape.vertices_m) {
        const Vec3 p = b.position_m + rotate(b.orientation, v);
        grow(box, {p, p});
    }
    return box;
}

// The range of the table's displacement over the run [m]. Sampled every millisecond (the
// displacement is smooth; the margin is a body size), and at most 1e5 times, so that a run set
// to go on "for ever" costs no more (as world/model_domain.cpp).
Aabb3d table_displacement_range(const World3d& w) {
    Aabb3d range{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    const double duration_s = w.duration_s;
    const double interval_s = std::max(1e-3, duration_s / 1e5);
    const auto samples = static_cast<std::int64_t>(std::ceil(duration_s / interval_s));
    for (std::int64_t k = 0; k <= samples; ++k) {
        const Vec3 d = table_displacement(w.table, std::min(duration_s, static_cast<double>(k) * interval_s));
        grow(range, {d, d});
    }
    return range;
}

// The driven bodies' boxes are taken where the table is at rest (rest_positions_m), then swept.
ModelDomain3d derived_domain(const World3d& w) {
    const Aabb3d swept = table_displacement_range(w);
    Aabb3d box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    double largest_radius_m = 0.0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        RigidBody3d b = w.bodies[i];
        if (w.kinds[i] == BodyKind3d::driven) b.position_m = w.rest_positions_m[i];
        Aabb3d body = start_box(b);
        if (w.kinds[i] == BodyKind3d::driven) body = {body.lo + swept.lo, body.hi + swept.hi};
        if (w.kinds[i] == BodyKind3d::dynamic) {
            const Vec3 half = 0.5 * (body.hi - body.lo);
            largest_radius_m = std::max(largest_radius_m, length(half));
        }
        grow(box, body);
    }
    ModelDomain3d d;
    d.margin_m = 2.0 * largest_radius_m;
    const Vec3 margin{d.margin_m, d.margin_m, d.margin_m};
    d.box_m = {box.lo - margin, {box.hi.x + d.margin_m, box.hi.y + d.margin_m, INFINITY}};
    return d;
}

}  // namespace

void init_model_domain_3d(World3d& w, const std::optional<Aabb3d>& given) {
    if (given) {
        w.domain = ModelDomain3d{};
        w.domain.from_scenario = true;
        w.domain.box_m = *given;
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const Aabb3d body = start_box(w.bodies[i]);
            if (!contains(w.domain.box_m, body))
                throw ModelError(fmt::format(
                    "simulation.domain [[{:g}, {:g}, {:g}], [{:g}, {:g}, {:g}]] m does not contain body '{}' at t = 0 (its "
                    "box is [[{:g}, {:g}, {:g}], [{:g}, {:g}, {:g}]] m)",
                    given->lo.x, given->lo.y, given->lo.z, given->hi.x, given->hi.y, given->hi.z, w.bodies[i].name,
                    body.lo.x, body.lo.y, body.lo.z, body.hi.x, body.hi.y, body.hi.z));
        }
    } else {
        w.domain = derived_domain(w);
    }
    w.domain.taken_out.assign(w.bodies.size(), 0);
    w.domain.active = true;
}

bool is_outside(const ModelDomain3d& d, const Aabb3d& box_m) { return d.active && !overlaps(box_m, d.box_m); }

void take_out(World3d& w, std::uint32_t i) {
    RigidBody3d& b = w.bodies[i];
    w.domain.left.push_back({i, w.time_s, b.position_m, b.velocity_at_t_m_s});
    w.domain.taken_out[i] = 1;
    // Frozen: no velocity, and no more kicks or drifts (world/step_3d.cpp skips it).
    b.velocity_m_s = b.velocity_at_t_m_s = {};
    b.angular_momentum_kg_m2_s = b.angular_velocity_body_rad_s = b.angular_velocity_at_t_rad_s = {};
}

void mark_taken_out(World3d& w) {
    w.domain.taken_out.assign(w.bodies.size(), 0);
    for (const BodyLeftModel3d& l : w.domain.left) w.domain.taken_out[l.body] = 1;
}

}  // namespace blockdem
