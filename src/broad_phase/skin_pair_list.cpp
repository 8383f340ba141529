#include "broad_phase/skin_pair_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "world/parallel.hpp"

namespace blockdem {
namespace {

Aabb enlarged(const Aabb& b, double margin_m) {
    return {{b.lo.x - margin_m, b.lo.y - margin_m}, {b.hi.x + margin_m, b.hi.y + margin_m}};
}

Aabb3d enlarged(const Aabb3d& b, double margin_m) {
    return {{b.lo.x - margin_m, b.lo.y - margin_m, b.lo.z - margin_m},
            {b.hi.x + margin_m, b.hi.y + margin_m, b.hi.z + margin_m}};
}

// Written as "all bounds inside" so that a NaN bound answers false (and forces a rebuild).
template <class Box>
bool contains(const Box& outer, const Box& inner) {
    using Axes = BoxAxes<Box>;
    for (std::size_t axis = 0; axis < Axes::count; ++axis)
        if (!(Axes::lo(inner, axis) >= Axes::lo(outer, axis) && Axes::hi(inner, axis) <= Axes::hi(outer, axis)))
            return false;
    return true;
}

// The filter over the listed pairs runs in this many fixed chunks when the list is long, whatever
// the thread count: each chunk counts what it keeps, the counts' prefix sum places each chunk's
// pairs, so the pairs keep the list's order at any thread count (world/parallel.hpp, rule 1).
constexpr std::size_t large_list_chunks = 64;

// The same pairs as SkinPairListOf::find_pairs's two passes over its flags, in the same fixed
// chunks and order; written for 3-D alone, so that the 2-D filter is the code it was. Each chunk
// holds the list's and
// the boxes' pointers in its own locals (a store through a lambda's captures could alias them, so
// the 2-D loop reads them again at every pair) and writes each pair at once at the chunk's next
// free place in kept_pairs_ (compacted from the chunk's start; a pair that fails is overwritten),
// so that the second pass copies the kept pairs only instead of reading every listed pair's flag:
// 2.46 M -> 1.70 M instructions a step for the 1e4-brick wall's 64 k listed pairs.
// The two boxes of a listed pair are read at their byte offsets in the boxes' array, taken at the
// rebuild (box_offsets, two a pair), where they are addressed directly: from the bodies' numbers
// each box's address took a multiply by the box's 48 bytes (two instructions) and an add, and the
// pair's two numbers were split out of one register: 1.74 M -> 1.42 M instructions a step at 1e4.
void filter_compacted(const std::vector<BodyPair>& listed_pairs, const std::vector<std::uint32_t>& box_offsets,
                      const std::vector<Aabb3d>& boxes, std::vector<BodyPair>& kept_pairs,
                      std::vector<std::size_t>& chunk_kept_counts, std::vector<BodyPair>& pairs) {
    const std::size_t listed = listed_pairs.size();
    const std::size_t chunks =
        static_cast<std::ptrdiff_t>(listed) >= parallel_threshold ? large_list_chunks : std::size_t{1};
    kept_pairs.resize(listed);
    chunk_kept_counts.assign(chunks + 1, 0);
    const BodyPair* const list = listed_pairs.data();
    const std::uint32_t* const offset = box_offsets.data();
    const char* const box_bytes = reinterpret_cast<const char*>(boxes.data());
    const auto box_at = [box_bytes](std::uint32_t byte_offset) {
        return reinterpret_cast<const Aabb3d*>(box_bytes + byte_offset);
    };
    BodyPair* const compacted = kept_pairs.data();
    std::size_t* const chunk_kept = chunk_kept_counts.data();
    const auto n_chunks = static_cast<std::ptrdiff_t>(chunks);
#pragma omp parallel for schedule(dynamic) if (chunks > 1)
    for (std::ptrdiff_t k = 0; k < n_chunks; ++k) {
        const std::size_t begin = listed * static_cast<std::size_t>(k) / chunks;
        const std::size_t end = listed * static_cast<std::size_t>(k + 1) / chunks;
        BodyPair* const out = compacted + begin;
        std::size_t kept = 0;
        for (std::size_t p = begin; p < end; ++p) {
            out[kept] = list[p];
            kept += overlaps(*box_at(offset[2 * p]), *box_at(offset[2 * p + 1]));
        }
        chunk_kept[k + 1] = kept;
    }
    for (std::size_t k = 0; k < chunks; ++k) chunk_kept[k + 1] += chunk_kept[k];
    pairs.resize(chunk_kept[chunks]);
    BodyPair* const to = pairs.data();
#pragma omp parallel for schedule(dynamic) if (chunks > 1)
    for (std::ptrdiff_t k = 0; k < n_chunks; ++k) {
        const BodyPair* const from = compacted + listed * static_cast<std::size_t>(k) / chunks;
        std::copy(from, from + (chunk_kept[k + 1] - chunk_kept[k]), to + chunk_kept[k]);
    }
}

// Whether every box's byte offset in an array of count boxes fits the 32 bits of box_offsets.
template <class Box>
bool offsets_fit(std::size_t count) {
    return count <= std::numeric_limits<std::uint32_t>::max() / sizeof(Box);
}

}  // namespace

template <class Box>
bool SkinPairListOf<Box>::must_rebuild(const std::vector<Box>& boxes,
                                       const std::vector<std::uint8_t>& is_static) const {
    if (rebuilds_ == 0 || boxes.size() != enlarged_.size() || is_static != built_static_) return true;
    // "Any body outside its enlarged box" as a count, so that the loop may share out; which
    // bodies are counted by which thread does not change whether the count is zero.
    const std::size_t outside = deterministic_sum(static_cast<std::ptrdiff_t>(boxes.size()), [&](std::ptrdiff_t i) {
        return static_cast<std::size_t>(!contains(enlarged_[i], boxes[i]));
    });
    return outside > 0;
}

template <class Box>
void SkinPairListOf<Box>::rebuild(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static) {
    using Axes = BoxAxes<Box>;
    // The margin follows the median body (its largest side), as the grid's cell does.
    std::vector<double>& extents = extents_;
    extents.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        double extent = 0.0;
        for (std::size_t axis = 0; axis < Axes::count; ++axis)
            extent = std::max(extent, Axes::hi(boxes[i], axis) - Axes::lo(boxes[i], axis));
        extents[i] = extent;
    }
    double margin_m = 0.0;  // [m]
    if (!extents.empty()) {
        std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
        margin_m = margin_fraction * extents[extents.size() / 2];
    }
    if (!std::isfinite(margin_m)) margin_m = 0.0;  // a NaN or infinite body: the exact boxes
    enlarged_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) enlarged_[i] = enlarged(boxes[i], margin_m);
    built_static_ = is_static;
    grid_.find_pairs(enlarged_, is_static, listed_);
    if constexpr (std::is_same_v<Box, Aabb3d>) {
        // Each listed pair's two boxes by their byte offsets, for the filter (filter_compacted).
        box_offsets_.clear();
        if (offsets_fit<Box>(boxes.size())) {
            box_offsets_.resize(2 * listed_.size());
            for (std::size_t p = 0; p < listed_.size(); ++p) {
                box_offsets_[2 * p] = static_cast<std::uint32_t>(listed_[p].first * sizeof(Box));
                box_offsets_[2 * p + 1] = static_cast<std::uint32_t>(listed_[p].second * sizeof(Box));
            }
        }
    }
    ++rebuilds_;
}

