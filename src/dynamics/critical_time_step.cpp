#include "dynamics/critical_time_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "dynamics/block_pencil.hpp"
#include "dynamics/highest_mode.hpp"
#include "geometry/polygon_contact.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/mohr_coulomb_joint.hpp"

namespace blockdem {

namespace {

// Stands for a fixed body that a free body may land on (infinitely heavy: no entries in g).
constexpr std::uint32_t fixed_ground = 0xffffffffu;

bool moves(const Bodies& b, std::uint32_t i) { return i != fixed_ground && b.kind[i] == BodyKind::dynamic; }

// Body i's part of g for a unit force along d at lever r (sign -1 on a, +1 on b).
std::array<double, 3> body_part(const Bodies& b, std::uint32_t i, Vec2 r, Vec2 d, double sign) {
    if (!moves(b, i)) return {0.0, 0.0, 0.0};
    const double over_sqrt_m = std::sqrt(b.inv_mass_1_kg[i]);
    const double over_sqrt_i = std::sqrt(b.inv_inertia_1_kg_m2[i]);
    return {sign * d.x * over_sqrt_m, sign * d.y * over_sqrt_m, sign * cross(r, d) * over_sqrt_i};
}

void add_direction(StabilityRows& rows, const Bodies& b, const StiffnessPoint& p, Vec2 d, double k, double c) {
    const Vec2 ra = moves(b, p.a) ? p.point_m - b.position_m[p.a] : Vec2{};
    const Vec2 rb = moves(b, p.b) ? p.point_m - b.position_m[p.b] : Vec2{};
    const std::array<double, 3> ga = body_part(b, p.a, ra, d, -1.0);
    const std::array<double, 3> gb = body_part(b, p.b, rb, d, 1.0);
    double l1 = 0.0;
    for (int j = 0; j < 3; ++j) l1 += std::abs(ga[j]) + std::abs(gb[j]);
    auto add = [&](std::uint32_t body, const std::array<double, 3>& g) {
        if (!moves(b, body)) return;
        for (int j = 0; j < 3; ++j) {
            rows.stiffness_1_s2[3 * body + j] += k * std::abs(g[j]) * l1;
            rows.damping_1_s[3 * body + j] += c * std::abs(g[j]) * l1;
        }
    };
    add(p.a, ga);
    add(p.b, gb);
}

// The point's stiffness and damping as the law applies them (contact_forces.cpp): the pair's
// reduced mass shared among its body pair's points (mass_sharing_points: over all the body
// pair's part pairs); a per-length joint's point with its tributary length (the pair's two
// points, first and second, or its one).
StiffnessPoint stiffness_point(const World& w, std::uint32_t a, std::uint32_t b, Vec2 point, Vec2 normal,
                               std::uint32_t points_in_pair, std::uint32_t mass_sharing_points, double stiffness_scale,
                               Vec2 first_m, Vec2 second_m) {
    const Bodies& bodies = w.bodies;
    ContactParameters params = w.contact.at(bodies.material[a], bodies.material[b]);
    if (params.stiffness == StiffnessBasis::per_length) {
        const double least_width_m = std::min(bodies.least_width_m[a], bodies.least_width_m[b]);
        const JointPoint joint =
            joint_point(params, tributary_length_m(points_in_pair, first_m, second_m, least_width_m, w.contact.rounding_m),
                        std::min(bodies.thickness_m[a], bodies.thickness_m[b]));
        params.kn_N_m = joint.kn_N_m;
        params.ks_N_m = joint.ks_N_m;
    }
    params.kn_N_m *= stiffness_scale;
    params.ks_N_m *= stiffness_scale;
    const double reduced_mass = 1.0 / (bodies.inv_mass_1_kg[a] + bodies.inv_mass_1_kg[b]);
    const DashpotCoefficients c = dashpot_coefficients(params, reduced_mass / mass_sharing_points);
    return {a, b, point, normal, params.kn_N_m, params.ks_N_m, c.cn_N_s_m, c.cs_N_s_m};
}

// A dynamic body that touches nothing at the start lands, at worst, flat on two of its corners
// on a fixed body of the stiffest material it can meet.
void add_landing(const World& w, std::uint32_t i, std::vector<StiffnessPoint>& out) {
    const Bodies& b = w.bodies;
    ContactParameters stiffest{};
    for (std::uint32_t other = 0; other < w.contact.materials.size(); ++other) {
        ContactParameters p = w.contact.at(b.material[i], other);
        if (p.stiffness == StiffnessBasis::per_length) {
            // Flat on two corners, each carrying at most the body's radius of face (more than
            // half of any face: an upper bound, so a safe step).
            const JointPoint joint = joint_point(p, b.bounding_radius_m[i], b.thickness_m[i]);
            p.kn_N_m = joint.kn_N_m;
            p.ks_N_m = joint.ks_N_m;
        }
        stiffest.kn_N_m = std::max(stiffest.kn_N_m, p.kn_N_m);
        stiffest.ks_N_m = std::max(stiffest.ks_N_m, p.ks_N_m);
        stiffest.h_n = std::max(stiffest.h_n, p.h_n);
        stiffest.h_s = std::max(stiffest.h_s, p.h_s);
    }
    const DashpotCoefficients c = dashpot_coefficients(stiffest, 0.5 * b.mass_kg[i]);
    // Its two lowest corners (the landing face of a falling block).
    std::vector<Vec2> corners(b.world_vertices_m.begin() + b.vertex_begin[i],
                              b.world_vertices_m.begin() + b.vertex_begin[i] + b.vertex_count[i]);
    std::partial_sort(corners.begin(), corners.begin() + 2, corners.end(), [](Vec2 p, Vec2 q) { return p.y < q.y; });
    for (int k = 0; k < 2; ++k)
        out.push_back({fixed_ground, i, corners[k], {0.0, 1.0}, stiffest.kn_N_m, stiffest.ks_N_m, c.cn_N_s_m, c.cs_N_s_m});
}

}  // namespace

CriticalTimeStep stable_time_step(const Bodies& bodies, const std::vector<StiffnessPoint>& points) {
    StabilityRows rows;
    rows.reset(bodies.size());
    for (const StiffnessPoint& p : points) rows.add(bodies, p);
    return rows.limit(bodies);
}

void StabilityRows::reset(std::size_t bodies) {
    stiffness_1_s2.assign(3 * bodies, 0.0);
    damping_1_s.assign(3 * bodies, 0.0);
}

void StabilityRows::add(const Bodies& bodies, const StiffnessPoint& p) {
    add_direction(*this, bodies, p, p.normal, p.kn_N_m, p.cn_N_s_m);
    add_direction(*this, bodies, p, perp(p.normal), p.ks_N_m, p.cs_N_s_m);
}

CriticalTimeStep StabilityRows::limit(const Bodies& bodies) const {
    CriticalTimeStep best;
    best.dt_s = std::numeric_limits<double>::infinity();
    for (std::size_t row = 0; row < stiffness_1_s2.size(); ++row) {
        const double k = stiffness_1_s2[row];
        const double c = damping_1_s[row];
        if (!(k > 0.0)) continue;
        // The root of (dt^2/4) k + (dt/2) c = 1.
        const double dt = (std::sqrt(c * c + 4.0 * k) - c) / k;
        if (dt < best.dt_s) best = {dt, bodies.name[row / 3], std::sqrt(k), c / (2.0 * std::sqrt(k))};
    }
    return best;
}

namespace {

// Calls f(point) for each point of the live contact table, its springs and dashpots as the law
// applies them.
template <class F>
void for_each_live_point(const World& w, F&& f) {
    // (Worlds with concave bodies count each body pair's points in the step: world/step.cpp.)
    const bool concave = w.body_pair_points.size() == w.contacts.size() && w.bodies.part_total() != w.bodies.size();
    for (std::size_t p = 0; p < w.contacts.size(); ++p) {
        const PairContact& pair = w.contacts[p];
        const std::uint32_t sharing = concave ? w.body_pair_points[p] : pair.count;
        for (std::uint32_t k = 0; k < pair.count; ++k)
            f(stiffness_point(w, pair.a, pair.b, pair.points[k].point_m, pair.normal, pair.count, sharing,
                              pair.stiffness_scale, pair.points[0].point_m, pair.points[1].point_m));
    }
}

}  // namespace

CriticalTimeStep live_time_step(const World& w, StabilityRows& rows) {
    rows.reset(w.bodies.size());
    for_each_live_point(w, [&](const StiffnessPoint& s) { rows.add(w.bodies, s); });
    return rows.limit(w.bodies);
}

CriticalTimeStep live_highest_mode_time_step(const World& w, const CriticalTimeStep& bound) {
    std::vector<StiffnessPoint> points;
    for_each_live_point(w, [&](const StiffnessPoint& s) { points.push_back(s); });
    return highest_mode_time_step(w.bodies, points, bound);
}

CriticalTimeStep body_block_limit(const World& w, double dt_s) {
    const Bodies& bodies = w.bodies;
    std::vector<BodyBlocks<3>> blocks(bodies.size());
    for_each_live_point(w, [&](const StiffnessPoint& s) {
        const Vec2 directions[2] = {s.normal, perp(s.normal)};
        const double stiffness[2] = {s.kn_N_m, s.ks_N_m}, damping[2] = {s.cn_N_s_m, s.cs_N_s_m};
        for (std::uint32_t body : {s.a, s.b}) {
            if (!moves(bodies, body)) continue;
            for (int d = 0; d < 2; ++d) {
                // (The sign of g on this end does not matter in g g^T.)
                const std::array<double, 3> g = body_part(bodies, body, s.point_m - bodies.position_m[body], directions[d], 1.0);
                blocks[body].add(g.data(), stiffness[d], damping[d]);
            }
        }
    });
    const auto [body, mode] = most_unstable_body(blocks, dt_s);
    if (!mode.found) return {std::numeric_limits<double>::infinity(), std::string(), 0.0, 0.0};
    return {mode.dt_s, bodies.name[body], mode.omega_rad_s, mode.h};
}

std::vector<StiffnessPoint> start_stiffness_points(const World& w) {
    const Bodies& b = w.bodies;
    std::vector<StiffnessPoint> points;
    std::vector<std::uint8_t> touches(b.size(), 0);
    // Bodies laid exactly touching (a block on the table, bricks side by side) are "apart" to
    // the narrow phase until they press; here a grows by a millionth about its centroid, so
    // every pair that touches within that shows the contact it will have.
    constexpr double growth = 1e-6;
    std::vector<Vec2> grown;
    struct TouchingPair {
        std::uint32_t a, b;
        ContactManifold manifold;
    };
    std::vector<TouchingPair> touching;
    for (const PairContact& pair : w.contacts) {
        // (The pair's polygons are parts of the two bodies, world/world.hpp.)
        const std::uint32_t first = b.part_vertex_begin[pair.part_a];
        const std::uint32_t count = b.part_vertex_count[pair.part_a];
        grown.resize(count);
        for (std::uint32_t k = 0; k < count; ++k)
            grown[k] = b.position_m[pair.a] + (1.0 + growth) * (b.world_vertices_m[first + k] - b.position_m[pair.a]);
        const PolygonView a{grown.data(), &b.world_normals[first], count};
        const PolygonView other{&b.world_vertices_m[b.part_vertex_begin[pair.part_b]],
                                &b.world_normals[b.part_vertex_begin[pair.part_b]], b.part_vertex_count[pair.part_b]};
        ContactManifold manifold;
        if (!collide_polygons(a, other, no_reference, manifold)) continue;
        touches[pair.a] = touches[pair.b] = 1;
        touching.push_back({pair.a, pair.b, manifold});
    }
    // The dashpots share the body pair's reduced mass among all its part pairs' points, as the
    // law does (contact/contact_forces.hpp). The table is sorted by part a, so a body a's pairs
    // are one run: the body pair's points are summed within it.
    std::size_t run = 0;
    for (std::size_t i = 0; i < touching.size(); ++i) {
        const TouchingPair& t = touching[i];
        if (touching[run].a != t.a) run = i;
        std::uint32_t sharing = 0;
        for (std::size_t j = run; j < touching.size() && touching[j].a == t.a; ++j)
            if (touching[j].b == t.b) sharing += touching[j].manifold.count;
        for (std::uint32_t k = 0; k < t.manifold.count; ++k)
            points.push_back(stiffness_point(w, t.a, t.b, t.manifold.points[k].point_m, t.manifold.normal,
                                             t.manifold.count, sharing, 1.0, t.manifold.points[0].point_m,
                                             t.manifold.points[t.manifold.count - 1].point_m));  // (set points only)
    }
    for (std::uint32_t i = 0; i < b.size(); ++i)
        if (b.kind[i] == BodyKind::dynamic && !touches[i]) add_landing(w, i, points);
    return points;
}

namespace {

// The points as dynamics/block_pencil.hpp reads them: each point's normal and tangent, g's parts
// on its bodies (body_part: zero on a body that does not move), with its springs and dashpots.
struct PencilSource2d {
    const Bodies& b;
    const std::vector<StiffnessPoint>& points_;

