#include "world/response_monitor_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace blockdem {
namespace {

// atan(d / h) of body i at t = 0 (above): its lowest face's corners (within 1e-6 of its size),
// their hull, and the centroid's distance to the hull's nearest edge.
double overturning_angle_rad(const RigidBody3d& b) {
    double low = std::numeric_limits<double>::infinity(), size = 0.0;
    std::vector<Vec3> world;
    for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
        world.push_back(world_vertex(b, k));
        low = std::min(low, world.back().z);
        size = std::max(size, length(b.shape.vertices_m[k]));
    }
    std::vector<Vec2> base;
    for (const Vec3& v : world)
        if (v.z < low + 1e-6 * size) base.push_back({v.x, v.y});
    if (base.size() < 3) return 0.0;  // on an edge or a corner: any tilt is past it
    // The corners of a convex face, in the shape's vertex order (a box lists them row by row):
    // sorted by angle about their mean, they run counter-clockwise.
    Vec2 mean{};
    for (const Vec2& p : base) mean = {mean.x + p.x / base.size(), mean.y + p.y / base.size()};
    std::sort(base.begin(), base.end(), [&](Vec2 p, Vec2 q) {
        return std::atan2(p.y - mean.y, p.x - mean.x) < std::atan2(q.y - mean.y, q.x - mean.x);
    });
    const Vec2 c{b.position_m.x, b.position_m.y};
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < base.size(); ++k) {
        const Vec2 p = base[k], q = base[(k + 1) % base.size()];
        const Vec2 e = q - p;
        // Signed distance inside (counter-clockwise: the inside is on the left).
        d = std::min(d, (e.x * (c.y - p.y) - e.y * (c.x - p.x)) / std::hypot(e.x, e.y));
    }
    return std::atan2(std::max(d, 0.0), b.position_m.z - low);
}

}  // namespace

Quaternion turn_since_start(const World3d& w, const BodyResponse3d& r, std::size_t i) {
    return normalized(w.bodies[i].orientation * conjugate(r.start_orientation));
}

double tilt_rad(Quaternion turn) {
    return std::acos(std::clamp(rotate(turn, Vec3{0.0, 0.0, 1.0}).z, -1.0, 1.0));
}

Vec3 position_now_m(const World3d& w, std::size_t i) {
    if (w.kinds[i] == BodyKind3d::driven) return w.rest_positions_m[i] + table_displacement(w.table, w.time_s);
    return w.bodies[i].position_m;
}

Vec3 velocity_now_m_s(const World3d& w, std::size_t i) {
    if (w.kinds[i] != BodyKind3d::driven) return w.bodies[i].velocity_at_t_m_s;
    const TableMotion3d& m = w.table;
    return {sample(m.x, w.time_s).velocity_m_s, sample(m.y, w.time_s).velocity_m_s, sample(m.z, w.time_s).velocity_m_s};
}

Vec3 slip_m(const World3d& w, const BodyResponse3d& r, std::size_t i) {
    const Vec3 d = position_now_m(w, i) - r.start_position_m - table_displacement(w.table, w.time_s);
    return {d.x, d.y, 0.0};
}

ResponseMonitor3d::ResponseMonitor3d(const World3d& w) {
    for (const RigidBody3d& b : w.bodies) {
        BodyResponse3d r;
        r.start_position_m = b.position_m;
        r.start_orientation = b.orientation;
        r.overturning_angle_rad = overturning_angle_rad(b);
        bodies_.push_back(r);
    }
}

void ResponseMonitor3d::update(const World3d& w) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        BodyResponse3d& r = bodies_[i];
        const Quaternion turn = turn_since_start(w, r, i);
        const double tilt = tilt_rad(turn);
        if (tilt > r.peak_tilt_rad) {
            r.peak_tilt_rad = tilt;
            r.peak_tilt_time_s = w.time_s;
            const Vec3 axis = cross(Vec3{0.0, 0.0, 1.0}, rotate(turn, Vec3{0.0, 0.0, 1.0}));
            if (length(axis) > 0.0) r.peak_tilt_axis = normalized(axis);
        }
        r.peak_slip_m = std::max(r.peak_slip_m, length(slip_m(w, r, i)));
    }
}

bool ResponseMonitor3d::overturned(const World3d& w, std::size_t i) const {
    return w.kinds[i] == BodyKind3d::dynamic && tilt_rad(turn_since_start(w, bodies_[i], i)) > bodies_[i].overturning_angle_rad;
}

}  // namespace blockdem
