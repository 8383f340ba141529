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
// The face it rests on at t = 0: the one whose outward normal points most steeply down.
std::uint32_t resting_face(const RigidBody3d& b) {
    const Polyhedron& shape = b.shape;
    std::uint32_t support = 0;
    for (std::uint32_t f = 1; f < shape.faces.size(); ++f)
        if (rotate(b.orientation, shape.face_normals[f]).z < rotate(b.orientation, shape.face_normals[support]).z) support = f;
    return support;
}

double overturning_angle_rad(const RigidBody3d& b, std::uint32_t support) {
    const Polyhedron& shape = b.shape;
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

// [m] the least width of face f in its plane: over its edges, the extent of its corners across
// the edge (a rectangle's shorter side, a regular polygon's width across flats).
double least_width_m(const Polyhedron& shape, std::uint32_t f) {
    const std::vector<std::size_t>& corners = shape.faces[f];
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec3 e = shape.vertices_m[corners[(k + 1) % corners.size()]] - shape.vertices_m[corners[k]];
        const Vec3 across = normalized(cross(shape.face_normals[f], e));
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (std::size_t c : corners) {
            low = std::min(low, dot(shape.vertices_m[c], across));
            high = std::max(high, dot(shape.vertices_m[c], across));
        }
        least = std::min(least, high - low);
    }
    return least;
}

BodyResponse3d response_at_start(const RigidBody3d& b) {
    BodyResponse3d r;
    r.start_position_m = b.position_m;
    r.start_orientation = b.orientation;
    r.support_face = resting_face(b);
    r.overturning_angle_rad = overturning_angle_rad(b, r.support_face);
    r.base_width_m = least_width_m(b.shape, r.support_face);
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
        low = std::min(low, world_vertex(b, k).z);
        high = std::max(high, world_vertex(b, k).z);
        r.bounding_radius_m = std::max(r.bounding_radius_m, length(b.shape.vertices_m[k]));
    }
    r.height_m = high - low;
    return r;
}

// A contact normal within about 84 deg of the vertical (|n_z| > 0.1) holds the upper body up; one
// nearer level is a neighbour beside it (the 2-D rule).
constexpr double supporting_normal_z = 0.1;

bool holds(const std::vector<std::uint32_t>& list, std::uint32_t body) {
    return std::find(list.begin(), list.end(), body) != list.end();
}

// Where the material point of body s that was at start_m at t = 0 is now.
Vec3 carried_by(const World3d& w, const std::vector<BodyResponse3d>& responses, std::uint32_t s, Vec3 start_m) {
    switch (w.kinds[s]) {
        case BodyKind3d::fixed: return start_m;
        case BodyKind3d::driven: return start_m + table_displacement(w.table, w.time_s);
        case BodyKind3d::dynamic: break;
    }
    const BodyResponse3d& r = responses[s];
    return position_now_m(w, s) + rotate(turn_since_start(w, r, s), start_m - r.start_position_m);
}

