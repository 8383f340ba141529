#include "world/response_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/outline.hpp"
#include "geometry/polygon.hpp"
#include "world/parallel.hpp"

namespace blockdem {
namespace {

// The base is the edge whose outward normal points most nearly down at the start; the body tips
// about one of its two ends. Working in the edge's own frame makes the critical angles right
// for a body that starts tilted (on a slope, or settled a little off level): alpha is measured
// from the base lying flat, and the start's tilt is kept apart in base_tilt_rad. "Down" and
// "level" are gravity's, which a tilted table turns (down = (-sin tilt, -cos tilt), level angle =
// tilt: a base along x is tilted from level by the table's tilt).
// A concave body stands on its convex hull (a Pi-shaped block on both legs, not on one), so its
// base is the hull's edge; a convex body's outline is its hull.
BodyResponse base_of(const Bodies& b, std::size_t i, const OutcomeThresholds& t, double level_angle_rad) {
    const Vec2 down{-std::sin(level_angle_rad), -std::cos(level_angle_rad)};
    const std::uint32_t first = b.vertex_begin[i];
    std::uint32_t count = b.vertex_count[i];
    const Vec2* corners = &b.world_vertices_m[first];
    const Vec2* normals = &b.world_normals[first];
    std::vector<Vec2> hull, hull_normals;
    if (b.part_count[i] > 1) {
        hull = convex_hull(corners, count);
        count = static_cast<std::uint32_t>(hull.size());
        for (std::uint32_t k = 0; k < count; ++k) hull_normals.push_back(edge_normal(hull[k], hull[(k + 1) % count]));
        corners = hull.data();
        normals = hull_normals.data();
    }
    std::uint32_t base = 0;
    for (std::uint32_t k = 1; k < count; ++k)
        if (dot(normals[k], down) > dot(normals[base], down)) base = k;
    const Vec2 left = corners[base];
    const Vec2 right = corners[(base + 1) % count];
    const Vec2 along = normalized(right - left);   // +x when the base is level
    const Vec2 up = perp(along);                    // into the body
    const Vec2 c = b.position_m[i];
    const double height = dot(c - left, up);        // [m] centroid above the base
    BodyResponse r;
    r.alpha_ccw_rad = std::atan2(dot(c - left, along), height);
    r.alpha_cw_rad = std::atan2(dot(right - c, along), height);
    r.base_tilt_rad = std::atan2(along.y, along.x) + level_angle_rad;
    r.base_left_offset_m = left - c;
    r.base_right_offset_m = right - c;
    r.base_length_m = length(right - left);
    r.rocking_threshold_rad = t.rocking_ratio * std::max(1e-6, std::min(std::abs(r.alpha_ccw_rad), std::abs(r.alpha_cw_rad)));
    r.slip_threshold_m = t.slip_ratio * r.base_length_m;
    double low = INFINITY, high = -INFINITY;
    for (std::uint32_t k = 0; k < count; ++k) {
        low = std::min(low, -dot(corners[k], down));
        high = std::max(high, -dot(corners[k], down));
    }
    r.height_m = high - low;
    return r;
}

bool holds(const std::vector<std::uint32_t>& list, std::uint32_t body) {
    return std::find(list.begin(), list.end(), body) != list.end();
}

// A contact normal within about 84 deg of gravity's vertical (|n . up| > 0.1) holds the upper
// body up; one nearer level is a neighbour beside it.
constexpr double supporting_normal_y = 0.1;

}  // namespace

double level_rad(const World& w, double t_s) {
    return w.settings.gravity_m_s2 > 0.0 ? tilt_at_rad(w.settings, t_s) : 0.0;
}

ResponseMonitor::ResponseMonitor(const World& w)
    : thresholds_(w.settings.outcomes),
      responses_(w.bodies.size()),
      sliding_now_(w.bodies.size(), 0),
      touching_supporter_now_(w.bodies.size(), 0) {
    const Bodies& b = w.bodies;
    for (std::size_t i = 0; i < b.size(); ++i)
        if (b.kind[i] == BodyKind::driven) {
            reference_ = static_cast<std::int64_t>(i);
            break;
        }
    start_level_rad_ = level_rad(w, w.time_s);
    for (std::size_t i = 0; i < b.size(); ++i) {
        responses_[i] = base_of(b, i, thresholds_, start_level_rad_);
        responses_[i].start_rotation_rad = b.rotation_rad[i];
        responses_[i].support_body = reference_;
    }
}

// Sliding and the elastic shear displacement, at the pairs with the bodies below (any pair
// while a body has no supporter yet). a_on_b: b is one of a's supporters (b_on_a the reverse).
// The pair's points are read once for both bodies: their largest shear spring force and whether
// one slides are the pair's, whichever body is noted (this runs for every contact at every step).
void ResponseMonitor::note_support_shear(const World& w, const PairContact& pair, bool a_on_b, bool b_on_a) {
    const Bodies& b = w.bodies;
    auto noted = [&](std::uint32_t body, bool on_other) {
        return b.kind[body] == BodyKind::dynamic && (on_other || responses_[body].supporters.empty());
    };
    const bool note_a = noted(pair.a, a_on_b);
    const bool note_b = noted(pair.b, b_on_a);
    if (!note_a && !note_b) return;
    double spring_n = 0.0;
    bool sliding = false;
    for (std::uint32_t k = 0; k < pair.count; ++k) {
        spring_n = std::max(spring_n, std::abs(pair.points[k].shear_spring_n));
        sliding = sliding || pair.points[k].sliding;
    }
    if (sliding) {
        if (note_a) sliding_now_[pair.a] = 1;
        if (note_b) sliding_now_[pair.b] = 1;
    }
    const double ks_N_m = w.contact.at(b.material[pair.a], b.material[pair.b]).ks_N_m;
    if (ks_N_m <= 0.0) return;
    const double shear_m = spring_n / ks_N_m;
    if (note_a) responses_[pair.a].peak_elastic_shear_m = std::max(responses_[pair.a].peak_elastic_shear_m, shear_m);
    if (note_b) responses_[pair.b].peak_elastic_shear_m = std::max(responses_[pair.b].peak_elastic_shear_m, shear_m);
}

void ResponseMonitor::restore(std::vector<BodyResponse> responses, double start_level_rad) {
    start_level_rad_ = start_level_rad;
    if (responses.size() != responses_.size())
        throw std::invalid_argument("ResponseMonitor::restore: one response per body is needed");
    responses_ = std::move(responses);
}

void ResponseMonitor::note_contacts(const World& w) {
    const Bodies& b = w.bodies;
    std::fill(sliding_now_.begin(), sliding_now_.end(), 0);
    std::fill(touching_supporter_now_.begin(), touching_supporter_now_.end(), 0);
    // Bodies laid exactly touching come into contact over the first steps, as the weight
    // reaches them: the supporters are gathered over a short window, not at one step.
    const bool gathering = w.time_s <= thresholds_.support_window_s;
    const double level = level_rad(w, w.time_s);
    const Vec2 up{std::sin(level), std::cos(level)};
    for (const PairContact& pair : w.contacts) {
        if (pair.count == 0) continue;
        responses_[pair.a].touched_a_body = responses_[pair.b].touched_a_body = true;
        note_ground(responses_[pair.a], responses_[pair.b], b.kind[pair.a] != BodyKind::dynamic, b.kind[pair.b] != BodyKind::dynamic);
        if (gathering) {
            // The normal points from a to b: upwards means a is below b and holds it up. The
            // first supporter found is the body whose interface judges sliding and rocking.
            auto add = [&](std::uint32_t upper, std::uint32_t lower) {
                BodyResponse& r = responses_[upper];
                if (b.kind[upper] != BodyKind::dynamic || holds(r.supporters, lower)) return;
                if (r.supporters.empty()) r.support_body = lower;
                r.supporters.push_back(lower);
            };
            if (dot(pair.normal, up) > supporting_normal_y) add(pair.b, pair.a);
            if (dot(pair.normal, up) < -supporting_normal_y) add(pair.a, pair.b);
        }
        const bool a_on_b = holds(responses_[pair.a].supporters, pair.b);
        const bool b_on_a = holds(responses_[pair.b].supporters, pair.a);
        note_support_shear(w, pair, a_on_b, b_on_a);
        if (a_on_b) touching_supporter_now_[pair.a] = 1;
        if (b_on_a) touching_supporter_now_[pair.b] = 1;
    }
}

void ResponseMonitor::observe_support(const Bodies& b, std::size_t i, double t_s, BodyResponse& r, Vec2 table_velocity_m_s,
                                      Vec2 down) {
    const bool touching = touching_supporter_now_[i] != 0;
    if (!r.supporters.empty()) {
        if (r.touches_a_supporter && !touching) r.support_lost_time_s = t_s;
        if (touching) r.support_lost_time_s = -1.0;
        r.touches_a_supporter = touching;
    }
    if (r.drop_time_s < 0.0 && dot(r.relative_displacement_m, down) > thresholds_.fall_drop_ratio * r.height_m) r.drop_time_s = t_s;
    const double speed_m_s = length(b.velocity_at_t_m_s[i] - table_velocity_m_s) +
                             b.bounding_radius_m[i] * std::abs(b.angular_velocity_at_t_rad_s[i]);
    r.at_rest = speed_m_s < thresholds_.rest_speed_m_s;
}

namespace {

// Where the material point of body s that was at start_m when the monitor started is now
// (s = -1: the ground, which does not move).
Vec2 carried_by(const Bodies& b, std::int64_t s, double start_rotation_rad, Vec2 start_m) {
    if (s < 0) return start_m;
    const auto i = static_cast<std::size_t>(s);
    // A table or a fixed body only translates: no rotation to evaluate (the common case).
    if (b.kind[i] != BodyKind::dynamic) return start_m + (b.position_m[i] - b.initial_position_m[i]);
    // Its rotation now from its first edge's normal (rest orientation to now), which spares a
    // cosine and a sine per body and step; the start's rotation is 0 unless settling turned it.
    const std::uint32_t k = b.vertex_begin[i];
    const Vec2 rest = b.local_normals[k];
    const Vec2 now = b.world_normals[k];
    const Rotation turned{dot(rest, now), cross(rest, now)};
    const Vec2 arm = start_m - b.initial_position_m[i];
    if (start_rotation_rad == 0.0) return b.position_m[i] + turned.apply(arm);
    return b.position_m[i] + turned.apply(Rotation::from_angle(-start_rotation_rad).apply(arm));
}

}  // namespace

void ResponseMonitor::observe(const World& w) {
    const Bodies& b = w.bodies;
    note_contacts(w);
    const Vec2 table_moved = reference_ >= 0 ? b.position_m[static_cast<std::size_t>(reference_)] -
                                                   b.initial_position_m[static_cast<std::size_t>(reference_)]
                                             : Vec2{};
    const Vec2 table_velocity = reference_ >= 0 ? b.velocity_at_t_m_s[static_cast<std::size_t>(reference_)] : Vec2{};
    // The tilt from level follows a tilting table: its change since the start adds to every body's.
    const double level = level_rad(w, w.time_s);
    const double level_change_rad = level - start_level_rad_;
    const Vec2 down{-std::sin(level), -std::cos(level)};
    // Each body writes only its own response (a supporter's start_rotation_rad is read, never
    // written here): parallel_for's rule 1, so the results do not depend on the thread count.
    parallel_for(static_cast<std::ptrdiff_t>(b.size()), [&](std::ptrdiff_t item) {
        const auto i = static_cast<std::size_t>(item);
        // A taken-out body is a dynamic one made static (is_taken_out), tested inline: this loop
        // runs for every body at every step.
        if (b.kind[i] != BodyKind::dynamic || b.is_static[i]) return;
        BodyResponse& r = responses_[i];
        const double theta = b.rotation_rad[i];
        if (std::abs(theta) > r.peak_abs_rotation_rad) {
            r.peak_abs_rotation_rad = std::abs(theta);
            r.time_of_peak_rotation_s = w.time_s;
        }
        const double tilt = r.base_tilt_rad + theta + level_change_rad;  // the base's angle from level
        const bool beyond = tilt > r.alpha_ccw_rad || tilt < -r.alpha_cw_rad;
        if (beyond && !r.beyond_alpha) r.last_crossing_s = w.time_s;
        r.beyond_alpha = beyond;
        r.relative_displacement_m = (b.position_m[i] - b.initial_position_m[i]) - table_moved;
        // On the body below: its rotation taken out, the corner it tips about followed (it
        // stays put on the body below unless the base slides).
        const double support_start_rad = r.support_body >= 0 ? responses_[static_cast<std::size_t>(r.support_body)].start_rotation_rad : 0.0;
        const double support_turn_rad = r.support_body >= 0 ? b.rotation_rad[static_cast<std::size_t>(r.support_body)] - support_start_rad : 0.0;
        const double rotation_on_support = theta - r.start_rotation_rad - support_turn_rad;
        r.peak_abs_rotation_on_support_rad = std::max(r.peak_abs_rotation_on_support_rad, std::abs(rotation_on_support));
        const Vec2 pivot = r.base_tilt_rad + rotation_on_support >= 0.0 ? r.base_left_offset_m : r.base_right_offset_m;
        const Vec2 pivot_now = b.position_m[i] + Rotation::from_angle(theta - r.start_rotation_rad).apply(pivot);
        r.base_slip_m = pivot_now.x - carried_by(b, r.support_body, support_start_rad, b.initial_position_m[i] + pivot).x;
        r.peak_abs_base_slip_m = std::max(r.peak_abs_base_slip_m, std::abs(r.base_slip_m));
        r.peak_abs_relative_displacement_m = std::max(r.peak_abs_relative_displacement_m, length(r.relative_displacement_m));
        if (sliding_now_[i]) r.sliding_time_s += w.dt_s;
        if (r.rocking_onset_s < 0.0 && r.rocked()) r.rocking_onset_s = w.time_s;
        if (r.slip_onset_s < 0.0 && r.slid()) r.slip_onset_s = w.time_s;
        observe_support(b, i, w.time_s, r, table_velocity, down);
    });
}

std::vector<BodyRecord> ResponseMonitor::records(const World& w) const {
    const Bodies& b = w.bodies;
    std::vector<BodyRecord> out(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) {
        const BodyResponse& r = responses_[i];
        BodyRecord& o = out[i];
        o.dynamic = b.kind[i] == BodyKind::dynamic;
        o.mass_kg = b.mass_kg[i];
        o.height_m = r.height_m;
        o.rocked = r.rocked();
        o.rocking_time_s = r.rocking_onset_s;
        o.slid = r.slid();
        o.sliding_time_s = r.slip_onset_s;
        o.overturned = r.overturned();
        o.overturning_time_s = r.overturned() ? r.last_crossing_s : -1.0;
        o.supporters = r.supporters;
        o.touches_a_supporter = r.touches_a_supporter;
        o.support_lost_time_s = r.support_lost_time_s;
        const double level = level_rad(w, w.time_s);
        o.drop_m = dot(r.relative_displacement_m, Vec2{-std::sin(level), -std::cos(level)});
        o.drop_time_s = r.drop_time_s;
        o.final_displacement_m = length(r.relative_displacement_m);
        o.final_position_m = b.position_m[i];
        o.at_rest = r.at_rest;
        o.touched_a_body = r.touched_a_body;
        o.rested_on_ground = r.rested_on_ground;
    }
    for (const BodyLeftModel& left : w.domain.left) {
        BodyRecord& o = out[left.body];
        o.left_model = true;
        o.left_model_time_s = left.time_s;
        o.left_model_position_m = left.position_m;
    }
    return out;
}

}  // namespace blockdem
