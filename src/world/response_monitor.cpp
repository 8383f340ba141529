#include "world/response_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {
namespace {

// The base is the edge whose outward normal points most nearly down at the start; the body tips
// about one of its two ends. Working in the edge's own frame makes the critical angles right
// for a body that starts tilted (on a slope, or settled a little off level): alpha is measured
// from the base lying flat, and the start's tilt is kept apart in base_tilt_rad. "Down" and
// "level" are gravity's, which a tilted table turns (down = (-sin tilt, -cos tilt), level angle =
// tilt: a base along x is tilted from level by the table's tilt).
BodyResponse base_of(const Bodies& b, std::size_t i, const OutcomeThresholds& t, double level_angle_rad) {
    const Vec2 down{-std::sin(level_angle_rad), -std::cos(level_angle_rad)};
    const std::uint32_t first = b.vertex_begin[i];
    const std::uint32_t count = b.vertex_count[i];
    std::uint32_t base = 0;
    for (std::uint32_t k = 1; k < count; ++k)
        if (dot(b.world_normals[first + k], down) > dot(b.world_normals[first + base], down)) base = k;
    const Vec2 left = b.world_vertices_m[first + base];
    const Vec2 right = b.world_vertices_m[first + (base + 1) % count];
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
    for (std::uint32_t k = first; k < first + count; ++k) {
        low = std::min(low, -dot(b.world_vertices_m[k], down));
        high = std::max(high, -dot(b.world_vertices_m[k], down));
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
    for (std::size_t i = 0; i < b.size(); ++i) responses_[i] = base_of(b, i, thresholds_, start_level_rad_);
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
        for (std::uint32_t k = 0; k < pair.count; ++k)
            if (pair.points[k].sliding) sliding_now_[pair.a] = sliding_now_[pair.b] = 1;
        if (gathering) {
            // The normal points from a to b: upwards means a is below b and holds it up.
            auto add = [&](std::uint32_t upper, std::uint32_t lower) {
                if (b.kind[upper] == BodyKind::dynamic && !holds(responses_[upper].supporters, lower))
                    responses_[upper].supporters.push_back(lower);
            };
            if (dot(pair.normal, up) > supporting_normal_y) add(pair.b, pair.a);
            if (dot(pair.normal, up) < -supporting_normal_y) add(pair.a, pair.b);
        }
        if (holds(responses_[pair.a].supporters, pair.b)) touching_supporter_now_[pair.a] = 1;
        if (holds(responses_[pair.b].supporters, pair.a)) touching_supporter_now_[pair.b] = 1;
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
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic || is_taken_out(b, i)) continue;
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
        // The corner it tips about stays put unless the base slides: follow that one.
        const Vec2 pivot = tilt >= 0.0 ? r.base_left_offset_m : r.base_right_offset_m;
        const Vec2 pivot_now = b.position_m[i] + Rotation::from_angle(theta).apply(pivot);
        r.base_slip_m = pivot_now.x - (b.initial_position_m[i].x + pivot.x) - table_moved.x;
        r.peak_abs_base_slip_m = std::max(r.peak_abs_base_slip_m, std::abs(r.base_slip_m));
        r.peak_abs_relative_displacement_m = std::max(r.peak_abs_relative_displacement_m, length(r.relative_displacement_m));
        if (sliding_now_[i]) r.sliding_time_s += w.dt_s;
        if (r.rocking_onset_s < 0.0 && r.rocked()) r.rocking_onset_s = w.time_s;
        if (r.slip_onset_s < 0.0 && r.slid()) r.slip_onset_s = w.time_s;
        observe_support(b, i, w.time_s, r, table_velocity, down);
    }
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
