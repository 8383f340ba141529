#pragma once
// A Verlet skin over the grid broad phase: the grid's search is run only now and then, on the
// boxes enlarged by a margin, and between these rebuilds the step's pairs are filtered out of
// that list by the exact test. The grid's search (counting sort into cells, pairs sorted) was
// 12 % of a 3-D wall's step and mostly serial (docs/performance.md, "Branch bp3d"), while a
// wall's bricks move a few hundredths of a millimetre a step.
//
// Why the pairs are exactly the grid's, bit for bit and in the same order: the grid gives every
// pair a < b, not both static, whose boxes overlap (broad_phase/grid_broad_phase.hpp). While
// each body's box stays inside the enlarged box it had at the last rebuild, two boxes that
// overlap now had overlapping enlarged boxes then, so the pair is in the list; the list is
// sorted, and the filter keeps its order. A body whose box leaves its enlarged box (moved or
// turned by more than the margin), a body added or removed, or a body that became static or
// dynamic, triggers a rebuild before the filter. The containment test is written so that a
// NaN coordinate fails it: such a step rebuilds, as the grid would have searched anyway.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "broad_phase/grid_broad_phase.hpp"
#include "broad_phase/grid_broad_phase_3d.hpp"

namespace blockdem {

template <class Box>
class SkinPairListOf {
public:
    /// The margin added to each side of every box at a rebuild, as a fraction of the median
    /// body's largest side. Larger: fewer rebuilds but more listed pairs to filter each step.
    /// 0.05 of a brick's 0.2 m is 1 cm: on the shaken S3D wall (0.23 m/s peak) a rebuild every
    /// few hundred steps, and almost no extra pairs (docs/performance.md, "Branch bp3d").
    static constexpr double margin_fraction = 0.05;

    /// Candidate pairs (a < b), sorted, excluding pairs where both bodies are static: the same
    /// pairs, in the same order, as GridBroadPhaseOf::find_pairs on the same boxes.
    void find_pairs(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static,
                    std::vector<BodyPair>& pairs);

    /// Rebuilds of the listed pairs (grid searches) since this object was made.
    std::int64_t rebuilds() const { return rebuilds_; }
    /// Pairs held in the skin list now (a superset of the last step's pairs).
    std::size_t listed_pairs() const { return listed_.size(); }

    /// Bytes held by the list, the enlarged boxes and the grid's scratch arrays.
    std::size_t memory_bytes() const {
        return grid_.memory_bytes() + enlarged_.capacity() * sizeof(Box) +
               (listed_.capacity() + kept_pairs_.capacity()) * sizeof(BodyPair) +
               (built_static_.capacity() + keep_.capacity()) * sizeof(std::uint8_t) +
               chunk_kept_.capacity() * sizeof(std::size_t) + extents_.capacity() * sizeof(double) +
               box_offsets_.capacity() * sizeof(std::uint32_t);
    }

private:
    bool must_rebuild(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static) const;
    void rebuild(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static);

    GridBroadPhaseOf<Box> grid_;
    std::vector<Box> enlarged_;               ///< each body's box at the last rebuild, plus the margin
    std::vector<std::uint8_t> built_static_;  ///< is_static at the last rebuild
    std::vector<BodyPair> listed_;            ///< the grid's pairs of the enlarged boxes, sorted
    std::vector<std::uint8_t> keep_;          ///< per listed pair: its boxes overlap this step
    std::vector<std::size_t> chunk_kept_;     ///< per fixed chunk of the list: pairs kept, then their offset
    std::vector<double> extents_;             ///< [m] scratch of a rebuild: each body's largest side
    std::int64_t rebuilds_ = 0;
    std::vector<BodyPair> kept_pairs_;        ///< 3-D: each chunk's kept pairs, from the chunk's start
    /// 3-D: per listed pair, its two boxes' byte offsets in the boxes' array (empty where they would
    /// not fit 32 bits; the 2-D loop is then used).
    std::vector<std::uint32_t> box_offsets_;
};

extern template class SkinPairListOf<Aabb>;
extern template class SkinPairListOf<Aabb3d>;
using SkinPairList = SkinPairListOf<Aabb>;
using SkinPairList3d = SkinPairListOf<Aabb3d>;

}  // namespace blockdem
