// Body outlines (geometry/outline.hpp): the checks of a simple polygon and its convex parts.
// The parts must tile the outline: each strictly convex, their areas summing to the outline's
// (to round-off, 1e-12 relative), and no part outside it (its centroid inside). Shapes masons
// draw are cut into their natural rectangles; random star-shaped outlines (simple by
// construction) exercise the cuts in general position.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "geometry/outline.hpp"
#include "geometry/polygon.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem {
namespace {

// Even-odd test: p strictly inside the polygon (not on an edge) for a point in general position.
bool inside(const std::vector<Vec2>& poly, Vec2 p) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            in = !in;
    return in;
}

void expect_tiling(const std::vector<Vec2>& outline, std::size_t expected_parts = 0) {
    ASSERT_FALSE(outline_problem(outline)) << *outline_problem(outline);
    const std::vector<std::vector<Vec2>> parts = outline_parts(outline);
    if (expected_parts > 0) EXPECT_EQ(parts.size(), expected_parts);
    double area = 0.0;
    for (const std::vector<Vec2>& part : parts) {
        EXPECT_FALSE(convexity_problem(part)) << *convexity_problem(part);
        const PolygonProperties props = polygon_properties(part);
        area += props.area_m2;
        EXPECT_TRUE(inside(outline, props.centroid_m));
    }
    const double whole = polygon_properties(outline).area_m2;
    EXPECT_NEAR(area, whole, 1e-12 * whole);
}

TEST(Outline, MasonsShapesAreCutIntoTheirRectangles) {
    expect_tiling({{0, 0}, {0.4, 0}, {0.4, 0.15}, {0.1, 0.15}, {0.1, 0.8}, {0, 0.8}}, 2);                        // L
    expect_tiling({{-0.05, 0}, {0.05, 0}, {0.05, 0.5}, {0.3, 0.5}, {0.3, 0.6}, {-0.3, 0.6}, {-0.3, 0.5}, {-0.05, 0.5}}, 2);  // T
    expect_tiling({{0, 0}, {0.1, 0}, {0.1, 0.2}, {0.3, 0.2}, {0.3, 0}, {0.4, 0}, {0.4, 0.3}, {0, 0.3}}, 3);      // Pi
    expect_tiling(scenes::keyed_brick({1.0, 2.0}, 0.2, 0.1, 0.04, 0.02), 5);
    // The L's sole stays one edge of one part (no cut ends at its corners).
    int parts_on_sole = 0;
    for (const auto& part : outline_parts({{0, 0}, {0.4, 0}, {0.4, 0.15}, {0.1, 0.15}, {0.1, 0.8}, {0, 0.8}}))
        for (Vec2 v : part) parts_on_sole += v.x == 0.4 && v.y == 0.0 ? 1 : 0;
    EXPECT_EQ(parts_on_sole, 1);
}

TEST(Outline, RandomStarShapedOutlinesAreTiledByConvexParts) {
    std::uint64_t state = 12345;
    auto uniform = [&state] {  // (a fixed 64-bit generator: the same shapes on every library)
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    for (int shape = 0; shape < 200; ++shape) {
        const int n = 5 + shape % 20;
        std::vector<Vec2> outline;
        for (int k = 0; k < n; ++k) {
            const double angle = 2.0 * std::numbers::pi * (k + 0.8 * uniform()) / n;
            const double radius = 0.3 + uniform();
            outline.push_back({10.0 + radius * std::cos(angle), -3.0 + radius * std::sin(angle)});
        }
        if (outline_problem(outline)) continue;  // (a rare straight corner)
        SCOPED_TRACE(shape);
        expect_tiling(outline);
    }
}

TEST(Outline, ProblemsNameTheVertices) {
    // Keyhole: a square with a square hole reached through a slit.
    const std::vector<Vec2> keyhole{{0, 0},     {0.4, 0},   {0.4, 0.4}, {0, 0.4},   {0, 0.2},   {0.1, 0.2},
                                    {0.1, 0.3}, {0.3, 0.3}, {0.3, 0.1}, {0.1, 0.1}, {0.1, 0.2}, {0, 0.2}};
    EXPECT_NE(outline_problem(keyhole)->find("vertices 4 and 11 coincide"), std::string::npos);
    EXPECT_NE(outline_problem(keyhole)->find("keyhole"), std::string::npos);
    const auto crossing = outline_problem({{0, 0}, {0.4, 0}, {0.4, 0.3}, {0.2, 0.3}, {0.3, -0.1}});
    EXPECT_NE(crossing->find("the edge from vertex 0 to vertex 1 crosses the edge from vertex 3 to vertex 4"), std::string::npos);
    const auto folded = outline_problem({{0, 0}, {0.4, 0}, {0.4, 0.3}, {0.2, 0.3}, {0.3, 0.3}, {0, 0.3}, {0, 0.2}});
    EXPECT_TRUE(folded.has_value());
    // Listed clockwise: numbered as written.
    const auto straight = listed_outline_problem({{0, 0.8}, {0.1, 0.8}, {0.1, 0.5}, {0.1, 0.15}, {0.4, 0.15}, {0.4, 0}, {0, 0}});
    EXPECT_NE(straight->find("straight corner at vertex 2"), std::string::npos);
    EXPECT_NE(straight->find("listed clockwise"), std::string::npos);
    EXPECT_FALSE(listed_outline_problem({{0, 0.8}, {0.1, 0.8}, {0.1, 0.15}, {0.4, 0.15}, {0.4, 0}, {0, 0}}));
}

}  // namespace
}  // namespace blockdem
