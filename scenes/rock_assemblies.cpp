// Jointed rock masses and Voronoi packings (scenes/assemblies.hpp). Both start from the convex
// pieces of the region (geometry/convex_decomposition.hpp) and only ever cut convex polygons by
// lines, so every block is convex by construction; tidy_convex_polygon() then removes the
// straight corners and near-coincident corners that a cut through a corner leaves.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geometry/convex_decomposition.hpp"
#include "geometry/half_plane_clip.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem::scenes {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

// SplitMix64 (Steele, Lea and Flood 2014): a small generator with the same output everywhere.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double symmetric() { return 2.0 * uniform01() - 1.0; }  ///< uniform in [-1, 1)

private:
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    std::uint64_t state_;
};

struct Bounds {
    Vec2 lo{INFINITY, INFINITY};
    Vec2 hi{-INFINITY, -INFINITY};
    void add(Vec2 p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    double size() const { return std::max(hi.x - lo.x, hi.y - lo.y); }
};

Bounds bounds_of(const Polygon& p) {
    Bounds b;
    for (Vec2 v : p) b.add(v);
    return b;
}

// Keeps a block if it is a proper convex polygon of at least the minimum area.
void keep(Polygon p, double tolerance_m, double min_area_m2, GeneratedBlocks& out) {
    const double raw_area = polygon_area(p);
    auto tidy = tidy_convex_polygon(p, tolerance_m);
    if (!tidy || polygon_area(*tidy) < min_area_m2) {
        ++out.dropped;
        out.dropped_area_m2 += std::max(0.0, raw_area);
        return;
    }
    out.polygons.push_back(std::move(*tidy));
}

// The lines dot(n_k, x) = c_k of one joint set that cross the region's bounds.
std::vector<HalfPlane> joint_lines(const JointSet& set, const Bounds& region, Random& random) {
    if (!(set.spacing_m > 0.0)) throw std::invalid_argument("joint spacing must be > 0");
    if (set.spacing_spread < 0.0 || set.spacing_spread >= 1.0) throw std::invalid_argument("spacing spread must be in [0, 1)");
    const double dip = set.dip_deg * degree;
    const Vec2 normal{-std::sin(dip), std::cos(dip)};
    // Range of the region along the normal, with one spacing to spare for spread dips.
    double lo = INFINITY;
    double hi = -INFINITY;
    for (Vec2 corner : {region.lo, region.hi, Vec2{region.lo.x, region.hi.y}, Vec2{region.hi.x, region.lo.y}}) {
        lo = std::min(lo, dot(normal, corner - set.origin_m));
        hi = std::max(hi, dot(normal, corner - set.origin_m));
    }
    // Joint positions along the normal from the origin, both ways, each gap spread at random.
    std::vector<double> at{0.0};
    for (double c = 0.0; c < hi + set.spacing_m;) at.push_back(c += set.spacing_m * (1.0 + set.spacing_spread * random.symmetric()));
    for (double c = 0.0; c > lo - set.spacing_m;) at.push_back(c -= set.spacing_m * (1.0 + set.spacing_spread * random.symmetric()));
    std::sort(at.begin(), at.end());
    std::vector<HalfPlane> lines;
    for (double c : at) {
        const double d = dip + set.dip_spread_deg * degree * random.symmetric();
        const Vec2 n{-std::sin(d), std::cos(d)};
        lines.push_back(half_plane_through(set.origin_m + c * normal, n));
    }
    return lines;
}

}  // namespace

Polygon slope_region(double base_height_m, double slope_height_m, double face_deg, double toe_length_m,
                     double crest_length_m) {
    if (!(face_deg > 0.0 && face_deg <= 90.0)) throw std::invalid_argument("the slope face angle must be in (0, 90] degrees");
    const double run = slope_height_m / std::tan(face_deg * degree);
    const double crest_x = run;
    const double end_x = crest_x + crest_length_m;
    Polygon p{{-toe_length_m, -base_height_m}, {end_x, -base_height_m}, {end_x, slope_height_m}, {crest_x, slope_height_m}};
    p.push_back({0.0, 0.0});
    if (toe_length_m > 0.0) p.push_back({-toe_length_m, 0.0});
    // A face without a base layer or toe: the corners at the origin repeat; drop repeats.
    if (base_height_m <= 0.0 && toe_length_m <= 0.0) p.erase(p.begin());
    return p;
}