// [rad] the tilt on its first supporter above which it rocked.
double rocking_threshold_rad(const BodyResponse3d& r, const OutcomeThresholds& t) {
    return t.rocking_ratio * std::max(1e-6, r.overturning_angle_rad);
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

double drop_m(const World3d& w, const BodyResponse3d& r, std::size_t i) {
    return -(position_now_m(w, i).z - r.start_position_m.z - table_displacement(w.table, w.time_s).z);
}

ResponseMonitor3d::ResponseMonitor3d(const World3d& w, const OutcomeThresholds& thresholds)
    : thresholds_(thresholds), touching_supporter_now_(w.bodies.size(), 0) {
    for (const RigidBody3d& b : w.bodies) bodies_.push_back(response_at_start(b));
}

// Bodies laid exactly touching come into contact over the first steps, as the weight reaches
// them: the supporters are gathered over a short window, not at one step (the 2-D rule).
void ResponseMonitor3d::note_contacts(const World3d& w) {
    std::fill(touching_supporter_now_.begin(), touching_supporter_now_.end(), 0);
    const bool gathering = w.time_s <= thresholds_.support_window_s;
    for (const ContactPoint3d& p : w.contacts) {
        const std::uint32_t a = p.key.body_a, b = p.key.body_b;
        bodies_[a].touched_a_body = bodies_[b].touched_a_body = true;
        note_ground(bodies_[a], bodies_[b], w.kinds[a] != BodyKind3d::dynamic, w.kinds[b] != BodyKind3d::dynamic);
        // The normal points from a to b: upwards means a is below b and holds it up.
        const bool b_on_a = p.normal.z > supporting_normal_z, a_on_b = p.normal.z < -supporting_normal_z;
        if (gathering) {
            if (b_on_a && w.kinds[b] == BodyKind3d::dynamic && !holds(bodies_[b].supporters, a)) bodies_[b].supporters.push_back(a);
            if (a_on_b && w.kinds[a] == BodyKind3d::dynamic && !holds(bodies_[a].supporters, b)) bodies_[a].supporters.push_back(b);
        }
        // Slip is judged at the points on what it rests on (any point while it rests on nothing).
        auto note = [&](std::uint32_t body, std::uint32_t other) {
            BodyResponse3d& r = bodies_[body];
            const bool on_support = holds(r.supporters, other);
            if (on_support) touching_supporter_now_[body] = 1;
            if (w.kinds[body] != BodyKind3d::dynamic || !(on_support || r.supporters.empty())) return;
            r.slid_on_support = r.slid_on_support || p.sliding;
            if (w.contact.ks_N_m > 0.0) r.peak_elastic_shear_m = std::max(r.peak_elastic_shear_m, length(p.shear.spring_n) / w.contact.ks_N_m);
        };
        note(b, a);
        note(a, b);
    }
}

// The base slip on the first supporter (the table's motion when it rests on none), the support
// it holds, the drop and whether it is at rest.
void ResponseMonitor3d::follow_support(const World3d& w, std::size_t i, BodyResponse3d& r) const {
    const RigidBody3d& b = w.bodies[i];
    const std::vector<std::size_t>& corners = b.shape.faces[r.support_face];
    std::size_t pivot = corners[0];
    double lowest_m = world_vertex(b, pivot).z;
    for (std::size_t k : corners)
        if (const double z = world_vertex(b, k).z; z < lowest_m) {
            pivot = k;
            lowest_m = z;
        }
    const Vec3 pivot_start = r.start_position_m + rotate(r.start_orientation, b.shape.vertices_m[pivot]);
    const Vec3 under = r.supporters.empty() ? pivot_start + table_displacement(w.table, w.time_s)
                                            : carried_by(w, bodies_, r.supporters.front(), pivot_start);
    const Vec3 slip = world_vertex(b, pivot) - under;
    r.peak_base_slip_m = std::max(r.peak_base_slip_m, std::hypot(slip.x, slip.y));
    const double slip_threshold_m = std::max(thresholds_.slip_ratio * r.base_width_m, elastic_slip_factor * r.peak_elastic_shear_m);
    if (r.slip_onset_s < 0.0 && r.slid_on_support && r.peak_base_slip_m > slip_threshold_m) r.slip_onset_s = w.time_s;
    const bool touching = touching_supporter_now_[i] != 0;
    if (!r.supporters.empty()) {
        if (r.touches_a_supporter && !touching) r.support_lost_time_s = w.time_s;
        if (touching) r.support_lost_time_s = -1.0;
        r.touches_a_supporter = touching;
    }
    if (r.drop_time_s < 0.0 && drop_m(w, r, i) > thresholds_.fall_drop_ratio * r.height_m) r.drop_time_s = w.time_s;
    const TableMotion3d& m = w.table;
    const Vec3 table_v{sample(m.x, w.time_s).velocity_m_s, sample(m.y, w.time_s).velocity_m_s, sample(m.z, w.time_s).velocity_m_s};
    const double speed_m_s = length(b.velocity_at_t_m_s - table_v) + r.bounding_radius_m * length(b.angular_velocity_at_t_rad_s);
    r.at_rest = speed_m_s < thresholds_.rest_speed_m_s;
}

void ResponseMonitor3d::update(const World3d& w) {
    note_contacts(w);
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
        // Rocking is judged on what it rests on, as in 2-D: a drum carried by the drum below as
        // that one rocks has not rocked itself.
        if (r.rocking_onset_s < 0.0) {
            const std::uint32_t s = r.supporters.empty() ? 0 : r.supporters.front();
            const bool on_dynamic = !r.supporters.empty() && w.kinds[s] == BodyKind3d::dynamic;
            const double tilt_on_support = on_dynamic ? tilt_rad(conjugate(turn_since_start(w, bodies_[s], s)) * turn) : tilt;
            if (tilt_on_support > rocking_threshold_rad(r, thresholds_)) r.rocking_onset_s = w.time_s;
        }
        follow_support(w, i, r);
    }
}

std::vector<BodyRecord> ResponseMonitor3d::records(const World3d& w) const {
    std::vector<BodyRecord> out(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const BodyResponse3d& r = bodies_[i];
        BodyRecord& o = out[i];
        o.dynamic = w.kinds[i] == BodyKind3d::dynamic;
        o.mass_kg = w.bodies[i].mass_kg;
        o.height_m = r.height_m;
        o.rocked = r.rocking_onset_s >= 0.0;
        o.rocking_time_s = r.rocking_onset_s;
        o.slid = r.slip_onset_s >= 0.0;
        o.sliding_time_s = r.slip_onset_s;
        o.overturned = overturned(w, i);
        o.overturning_time_s = o.overturned ? r.last_crossing_s : -1.0;
        o.supporters = r.supporters;
        o.touches_a_supporter = r.touches_a_supporter;
        o.support_lost_time_s = r.support_lost_time_s;
        o.drop_m = drop_m(w, r, i);
        o.drop_time_s = r.drop_time_s;
        const Vec3 moved = position_now_m(w, i) - r.start_position_m - table_displacement(w.table, w.time_s);
        o.final_displacement_m = length(moved);
        const Vec3 at = position_now_m(w, i);
        o.final_position_m = {at.x, at.y};
        o.at_rest = r.at_rest;
        o.touched_a_body = r.touched_a_body;
        o.rested_on_ground = r.rested_on_ground;
    }
    for (const BodyLeftModel3d& left : w.domain.left) {
        BodyRecord& o = out[left.body];
        o.left_model = true;
        o.left_model_time_s = left.time_s;
        o.left_model_position_m = {left.position_m.x, left.position_m.y};
    }
    return out;
}

bool ResponseMonitor3d::overturned(const World3d& w, std::size_t i) const {
    return w.kinds[i] == BodyKind3d::dynamic && tilt_rad(turn_since_start(w, bodies_[i], i)) > bodies_[i].overturning_angle_rad;
}

}  // namespace blockdem
