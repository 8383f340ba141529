#include "world/response_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {

ResponseMonitor::ResponseMonitor(const World& w) : responses_(w.bodies.size()), sliding_now_(w.bodies.size(), 0) {
    const Bodies& b = w.bodies;
    for (std::size_t i = 0; i < b.size(); ++i)
        if (b.kind[i] == BodyKind::driven) {
            reference_ = static_cast<std::int64_t>(i);
            break;
        }
    for (std::size_t i = 0; i < b.size(); ++i) {
        // Base corners: the lowest corners at the start. A settled assembly (world/settling.hpp)
        // starts slightly tilted (rotations of order 1e-4 rad), so "as low" means within 1e-3 of
        // the body's size, not within round-off: otherwise one corner alone is the base, alpha
        // is zero on one side and the block is reported overturned at t = 0.
        double lowest = INFINITY;
        double size = b.bounding_radius_m[i];
        for (std::uint32_t k = 0; k < b.vertex_count[i]; ++k)
            lowest = std::min(lowest, b.world_vertices_m[b.vertex_begin[i] + k].y);
        double left = INFINITY;
        double right = -INFINITY;
        for (std::uint32_t k = 0; k < b.vertex_count[i]; ++k) {
            const Vec2 v = b.world_vertices_m[b.vertex_begin[i] + k];
            if (v.y > lowest + 1e-3 * size) continue;
            left = std::min(left, v.x);
            right = std::max(right, v.x);
        }
        const Vec2 c = b.position_m[i];
        BodyResponse& r = responses_[i];
        r.alpha_ccw_rad = std::atan2(c.x - left, c.y - lowest);
        r.alpha_cw_rad = std::atan2(right - c.x, c.y - lowest);
        r.rocking_threshold_rad = 0.01 * std::max(1e-6, std::min(std::abs(r.alpha_ccw_rad), std::abs(r.alpha_cw_rad)));
    }
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
        const bool beyond = theta > r.alpha_ccw_rad || theta < -r.alpha_cw_rad;
        if (beyond && !r.beyond_alpha) r.last_crossing_s = w.time_s;
        r.beyond_alpha = beyond;
        r.relative_displacement_m = (b.position_m[i] - b.initial_position_m[i]) - table_moved;
        r.peak_abs_relative_displacement_m = std::max(r.peak_abs_relative_displacement_m, length(r.relative_displacement_m));
        if (sliding_now_[i]) r.sliding_time_s += w.dt_s;
    }
}

}  // namespace blockdem
