#include "broad_phase/grid_broad_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "broad_phase/grid_broad_phase_3d.hpp"
#include "world/parallel.hpp"

namespace blockdem {
namespace {

template <std::size_t Dims>
struct Grid {
    std::array<double, Dims> origin{};  ///< [m]
    double cell_m = 1.0;                ///< [m]
    std::array<std::int64_t, Dims> count;  // cells along each axis

    Grid() { count.fill(1); }

    // Clamped as doubles, then cast: a body 1e300 m away must not reach an undefined cast. Bodies
    // 1e308 m apart make the cell infinite and the far one's offset inf / inf, NaN, which
    // std::clamp would pass on to the cast: std::max(0.0, NaN) is 0, the first cell.
    std::int64_t index(std::size_t axis, double coordinate_m) const {
        const double cell = std::max(0.0, std::floor((coordinate_m - origin[axis]) / cell_m));
        return static_cast<std::int64_t>(std::min(cell, static_cast<double>(count[axis] - 1)));
    }
    // The flat index of the cell whose index along `axis` is `index` and along the higher
    // axes gives `flat_above`: x varies fastest.
    std::size_t flat(std::size_t flat_above, std::size_t axis, std::int64_t index) const {
        return flat_above * static_cast<std::size_t>(count[axis]) + static_cast<std::size_t>(index);
    }
    std::size_t cell_count() const {
        std::size_t cells = 1;
        for (std::int64_t c : count) cells *= static_cast<std::size_t>(c);
        return cells;
    }
};

// Calls visit(cell) for every cell the box spans, highest axis outermost: one nested loop per
// axis, unrolled at compile time.
template <std::size_t Axis, class Box, class Visit>
void for_cells(const Grid<BoxAxes<Box>::count>& grid, const Box& box, std::size_t flat_above, Visit& visit) {
    using Axes = BoxAxes<Box>;
    const std::int64_t last = grid.index(Axis, Axes::hi(box, Axis));
    for (std::int64_t c = grid.index(Axis, Axes::lo(box, Axis)); c <= last; ++c) {
        const std::size_t flat = grid.flat(flat_above, Axis, c);
        if constexpr (Axis == 0)
            visit(flat);
        else
            for_cells<Axis - 1>(grid, box, flat, visit);
    }
}

template <class Box, class Visit>
void for_cells(const Grid<BoxAxes<Box>::count>& grid, const Box& box, Visit visit) {
    for_cells<BoxAxes<Box>::count - 1>(grid, box, 0, visit);
}

// The cell holding the lowest corner of the intersection of a and b.
template <class Box>
std::size_t corner_cell(const Grid<BoxAxes<Box>::count>& grid, const Box& a, const Box& b) {
    using Axes = BoxAxes<Box>;
    std::size_t cell = 0;
    for (std::size_t axis = Axes::count; axis-- > 0;)
        cell = grid.flat(cell, axis, grid.index(axis, std::max(Axes::lo(a, axis), Axes::lo(b, axis))));
    return cell;
}

// The largest side of the box.
template <class Box>
double extent_m(const Box& box) {
    using Axes = BoxAxes<Box>;
    double extent = Axes::hi(box, 0) - Axes::lo(box, 0);
    for (std::size_t axis = 1; axis < Axes::count; ++axis)
        extent = std::max(extent, Axes::hi(box, axis) - Axes::lo(box, axis));
    return extent;
}

// A large scene's search is cut into this many chunks, whatever the thread count: each writes its
// own list (world/parallel.hpp's rule 1), and the lists are joined and sorted, so the pairs do not
// depend on how many threads ran. A small scene's is one chunk, run serially (world/parallel.hpp:
// starting threads costs more than its whole search).
constexpr std::size_t large_scene_chunks = 64;

std::size_t search_chunks(std::size_t n) {
    return static_cast<std::ptrdiff_t>(n) >= parallel_threshold ? large_scene_chunks : 1;
}

// Calls search(k) for every chunk k of a scene of n bodies, on all threads when it has several.
template <class Search>
void for_chunks(std::size_t n, Search search) {
    const auto chunks = static_cast<std::ptrdiff_t>(search_chunks(n));
    if (chunks == 1) {
        search(0);
        return;
    }
#pragma omp parallel for schedule(dynamic)
    for (std::ptrdiff_t k = 0; k < chunks; ++k) search(static_cast<std::size_t>(k));
}

}  // namespace

template <class Box>
void GridBroadPhaseOf<Box>::find_pairs(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static,
                                       std::vector<BodyPair>& pairs) {
    using Axes = BoxAxes<Box>;
    constexpr std::size_t dims = Axes::count;
    pairs.clear();
    const std::uint32_t n = static_cast<std::uint32_t>(boxes.size());
    if (n < 2) return;
    const std::size_t chunks = search_chunks(n);
    if (chunk_pairs_.size() < chunks) chunk_pairs_.resize(chunks);

    // Cell size: twice the median body extent, so that a typical body spans at most 2 cells a side.
    extents_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) extents_[i] = extent_m(boxes[i]);
    sorted_extents_.assign(extents_.begin(), extents_.end());  // scratch kept between rebuilds
    std::nth_element(sorted_extents_.begin(), sorted_extents_.begin() + n / 2, sorted_extents_.end());
    Grid<dims> grid;
    grid.cell_m = std::max(2.0 * sorted_extents_[n / 2], 1e-9);

