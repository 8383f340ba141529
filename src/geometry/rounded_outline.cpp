#include "geometry/rounded_outline.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "geometry/outline.hpp"
#include "geometry/polygon.hpp"

namespace blockdem {
namespace {

// The corner of the lines of edges before and after a corner, both moved by r along their
// outward normals (inward for r > 0): v - r (n1 + n2) / (1 + n1 . n2), for convex and reflex
// corners alike (a folded-back corner, n1 . n2 = -1, is refused by outline_problem).
Vec2 moved_corner(Vec2 v, Vec2 normal_before, Vec2 normal_after, double r) {
    return v - (r / (1.0 + dot(normal_before, normal_after))) * (normal_before + normal_after);
}

std::vector<Vec2> normals_of(const std::vector<Vec2>& p) {
    std::vector<Vec2> n;
    for (std::size_t k = 0; k < p.size(); ++k) n.push_back(edge_normal(p[k], p[(k + 1) % p.size()]));
    return n;
}

}  // namespace

RoundedOutlineParts rounded_outline_parts(const std::vector<Vec2>& outline, double rounding_m) {
    const std::size_t count = outline.size();
    const std::vector<Vec2> normals = normals_of(outline);
    std::vector<Vec2> core(count);
    for (std::size_t i = 0; i < count; ++i)
        core[i] = moved_corner(outline[i], normals[(i + count - 1) % count], normals[i], rounding_m);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t j = (i + 1) % count;
        if (dot(core[j] - core[i], outline[j] - outline[i]) <= 0.0)
            throw std::invalid_argument(fmt::format("[contact] rounding = {:g} m removes edge {} (corner {} to {}) of "
                                                    "the outline moved inward by the rounding",
                                                    rounding_m, i, i, j));
    }
    if (auto problem = outline_problem(core))
        throw std::invalid_argument(
            fmt::format("[contact] rounding = {:g} m: the outline moved inward by the rounding is no simple polygon: {}",
                        rounding_m, *problem));
    // The convex corners of the core: the arcs of the body, each given to one part.
    double size = 0.0;
    for (Vec2 v : outline) size = std::max(size, std::abs(v.x) + std::abs(v.y));
    const double same_place = 1e-9 * size;
    std::vector<std::uint8_t> arc_taken(count, 0);
    std::vector<std::uint8_t> convex(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec2 before = core[i] - core[(i + count - 1) % count];
        const Vec2 after = core[(i + 1) % count] - core[i];
        convex[i] = cross(before, after) > 0.0 ? 1 : 0;
    }
    RoundedOutlineParts out;
    for (const std::vector<Vec2>& piece : outline_parts(core)) {
        const std::vector<Vec2> piece_normals = normals_of(piece);
        std::vector<Vec2> part(piece.size());
        std::vector<std::uint8_t> seam(piece.size(), 1);
        for (std::size_t k = 0; k < piece.size(); ++k) {
            part[k] = moved_corner(piece[k], piece_normals[(k + piece.size() - 1) % piece.size()], piece_normals[k],
                                   -rounding_m);
            for (std::size_t i = 0; i < count; ++i) {
                if (!convex[i] || arc_taken[i] || std::abs(piece[k].x - core[i].x) + std::abs(piece[k].y - core[i].y) > same_place)
                    continue;
                arc_taken[i] = 1;
                seam[k] = 0;
                break;
            }
        }
        out.parts.push_back(std::move(part));
        out.seam.push_back(std::move(seam));
    }
    return out;
}

}  // namespace blockdem