    std::size_t points() const { return points_.size(); }

    PointEnds ends(std::size_t i) const {
        const StiffnessPoint& p = points_[i];
        return {p.a, p.b, moves(b, p.a), moves(b, p.b)};
    }

    template <class F>
    void directions(std::size_t i, F&& f) const {
        const StiffnessPoint& p = points_[i];
        const Vec2 ra = moves(b, p.a) ? p.point_m - b.position_m[p.a] : Vec2{};
        const Vec2 rb = moves(b, p.b) ? p.point_m - b.position_m[p.b] : Vec2{};
        const Vec2 normal = p.normal, tangent = perp(p.normal);
        const std::array<double, 3> ga_n = body_part(b, p.a, ra, normal, -1.0), gb_n = body_part(b, p.b, rb, normal, 1.0);
        f(ga_n.data(), gb_n.data(), p.kn_N_m, p.cn_N_s_m);
        const std::array<double, 3> ga_t = body_part(b, p.a, ra, tangent, -1.0), gb_t = body_part(b, p.b, rb, tangent, 1.0);
        f(ga_t.data(), gb_t.data(), p.ks_N_m, p.cs_N_s_m);
    }
};

}  // namespace

CriticalTimeStep highest_mode_time_step(const Bodies& b, const std::vector<StiffnessPoint>& points,
                                        const CriticalTimeStep& bound) {
    if (!std::isfinite(bound.dt_s)) return bound;
    const HighestMode mode = pencil_highest_mode<3>(PencilSource2d{b, points}, b.size(), bound.dt_s);
    if (!mode.found) return bound;
    return {std::max(mode.dt_s, bound.dt_s), b.name[body_moving_most(mode.mode, 3)], mode.omega_rad_s, mode.h};
}

StartTimeStep critical_time_step(const World& w) {
    const std::vector<StiffnessPoint> points = start_stiffness_points(w);
    StartTimeStep s;
    s.proven = stable_time_step(w.bodies, points);
    s.highest_mode = highest_mode_time_step(w.bodies, points, s.proven);
    return s;
}

}  // namespace blockdem
