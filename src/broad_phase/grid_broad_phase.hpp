#pragma once
// Broad phase: the candidate pairs whose (enlarged) bounding boxes overlap, in time linear in
// the number of bodies, written once for 2-D and 3-D boxes. Bodies are binned into a uniform
// grid whose cell size follows the typical body; a pair is reported once, from the cell holding
// the lowest corner of the two boxes' intersection. Bodies much larger than a cell (a table,
// the ground) are not binned but tested against every other body, which costs n per large body.
// What differs between the dimensions, reading a box's bounds along an axis, is BoxAxes<Box>;
// the 3-D box and its axes are in broad_phase/grid_broad_phase_3d.hpp.
#include <cstddef>
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

/// A box's bounds along axis 0 (x), 1 (y), ... : specialised for each box type.
template <class Box>
struct BoxAxes;

template <>
struct BoxAxes<Aabb> {
    static constexpr std::size_t count = 2;
    static double lo(const Aabb& b, std::size_t axis) { return axis == 0 ? b.lo.x : b.lo.y; }  ///< [m]
    static double hi(const Aabb& b, std::size_t axis) { return axis == 0 ? b.hi.x : b.hi.y; }  ///< [m]
};

using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

/// The grid broad phase over boxes of type Box (Aabb, Aabb3d); instantiated for both in its .cpp.
template <class Box>
class GridBroadPhaseOf {
public:
    /// Candidate pairs (a < b), sorted, excluding pairs where both bodies are static.
    void find_pairs(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static,
                    std::vector<BodyPair>& pairs);

    /// Bytes held by the scratch arrays.
    std::size_t memory_bytes() const {
        std::size_t chunk_bytes = 0;
        for (const std::vector<BodyPair>& c : chunk_pairs_) chunk_bytes += c.capacity() * sizeof(BodyPair);
        return (cell_start_.capacity() + cell_items_.capacity() + large_.capacity() + small_.capacity() +
                fill_.capacity()) * sizeof(std::uint32_t) +
               (extents_.capacity() + sorted_extents_.capacity()) * sizeof(double) + chunk_bytes;
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
    /// The pairs found by each fixed chunk of the search (threads share the chunks out).
    std::vector<std::vector<BodyPair>> chunk_pairs_;
};

extern template class GridBroadPhaseOf<Aabb>;
using GridBroadPhase = GridBroadPhaseOf<Aabb>;

}  // namespace blockdem