GeneratedBlocks jointed_rock_mass(const RockMassSpec& spec) {
    const Bounds region = bounds_of(spec.region_m);
    const double tolerance = 1e-12 * region.size();
    Random random(spec.seed);
    std::vector<Polygon> blocks = convex_decomposition(spec.region_m);
    for (const JointSet& set : spec.joint_sets) {
        for (const HalfPlane& line : joint_lines(set, region, random)) {
            std::vector<Polygon> next;
            next.reserve(blocks.size() + 16);
            for (Polygon& block : blocks) {
                ConvexSplit parts = split_convex(block, line);
                if (parts.below.empty() || parts.above.empty()) {
                    next.push_back(std::move(block));  // not crossed (or only touched)
                    continue;
                }
                next.push_back(std::move(parts.below));
                next.push_back(std::move(parts.above));
            }
            blocks = std::move(next);
        }
    }
    GeneratedBlocks out;
    for (Polygon& b : blocks) keep(std::move(b), tolerance, spec.min_block_area_m2, out);
    return out;
}

namespace {

struct SeedGrid {
    Vec2 origin;
    double pitch_m = 1.0;
    int nx = 0;
    int ny = 0;
    std::vector<int> seed_of_cell;  ///< -1: no seed (outside the region)
    std::vector<Vec2> seeds;
};

bool inside_any(Vec2 p, const std::vector<Polygon>& pieces) {
    for (const Polygon& piece : pieces) {
        bool inside = true;
        for (std::size_t i = 0; i < piece.size() && inside; ++i)
            inside = cross(piece[(i + 1) % piece.size()] - piece[i], p - piece[i]) >= 0.0;
        if (inside) return true;
    }
    return false;
}

SeedGrid place_seeds(const VoronoiSpec& spec, const std::vector<Polygon>& pieces, const Bounds& region) {
    SeedGrid g;
    g.origin = region.lo;
    g.pitch_m = spec.cell_size_m;
    const double nx = std::ceil((region.hi.x - region.lo.x) / g.pitch_m);
    const double ny = std::ceil((region.hi.y - region.lo.y) / g.pitch_m);
    if (!(nx * ny <= static_cast<double>(std::numeric_limits<int>::max())))  // checked before the casts
        throw std::invalid_argument("the Voronoi seed grid has more cells than can be numbered (cell size too small)");
    g.nx = static_cast<int>(nx);
    g.ny = static_cast<int>(ny);
    g.seed_of_cell.assign(static_cast<std::size_t>(g.nx) * g.ny, -1);
    Random random(spec.seed);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double u = 0.5 * spec.jitter * random.symmetric();
            const double v = 0.5 * spec.jitter * random.symmetric();
            const Vec2 p = g.origin + g.pitch_m * Vec2{i + 0.5 + u, j + 0.5 + v};
            if (!inside_any(p, pieces)) continue;
            g.seed_of_cell[static_cast<std::size_t>(j) * g.nx + i] = static_cast<int>(g.seeds.size());
            g.seeds.push_back(p);
        }
    return g;
}