template <class Box>
void SkinPairListOf<Box>::find_pairs(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static,
                                     std::vector<BodyPair>& pairs) {
    if (must_rebuild(boxes, is_static)) rebuild(boxes, is_static);
    if constexpr (std::is_same_v<Box, Aabb3d>) {
        if (offsets_fit<Box>(boxes.size())) {
            filter_compacted(listed_, box_offsets_, boxes, kept_pairs_, chunk_kept_, pairs);
            return;
        }
    }
    const std::size_t listed = listed_.size();
    const std::size_t chunks =
        static_cast<std::ptrdiff_t>(listed) >= parallel_threshold ? large_list_chunks : std::size_t{1};
    keep_.resize(listed);
    chunk_kept_.assign(chunks + 1, 0);
    auto chunk_begin = [&](std::size_t k) { return listed * k / chunks; };
    // Bounds and arrays taken into locals: a store through the flags' bytes may alias anything,
    // so the compiler would otherwise reload them (and divide for the bound) at every pair.
    const BodyPair* const list = listed_.data();
    const Box* const box = boxes.data();
    std::uint8_t* const keep = keep_.data();
    // Pass 1: each pair's exact test, and each chunk's count (the static test was the rebuild's).
    auto test_chunk = [&](std::size_t k) {
        std::size_t kept = 0;
        const std::size_t end = chunk_begin(k + 1);
        for (std::size_t p = chunk_begin(k); p < end; ++p) {
            const bool in = overlaps(box[list[p].first], box[list[p].second]);
            keep[p] = in;
            kept += in;
        }
        chunk_kept_[k + 1] = kept;
    };
    // Pass 2: each chunk's kept pairs written from its offset.
    auto write_chunk = [&](std::size_t k, BodyPair* out) {
        const std::size_t end = chunk_begin(k + 1);
        for (std::size_t p = chunk_begin(k); p < end; ++p)
            if (keep[p]) *out++ = list[p];
    };
    if (chunks == 1) {
        test_chunk(0);
        pairs.resize(chunk_kept_[1]);
        write_chunk(0, pairs.data());
        return;
    }
    const auto n_chunks = static_cast<std::ptrdiff_t>(chunks);
#pragma omp parallel for schedule(dynamic)
    for (std::ptrdiff_t k = 0; k < n_chunks; ++k) test_chunk(static_cast<std::size_t>(k));
    for (std::size_t k = 0; k < chunks; ++k) chunk_kept_[k + 1] += chunk_kept_[k];
    pairs.resize(chunk_kept_[chunks]);
#pragma omp parallel for schedule(dynamic)
    for (std::ptrdiff_t k = 0; k < n_chunks; ++k)
        write_chunk(static_cast<std::size_t>(k), pairs.data() + chunk_kept_[static_cast<std::size_t>(k)]);
}

template class SkinPairListOf<Aabb>;
template class SkinPairListOf<Aabb3d>;

}  // namespace blockdem
