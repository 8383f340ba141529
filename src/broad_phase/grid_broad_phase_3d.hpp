#pragma once
// Broad phase in 3-D: the candidate pairs whose bounding boxes overlap, in time linear in the
// number of bodies. The 2-D grid's scheme (broad_phase/grid_broad_phase.hpp) with one more index:
// bodies are binned into a uniform grid of cells twice the median body's size; a pair is reported
// once, from the cell that holds the lowest corner of the two boxes' intersection; bodies much
// larger than a cell (the table, a base) are not binned but tested against every other body.
#include <cstdint>
#include <vector>

#include "broad_phase/grid_broad_phase.hpp"  // BodyPair
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

class GridBroadPhase3d {
public:
    /// Candidate pairs (a < b), sorted, excluding pairs where both bodies are static.
    void find_pairs(const std::vector<Aabb3d>& boxes, const std::vector<std::uint8_t>& is_static,
                    std::vector<BodyPair>& pairs);

    /// Bytes held by the scratch arrays.
    std::size_t memory_bytes() const {
        return (cell_start_.capacity() + cell_items_.capacity() + large_.capacity() + small_.capacity() +
                fill_.capacity()) * sizeof(std::uint32_t) +
               (extents_.capacity() + sorted_extents_.capacity()) * sizeof(double);
    }

private:
    std::vector<std::uint32_t> cell_start_;
    std::vector<std::uint32_t> cell_items_;
    std::vector<std::uint32_t> large_;
    std::vector<std::uint32_t> small_;
    std::vector<double> extents_;
    std::vector<double> sorted_extents_;
    std::vector<std::uint32_t> fill_;
};

}  // namespace blockdem