    large_.clear();
    small_.clear();
    std::array<double, dims> lo;  // [m] the bounds of the binned bodies
    std::array<double, dims> hi;  // [m]
    lo.fill(INFINITY);
    hi.fill(-INFINITY);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (extents_[i] > 4.0 * grid.cell_m) {
            large_.push_back(i);
            continue;
        }
        small_.push_back(i);
        for (std::size_t axis = 0; axis < dims; ++axis) {
            lo[axis] = std::min(lo[axis], Axes::lo(boxes[i], axis));
            hi[axis] = std::max(hi[axis], Axes::hi(boxes[i], axis));
        }
    }

    if (!small_.empty()) {
        grid.origin = lo;
        // Cell counts as doubles until they are known to be small: bodies spread over 1e300 m
        // must neither overflow the product nor reach an undefined cast.
        std::array<double, dims> along;
        auto count_cells = [&] {
            double cells = 1.0;
            for (std::size_t axis = 0; axis < dims; ++axis) {
                along[axis] = std::floor((hi[axis] - lo[axis]) / grid.cell_m) + 1.0;
                cells *= along[axis];
            }
            return cells;
        };
        // A sparse, spread-out set of bodies would make a huge grid: coarsen until cells ~ bodies
        // (4 per body, and 4 a side for a handful of bodies).
        double spare_cells = 1.0;
        for (std::size_t axis = 0; axis < dims; ++axis) spare_cells *= 4.0;
        const double max_cells = 4.0 * static_cast<double>(small_.size()) + spare_cells;
        double cells_wanted = count_cells();
        while (cells_wanted > max_cells && std::isfinite(grid.cell_m)) {
            grid.cell_m *= 2.0;
            cells_wanted = count_cells();
        }
        if (!(cells_wanted <= max_cells)) along.fill(1.0);  // an infinite extent (1e308 m apart): one cell
        for (std::size_t axis = 0; axis < dims; ++axis) grid.count[axis] = static_cast<std::int64_t>(along[axis]);
        const std::size_t cells = grid.cell_count();

        // Counting sort of (cell, body) entries.
        cell_start_.assign(cells + 1, 0);
        for (std::uint32_t i : small_) for_cells(grid, boxes[i], [&](std::size_t c) { ++cell_start_[c + 1]; });
        for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
        cell_items_.resize(cell_start_[cells]);
        fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
        for (std::uint32_t i : small_) for_cells(grid, boxes[i], [&](std::size_t c) { cell_items_[fill_[c]++] = i; });

        for_chunks(n, [&](std::size_t k) {
            std::vector<BodyPair>& found = chunk_pairs_[k];
            for (std::size_t c = cells * k / chunks; c < cells * (k + 1) / chunks; ++c) {
                for (std::uint32_t p = cell_start_[c]; p < cell_start_[c + 1]; ++p) {
                    for (std::uint32_t q = p + 1; q < cell_start_[c + 1]; ++q) {
                        const std::uint32_t a = cell_items_[p];
                        const std::uint32_t b = cell_items_[q];
                        if ((is_static[a] && is_static[b]) || !overlaps(boxes[a], boxes[b])) continue;
                        // Report only from the cell that holds the intersection's lowest corner.
                        if (corner_cell(grid, boxes[a], boxes[b]) != c) continue;
                        found.emplace_back(std::min(a, b), std::max(a, b));
                    }
                }
            }
        });
    }

    if (!large_.empty()) {
        for_chunks(n, [&](std::size_t k) {
            std::vector<BodyPair>& found = chunk_pairs_[k];
            for (std::uint32_t big : large_) {
                for (std::uint32_t other = n * k / chunks; other < n * (k + 1) / chunks; ++other) {
                    if (other == big) continue;
                    const bool other_is_large = extents_[other] > 4.0 * grid.cell_m;
                    if (other_is_large && other < big) continue;  // large-large pairs once
                    if ((is_static[big] && is_static[other]) || !overlaps(boxes[big], boxes[other])) continue;
                    found.emplace_back(std::min(big, other), std::max(big, other));
                }
            }
        });
    }
    for (std::size_t k = 0; k < chunks; ++k) {
        pairs.insert(pairs.end(), chunk_pairs_[k].begin(), chunk_pairs_[k].end());
        chunk_pairs_[k].clear();
    }
    std::sort(pairs.begin(), pairs.end());
}

template class GridBroadPhaseOf<Aabb>;
template class GridBroadPhaseOf<Aabb3d>;

}  // namespace blockdem
