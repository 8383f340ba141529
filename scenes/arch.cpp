// A masonry arch of voussoirs with radial joints (scenes/assemblies.hpp). The joint lines are
// computed once, at equal angles along the ring, and shared by the two blocks on either side of
// each joint (and by the abutments at the springings), so that neighbouring faces coincide
// exactly: a limit analysis finds them as interfaces and a DEM run starts with them touching.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "scenes/assemblies.hpp"

namespace blockdem::scenes {

double arch_radius_m(double span_m, double rise_m) { return (0.25 * span_m * span_m + rise_m * rise_m) / (2.0 * rise_m); }

ArchBlocks masonry_arch(const ArchSpec& spec) {
    if (!(spec.span_m > 0.0)) throw std::invalid_argument(fmt::format("span must be > 0, got {}", spec.span_m));
    if (!(spec.rise_m > 0.0 && spec.rise_m <= 0.5 * spec.span_m * (1.0 + 1e-12)))
        throw std::invalid_argument(fmt::format("rise must be in (0, span / 2] = (0, {}], got {} (span / 2: a semicircle)",
                                                0.5 * spec.span_m, spec.rise_m));
    if (spec.voussoirs < 3) throw std::invalid_argument(fmt::format("voussoirs must be >= 3, got {}", spec.voussoirs));
    // A rise far below the span makes the radius, and the centre's distance, enormous: the
    // blocks' corners would lose every digit that tells them apart (or overflow).
    if (!(spec.rise_m >= 1e-3 * spec.span_m))
        throw std::invalid_argument(fmt::format("rise must be at least span / 1000 = {:g} m (a flatter arch is a lintel), got {}",
                                                1e-3 * spec.span_m, spec.rise_m));
    if (!(spec.span_m < 1e4)) throw std::invalid_argument(fmt::format("span must be < 10 km, got {} m", spec.span_m));
    const double radius = arch_radius_m(spec.span_m, spec.rise_m);
    if (!(spec.ring_thickness_m > 0.0 && spec.ring_thickness_m < 2.0 * radius))
        throw std::invalid_argument(fmt::format("ring_thickness must be in (0, 2 R) = (0, {:g}) m, got {}", 2.0 * radius,
                                                spec.ring_thickness_m));
    const double intrados = radius - 0.5 * spec.ring_thickness_m;
    const double extrados = radius + 0.5 * spec.ring_thickness_m;
    const Vec2 centre = spec.origin_m + Vec2{0.0, spec.rise_m - radius};
    // Half the angle the ring subtends; its joints at pi/2 + half - k (2 half / n).
    const double half = std::asin(std::min(1.0, 0.5 * spec.span_m / radius));
    const int n = spec.voussoirs;
    std::vector<Vec2> inner(n + 1), outer(n + 1);
    for (int k = 0; k <= n; ++k) {
        const double angle = 0.5 * std::numbers::pi + half - 2.0 * half * k / n;
        const Vec2 radial{std::cos(angle), std::sin(angle)};
        inner[k] = centre + intrados * radial;
        outer[k] = centre + extrados * radial;
    }
    ArchBlocks out;
    for (int k = 0; k < n; ++k) out.voussoirs.push_back({inner[k + 1], outer[k + 1], outer[k], inner[k]});
    const double depth = spec.abutment_height_m > 0.0 ? spec.abutment_height_m : spec.ring_thickness_m;
    const double left_base = std::min(inner[0].y, outer[0].y) - depth;
    const double right_base = std::min(inner[n].y, outer[n].y) - depth;
    out.left_abutment = {{outer[0].x, left_base}, {inner[0].x, left_base}, inner[0], outer[0]};
    out.right_abutment = {{inner[n].x, right_base}, {outer[n].x, right_base}, outer[n], inner[n]};
    return out;
}

std::vector<BodyDef> arch_bodies(const ArchBlocks& arch, const BlockStyle& style, BodyKind abutments) {
    std::vector<Polygon> polygons = arch.voussoirs;
    polygons.push_back(arch.left_abutment);
    polygons.push_back(arch.right_abutment);
    std::vector<BodyDef> bodies = as_bodies(polygons, style);
    for (std::size_t side = 0; side < 2; ++side) {
        BodyDef& b = bodies[bodies.size() - 2 + side];
        b.name = style.name_prefix + (side == 0 ? "_left_abutment" : "_right_abutment");
        b.kind = abutments;
    }
    return bodies;
}

}  // namespace blockdem::scenes
