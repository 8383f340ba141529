#pragma once
// The 3-D box and its axes for the grid broad phase (broad_phase/grid_broad_phase.hpp), which
// is written once for both dimensions.
#include <cstddef>

#include "broad_phase/grid_broad_phase.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

struct Aabb3d {
    Vec3 lo;  ///< [m]
    Vec3 hi;  ///< [m]
};

inline bool overlaps(const Aabb3d& a, const Aabb3d& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
}

template <>
struct BoxAxes<Aabb3d> {
    static constexpr std::size_t count = 3;
    static double lo(const Aabb3d& b, std::size_t axis) {  ///< [m]
        return axis == 0 ? b.lo.x : axis == 1 ? b.lo.y : b.lo.z;
    }
    static double hi(const Aabb3d& b, std::size_t axis) {  ///< [m]
        return axis == 0 ? b.hi.x : axis == 1 ? b.hi.y : b.hi.z;
    }
};

extern template class GridBroadPhaseOf<Aabb3d>;
using GridBroadPhase3d = GridBroadPhaseOf<Aabb3d>;

}  // namespace blockdem
