#include "broad_phase/grid_broad_phase.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {
namespace {

struct Grid {
    Vec2 origin;            ///< [m]
    double cell_m = 1.0;    ///< [m]
    std::int64_t nx = 1;
    std::int64_t ny = 1;

    // Clamped as doubles, then cast: a body 1e300 m away must not reach an undefined cast.
    std::int64_t ix(double x) const { return index(x - origin.x, nx); }
    std::int64_t iy(double y) const { return index(y - origin.y, ny); }
    std::int64_t index(double offset_m, std::int64_t count) const {
        return static_cast<std::int64_t>(std::clamp(std::floor(offset_m / cell_m), 0.0, static_cast<double>(count - 1)));
    }
};

}  // namespace

void GridBroadPhase::find_pairs(const std::vector<Aabb>& boxes, const std::vector<std::uint8_t>& is_static,
                                std::vector<BodyPair>& pairs) {
    pairs.clear();
    const std::uint32_t n = static_cast<std::uint32_t>(boxes.size());
    if (n < 2) return;

    // Cell size: twice the median body extent, so that a typical body spans at most 2 x 2 cells.
    extents_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
        extents_[i] = std::max(boxes[i].hi.x - boxes[i].lo.x, boxes[i].hi.y - boxes[i].lo.y);
    sorted_extents_.assign(extents_.begin(), extents_.end());  // scratch kept between rebuilds
    std::nth_element(sorted_extents_.begin(), sorted_extents_.begin() + n / 2, sorted_extents_.end());
    Grid grid;
    grid.cell_m = std::max(2.0 * sorted_extents_[n / 2], 1e-9);

    large_.clear();
    small_.clear();
    Aabb bounds{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    for (std::uint32_t i = 0; i < n; ++i) {
        if (extents_[i] > 4.0 * grid.cell_m) {
            large_.push_back(i);
            continue;
        }
        small_.push_back(i);
        bounds.lo = {std::min(bounds.lo.x, boxes[i].lo.x), std::min(bounds.lo.y, boxes[i].lo.y)};
        bounds.hi = {std::max(bounds.hi.x, boxes[i].hi.x), std::max(bounds.hi.y, boxes[i].hi.y)};
    }

    if (!small_.empty()) {
        grid.origin = bounds.lo;
        // Cell counts as doubles until they are known to be small: bodies spread over 1e300 m
        // must neither overflow the product nor reach an undefined cast.
        auto cells_along = [&](double extent_m) { return std::floor(extent_m / grid.cell_m) + 1.0; };
        double nx = cells_along(bounds.hi.x - bounds.lo.x);
        double ny = cells_along(bounds.hi.y - bounds.lo.y);
        // A sparse, spread-out set of bodies would make a huge grid: coarsen until cells ~ bodies.
        const double max_cells = 4.0 * static_cast<double>(small_.size()) + 16.0;
        while (nx * ny > max_cells && std::isfinite(grid.cell_m)) {
            grid.cell_m *= 2.0;
            nx = cells_along(bounds.hi.x - bounds.lo.x);
            ny = cells_along(bounds.hi.y - bounds.lo.y);
        }
        if (!(nx * ny <= max_cells)) nx = ny = 1.0;  // an infinite extent (1e308 m apart): one cell
        grid.nx = static_cast<std::int64_t>(nx);
        grid.ny = static_cast<std::int64_t>(ny);
        const std::size_t cells = static_cast<std::size_t>(grid.nx * grid.ny);

        // Counting sort of (cell, body) entries.
        cell_start_.assign(cells + 1, 0);
        for (std::uint32_t i : small_)
            for (auto cy = grid.iy(boxes[i].lo.y); cy <= grid.iy(boxes[i].hi.y); ++cy)
                for (auto cx = grid.ix(boxes[i].lo.x); cx <= grid.ix(boxes[i].hi.x); ++cx)
                    ++cell_start_[static_cast<std::size_t>(cy * grid.nx + cx) + 1];
        for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
        cell_items_.resize(cell_start_[cells]);
        fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
        for (std::uint32_t i : small_)
            for (auto cy = grid.iy(boxes[i].lo.y); cy <= grid.iy(boxes[i].hi.y); ++cy)
                for (auto cx = grid.ix(boxes[i].lo.x); cx <= grid.ix(boxes[i].hi.x); ++cx)
                    cell_items_[fill_[static_cast<std::size_t>(cy * grid.nx + cx)]++] = i;

        for (std::size_t c = 0; c < cells; ++c) {
            const std::int64_t cx = static_cast<std::int64_t>(c) % grid.nx;
            const std::int64_t cy = static_cast<std::int64_t>(c) / grid.nx;
            for (std::uint32_t p = cell_start_[c]; p < cell_start_[c + 1]; ++p) {
                for (std::uint32_t q = p + 1; q < cell_start_[c + 1]; ++q) {
                    const std::uint32_t a = cell_items_[p];
                    const std::uint32_t b = cell_items_[q];
                    if ((is_static[a] && is_static[b]) || !overlaps(boxes[a], boxes[b])) continue;
                    // Report only from the cell that holds the intersection's lower-left corner.
                    const double x0 = std::max(boxes[a].lo.x, boxes[b].lo.x);
                    const double y0 = std::max(boxes[a].lo.y, boxes[b].lo.y);
                    if (grid.ix(x0) != cx || grid.iy(y0) != cy) continue;
                    pairs.emplace_back(std::min(a, b), std::max(a, b));
                }
            }
        }
    }

    for (std::size_t k = 0; k < large_.size(); ++k) {
        const std::uint32_t big = large_[k];
        for (std::uint32_t other = 0; other < n; ++other) {
            if (other == big) continue;
            const bool other_is_large = extents_[other] > 4.0 * grid.cell_m;
            if (other_is_large && other < big) continue;  // large-large pairs once
            if ((is_static[big] && is_static[other]) || !overlaps(boxes[big], boxes[other])) continue;
            pairs.emplace_back(std::min(big, other), std::max(big, other));
        }
    }
    std::sort(pairs.begin(), pairs.end());
}

}  // namespace blockdem
