#include "geometry/joint_set_3d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace blockdem {

Vec3 joint_normal(double dip_direction_deg, double dip_deg) {
    const double to_rad = std::numbers::pi / 180.0;
    const double a = dip_direction_deg * to_rad, b = dip_deg * to_rad;
    return {std::sin(b) * std::sin(a), std::sin(b) * std::cos(a), std::cos(b)};
}

namespace {

// The whole multiples k of the spacing whose joint crosses the region: [first, last].
struct JointRange {
    double first = 0.0;
    double last = -1.0;
};

JointRange joint_range(const JointSet3d& set, const std::vector<Vec3>& region_vertices_m) {
    const Vec3 n = joint_normal(set.dip_direction_deg, set.dip_deg);
    const double origin_offset_m = dot(n, set.origin_m);
    double lowest = INFINITY, highest = -INFINITY;  // [m] of the region along n, from the origin's joint
    for (Vec3 v : region_vertices_m) {
        lowest = std::min(lowest, dot(n, v) - origin_offset_m);
        highest = std::max(highest, dot(n, v) - origin_offset_m);
    }
    // (A joint on the region's extreme vertex or face is counted; it cuts nothing off.)
    const JointRange r{std::ceil(lowest / set.spacing_m), std::floor(highest / set.spacing_m)};
    // Beyond 2^52 whole numbers are no longer spaced by one in a double: an origin or a spacing
    // no rock mass has.
    if (!(std::abs(r.first) < 0x1.0p52 && std::abs(r.last) < 0x1.0p52))
        throw std::invalid_argument("the joints' numbers from the origin exceed 2^52: origin too far or spacing too small");
    return r;
}

}  // namespace

std::size_t joint_plane_count(const JointSet3d& set, const std::vector<Vec3>& region_vertices_m) {
    const JointRange r = joint_range(set, region_vertices_m);
    return r.last < r.first ? 0 : static_cast<std::size_t>(r.last - r.first) + 1;
}

std::vector<Plane3d> joint_planes(const JointSet3d& set, const std::vector<Vec3>& region_vertices_m) {
    const Vec3 n = joint_normal(set.dip_direction_deg, set.dip_deg);
    const double origin_offset_m = dot(n, set.origin_m);
    const JointRange r = joint_range(set, region_vertices_m);
    std::vector<Plane3d> planes;
    for (double k = r.first; k <= r.last; k += 1.0) planes.push_back({n, origin_offset_m + k * set.spacing_m});
    return planes;
}

}  // namespace blockdem
