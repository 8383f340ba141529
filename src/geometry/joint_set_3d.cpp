#include "geometry/joint_set_3d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace blockdem {

Vec3 joint_normal(double dip_direction_deg, double dip_deg) {
    const double to_rad = std::numbers::pi / 180.0;
    const double a = dip_direction_deg * to_rad, b = dip_deg * to_rad;
    return {std::sin(b) * std::sin(a), std::sin(b) * std::cos(a), std::cos(b)};
}

std::vector<Plane3d> joint_planes(const JointSet3d& set, const std::vector<Vec3>& region_vertices_m) {
    const Vec3 n = joint_normal(set.dip_direction_deg, set.dip_deg);
    const double origin_offset_m = dot(n, set.origin_m);
    double lowest = INFINITY, highest = -INFINITY;  // [m] of the region along n, from the origin's joint
    for (Vec3 v : region_vertices_m) {
        lowest = std::min(lowest, dot(n, v) - origin_offset_m);
        highest = std::max(highest, dot(n, v) - origin_offset_m);
    }
    std::vector<Plane3d> planes;
    // (A joint on the region's extreme vertex or face cuts nothing: the cut leaves it whole.)
    for (double k = std::ceil(lowest / set.spacing_m); k * set.spacing_m <= highest; k += 1.0)
        planes.push_back({n, origin_offset_m + k * set.spacing_m});
    return planes;
}

}  // namespace blockdem
