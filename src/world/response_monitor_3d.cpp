#include "world/response_monitor_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace blockdem {
namespace {

// The tilt at which body i would topple at t = 0 (above). It rests on the face whose outward
// normal points most steeply down (the table, a bed joint, or a joint plane of a rock mass, which
// may dip). Tipping over an edge of that face turns the centroid about the edge until the
// centroid stands straight above it; in the plane across the edge that turn is the angle
// between the centroid's arm (from the edge) and the vertical. On a level base it is atan(d / h),
// d the centroid's distance inside the edge and h its height; on a face dipping at beta it is
// atan(d / h) - beta over the lower edge. The least over the face's edges is the body's limit;
// a centroid already beyond an edge gives 0.
double overturning_angle_rad(const RigidBody3d& b) {
    const Polyhedron& shape = b.shape;
    std::size_t support = 0;
    for (std::size_t f = 1; f < shape.faces.size(); ++f)
        if (rotate(b.orientation, shape.face_normals[f]).z < rotate(b.orientation, shape.face_normals[support]).z) support = f;
    const std::vector<std::size_t>& corners = shape.faces[support];
    const Vec3 into_body = -rotate(b.orientation, shape.face_normals[support]);
    Vec3 face_centre{};
    for (std::size_t k : corners) face_centre = face_centre + (1.0 / corners.size()) * world_vertex(b, k);
    const Vec3 up{0.0, 0.0, 1.0};
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec3 p = world_vertex(b, corners[k]);
        const Vec3 e = normalized(world_vertex(b, corners[(k + 1) % corners.size()]) - p);
        // In the plane across the edge: `inward` runs in the face, away from the edge, and
        // `into_body` out of the face; angles are measured from `into_body` towards `inward`.
        Vec3 inward = (face_centre - p) - dot(face_centre - p, e) * e;
        inward = normalized(inward - dot(inward, into_body) * into_body);
        const Vec3 arm = b.position_m - p;
        const Vec3 up_across = up - dot(up, e) * e;
        if (length(up_across) < 1e-9) continue;  // a vertical edge: no tipping about it
        const double arm_angle = std::atan2(dot(arm, inward), dot(arm, into_body));
        const double up_angle = std::atan2(dot(up_across, inward), dot(up_across, into_body));
        least = std::min(least, arm_angle - up_angle);
    }
    return std::isfinite(least) ? std::max(least, 0.0) : 0.0;
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
        // As in 2-D, a body overturned at the last time it went past its limit and stayed.
        const bool beyond = tilt > r.overturning_angle_rad;
        if (beyond && !r.beyond_limit) r.last_crossing_s = w.time_s;
        r.beyond_limit = beyond;
    }
}

bool ResponseMonitor3d::overturned(const World3d& w, std::size_t i) const {
    return w.kinds[i] == BodyKind3d::dynamic && tilt_rad(turn_since_start(w, bodies_[i], i)) > bodies_[i].overturning_angle_rad;
}

}  // namespace blockdem
