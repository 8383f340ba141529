#pragma once
// Broad phase: the candidate pairs whose (enlarged) bounding boxes overlap, in time linear in
// the number of bodies. Bodies are binned into a uniform grid whose cell size follows the
// typical body; a pair is reported once, from the cell holding the lower-left corner of the
// two boxes' intersection. Bodies much larger than a cell (a table, the ground) are not binned
// but tested against every other body, which costs n per large body.
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

struct Aabb {
    Vec2 lo;  ///< [m]
    Vec2 hi;  ///< [m]
};

inline bool overlaps(const Aabb& a, const Aabb& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

class GridBroadPhase {
public:
    /// Candidate pairs (a < b), sorted, excluding pairs where both bodies are static.
    void find_pairs(const std::vector<Aabb>& boxes, const std::vector<std::uint8_t>& is_static,
                    std::vector<BodyPair>& pairs);

    /// Bytes held by the scratch arrays.
    std::size_t memory_bytes() const {
        return (cell_start_.capacity() + cell_items_.capacity() + large_.capacity() + small_.capacity() +
                fill_.capacity()) * sizeof(std::uint32_t) +
               (extents_.capacity() + sorted_extents_.capacity()) * sizeof(double);
    }

private:
    // Scratch arrays kept between calls so that a rebuild allocates nothing in steady state.
    std::vector<std::uint32_t> cell_start_;
    std::vector<std::uint32_t> cell_items_;
    std::vector<std::uint32_t> large_;
    std::vector<std::uint32_t> small_;
    std::vector<double> extents_;
    std::vector<double> sorted_extents_;
    std::vector<std::uint32_t> fill_;
};

}  // namespace blockdem
