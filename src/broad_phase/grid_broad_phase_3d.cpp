#include "broad_phase/grid_broad_phase_3d.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {
namespace {

struct Grid3d {
    Vec3 origin;          ///< [m]
    double cell_m = 1.0;  ///< [m]
    std::int64_t nx = 1;
    std::int64_t ny = 1;
    std::int64_t nz = 1;

    // Clamped as doubles, then cast: a body 1e300 m away must not reach an undefined cast.
    std::int64_t index(double offset_m, std::int64_t count) const {
        const double cell = std::clamp(std::floor(offset_m / cell_m), 0.0, static_cast<double>(count - 1));
        return static_cast<std::int64_t>(cell);
    }
    std::int64_t ix(double x) const { return index(x - origin.x, nx); }
    std::int64_t iy(double y) const { return index(y - origin.y, ny); }
    std::int64_t iz(double z) const { return index(z - origin.z, nz); }
    std::size_t cell(std::int64_t cx, std::int64_t cy, std::int64_t cz) const {
        return static_cast<std::size_t>((cz * ny + cy) * nx + cx);
    }
};

// Calls visit(cell) for every cell the box spans.
template <class Visit>
void for_cells(const Grid3d& g, const Aabb3d& b, Visit visit) {
    for (auto cz = g.iz(b.lo.z); cz <= g.iz(b.hi.z); ++cz)
        for (auto cy = g.iy(b.lo.y); cy <= g.iy(b.hi.y); ++cy)
            for (auto cx = g.ix(b.lo.x); cx <= g.ix(b.hi.x); ++cx) visit(g.cell(cx, cy, cz));
}

double extent(const Aabb3d& b) { return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z}); }

}  // namespace

void GridBroadPhase3d::find_pairs(const std::vector<Aabb3d>& boxes, const std::vector<std::uint8_t>& is_static,
                                  std::vector<BodyPair>& pairs) {
    pairs.clear();
    const std::uint32_t n = static_cast<std::uint32_t>(boxes.size());
    if (n < 2) return;

    extents_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) extents_[i] = extent(boxes[i]);
    sorted_extents_.assign(extents_.begin(), extents_.end());
    std::nth_element(sorted_extents_.begin(), sorted_extents_.begin() + n / 2, sorted_extents_.end());
    Grid3d grid;
    grid.cell_m = std::max(2.0 * sorted_extents_[n / 2], 1e-9);

    large_.clear();
    small_.clear();
    Aabb3d bounds{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (std::uint32_t i = 0; i < n; ++i) {
        if (extents_[i] > 4.0 * grid.cell_m) {
            large_.push_back(i);
            continue;
        }
        small_.push_back(i);
        bounds.lo = {std::min(bounds.lo.x, boxes[i].lo.x), std::min(bounds.lo.y, boxes[i].lo.y),
                     std::min(bounds.lo.z, boxes[i].lo.z)};
        bounds.hi = {std::max(bounds.hi.x, boxes[i].hi.x), std::max(bounds.hi.y, boxes[i].hi.y),
                     std::max(bounds.hi.z, boxes[i].hi.z)};
    }

    if (!small_.empty()) {
        grid.origin = bounds.lo;
        auto cells_along = [&](double extent_m) { return std::floor(extent_m / grid.cell_m) + 1.0; };
        const Vec3 span = bounds.hi - bounds.lo;
        double nx = cells_along(span.x), ny = cells_along(span.y), nz = cells_along(span.z);
        // A sparse, spread-out set of bodies would make a huge grid: coarsen until cells ~ bodies.
        const double max_cells = 4.0 * static_cast<double>(small_.size()) + 64.0;
        while (nx * ny * nz > max_cells && std::isfinite(grid.cell_m)) {
            grid.cell_m *= 2.0;
            nx = cells_along(span.x);
            ny = cells_along(span.y);
            nz = cells_along(span.z);
        }
        if (!(nx * ny * nz <= max_cells)) nx = ny = nz = 1.0;  // an infinite extent: one cell
        grid.nx = static_cast<std::int64_t>(nx);
        grid.ny = static_cast<std::int64_t>(ny);
        grid.nz = static_cast<std::int64_t>(nz);
        const std::size_t cells = static_cast<std::size_t>(grid.nx * grid.ny * grid.nz);

        // Counting sort of (cell, body) entries.
        cell_start_.assign(cells + 1, 0);
        for (std::uint32_t i : small_) for_cells(grid, boxes[i], [&](std::size_t c) { ++cell_start_[c + 1]; });
        for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
        cell_items_.resize(cell_start_[cells]);
        fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
        for (std::uint32_t i : small_) for_cells(grid, boxes[i], [&](std::size_t c) { cell_items_[fill_[c]++] = i; });

        for (std::size_t c = 0; c < cells; ++c) {
            for (std::uint32_t p = cell_start_[c]; p < cell_start_[c + 1]; ++p) {
                for (std::uint32_t q = p + 1; q < cell_start_[c + 1]; ++q) {
                    const std::uint32_t a = cell_items_[p];
                    const std::uint32_t b = cell_items_[q];
                    if ((is_static[a] && is_static[b]) || !overlaps(boxes[a], boxes[b])) continue;
                    // Report only from the cell that holds the intersection's lowest corner.
                    const double x0 = std::max(boxes[a].lo.x, boxes[b].lo.x);
                    const double y0 = std::max(boxes[a].lo.y, boxes[b].lo.y);
                    const double z0 = std::max(boxes[a].lo.z, boxes[b].lo.z);
                    if (grid.cell(grid.ix(x0), grid.iy(y0), grid.iz(z0)) != c) continue;
                    pairs.emplace_back(std::min(a, b), std::max(a, b));
                }
            }
        }
    }

    for (std::uint32_t big : large_) {
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