// The Voronoi cell of seed s clipped to piece, within a square of half-size reach around s:
// seeds farther than 2 sqrt(2) reach cannot cut that square, so only grid cells within that
// distance are visited. Returns false if the cell reaches the square's edge (reach too small).
bool voronoi_cell(const SeedGrid& g, int s, const Polygon& piece, double reach_m, Polygon& cell) {
    const Vec2 p = g.seeds[static_cast<std::size_t>(s)];
    cell = piece;
    for (const Vec2 dir : {Vec2{1, 0}, Vec2{-1, 0}, Vec2{0, 1}, Vec2{0, -1}}) {
        cell = clip_convex(cell, half_plane_through(p + reach_m * dir, dir));
        if (cell.empty()) return true;
    }
    const int ring = static_cast<int>(std::ceil(2.0 * std::numbers::sqrt2 * reach_m / g.pitch_m)) + 1;
    const int ci = static_cast<int>((p.x - g.origin.x) / g.pitch_m);
    const int cj = static_cast<int>((p.y - g.origin.y) / g.pitch_m);
    for (int j = std::max(0, cj - ring); j <= std::min(g.ny - 1, cj + ring) && !cell.empty(); ++j)
        for (int i = std::max(0, ci - ring); i <= std::min(g.nx - 1, ci + ring) && !cell.empty(); ++i) {
            const int other = g.seed_of_cell[static_cast<std::size_t>(j) * g.nx + i];
            if (other < 0 || other == s) continue;
            const Vec2 q = g.seeds[static_cast<std::size_t>(other)];
            // The bisector, written the same way from both sides so the two cells share it exactly.
            const Vec2 mid = 0.5 * (p + q);
            cell = clip_convex(cell, half_plane_through(mid, q - p));
        }
    for (Vec2 v : cell)
        if (std::max(std::abs(v.x - p.x), std::abs(v.y - p.y)) > (1.0 - 1e-9) * reach_m) return false;
    return true;
}

Polygon shrunk(Polygon p, double shrink) {
    if (shrink <= 0.0) return p;
    Vec2 c;
    for (Vec2 v : p) c += v;
    c = (1.0 / static_cast<double>(p.size())) * c;
    for (Vec2& v : p) v = c + (1.0 - shrink) * (v - c);
    return p;
}

}  // namespace

double estimated_block_count(const RockMassSpec& spec) {
    const Bounds region = bounds_of(spec.region_m);
    const double diagonal = std::hypot(region.hi.x - region.lo.x, region.hi.y - region.lo.y);
    std::vector<double> lines;
    for (const JointSet& set : spec.joint_sets) {
        const double smallest_gap = set.spacing_m * (1.0 - std::clamp(set.spacing_spread, 0.0, 0.999));
        lines.push_back((diagonal + 2.0 * set.spacing_m) / smallest_gap + 3.0);
    }
    double faces = 1.0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        faces += lines[i];
        for (std::size_t j = i + 1; j < lines.size(); ++j) faces += lines[i] * lines[j];
    }
    const double pieces = static_cast<double>(std::max<std::size_t>(spec.region_m.size(), 3) - 2);
    double crossings = 0.0;
    for (double n : lines) crossings += n;
    return faces + pieces * (1.0 + crossings);
}

double estimated_block_count(const VoronoiSpec& spec) {
    const Bounds region = bounds_of(spec.region_m);
    return std::ceil((region.hi.x - region.lo.x) / spec.cell_size_m) * std::ceil((region.hi.y - region.lo.y) / spec.cell_size_m) +
           static_cast<double>(spec.region_m.size());
}

GeneratedBlocks voronoi_packing(const VoronoiSpec& spec) {
    if (!(spec.cell_size_m > 0.0)) throw std::invalid_argument("the Voronoi cell size must be > 0");
    if (spec.jitter < 0.0 || spec.jitter > 1.0) throw std::invalid_argument("jitter must be in [0, 1]");
    if (spec.shrink < 0.0 || spec.shrink >= 1.0) throw std::invalid_argument("shrink must be in [0, 1)");
    const std::vector<Polygon> pieces = convex_decomposition(spec.region_m);
    const Bounds region = bounds_of(spec.region_m);
    const double tolerance = 1e-12 * region.size();
    const SeedGrid grid = place_seeds(spec, pieces, region);
    GeneratedBlocks out;
    Polygon cell;
    for (int s = 0; s < static_cast<int>(grid.seeds.size()); ++s)
        for (const Polygon& piece : pieces) {
            // A cell is within sqrt(2) pitch of its seed unless seeds are missing nearby (at the
            // region's edge): then widen the search until the cell fits.
            double reach = 1.5 * grid.pitch_m;
            while (!voronoi_cell(grid, s, piece, reach, cell)) reach *= 2.0;
            if (cell.size() >= 3) keep(shrunk(cell, spec.shrink), tolerance, 0.0, out);
        }
    return out;
}

}  // namespace blockdem::scenes
