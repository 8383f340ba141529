#include "world/response_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {
namespace {

// The base is the edge whose outward normal points most nearly down at the start; the body tips
// about one of its two ends. Working in the edge's own frame makes the critical angles right
// for a body that starts tilted (on a slope, or settled a little off level): alpha is measured
// from the base lying flat, and the start's tilt is kept apart in base_tilt_rad.
BodyResponse base_of(const Bodies& b, std::size_t i) {
    const std::uint32_t first = b.vertex_begin[i];
    const std::uint32_t count = b.vertex_count[i];
    std::uint32_t base = 0;
    for (std::uint32_t k = 1; k < count; ++k)
        if (b.world_normals[first + k].y < b.world_normals[first + base].y) base = k;
    const Vec2 left = b.world_vertices_m[first + base];
    const Vec2 right = b.world_vertices_m[first + (base + 1) % count];
    const Vec2 along = normalized(right - left);   // +x when the base is level
    const Vec2 up = perp(along);                    // into the body
    const Vec2 c = b.position_m[i];
    const double height = dot(c - left, up);        // [m] centroid above the base
    BodyResponse r;
    r.alpha_ccw_rad = std::atan2(dot(c - left, along), height);
    r.alpha_cw_rad = std::atan2(dot(right - c, along), height);
    r.base_tilt_rad = std::atan2(along.y, along.x);
    r.base_left_offset_m = left - c;
    r.base_right_offset_m = right - c;
    r.base_length_m = length(right - left);
    r.rocking_threshold_rad = 0.01 * std::max(1e-6, std::min(std::abs(r.alpha_ccw_rad), std::abs(r.alpha_cw_rad)));
    return r;
}

}  // namespace

ResponseMonitor::ResponseMonitor(const World& w) : responses_(w.bodies.size()), sliding_now_(w.bodies.size(), 0) {
    const Bodies& b = w.bodies;
    for (std::size_t i = 0; i < b.size(); ++i)
        if (b.kind[i] == BodyKind::driven) {
            reference_ = static_cast<std::int64_t>(i);
            break;
        }
    for (std::size_t i = 0; i < b.size(); ++i) responses_[i] = base_of(b, i);
}

void ResponseMonitor::observe(const World& w) {
    const Bodies& b = w.bodies;
    std::fill(sliding_now_.begin(), sliding_now_.end(), 0);
    for (const PairContact& pair : w.contacts)
        for (std::uint32_t k = 0; k < pair.count; ++k)
            if (pair.points[k].sliding) sliding_now_[pair.a] = sliding_now_[pair.b] = 1;
    const Vec2 table_moved = reference_ >= 0 ? b.position_m[static_cast<std::size_t>(reference_)] -
                                                   b.initial_position_m[static_cast<std::size_t>(reference_)]
                                             : Vec2{};
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic) continue;
        BodyResponse& r = responses_[i];
        const double theta = b.rotation_rad[i];
        if (std::abs(theta) > r.peak_abs_rotation_rad) {
            r.peak_abs_rotation_rad = std::abs(theta);
            r.time_of_peak_rotation_s = w.time_s;
        }
        const double tilt = r.base_tilt_rad + theta;  // the base's angle from level
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
    }
}

}  // namespace blockdem
