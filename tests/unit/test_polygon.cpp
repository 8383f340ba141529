// Polygon validation and mass properties.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/polygon.hpp"

namespace blockdem {
namespace {

TEST(Polygon, RectangleProperties) {
    const auto v = rectangle_vertices(0.5, 0.2, {1.0, 2.0}, 0.3);
    const PolygonProperties p = polygon_properties(v);
    EXPECT_NEAR(p.area_m2, 0.1, 1e-15);
    EXPECT_NEAR(p.centroid_m.x, 1.0, 1e-14);
    EXPECT_NEAR(p.centroid_m.y, 2.0, 1e-14);
    // Polar moment of a rectangle: A (w^2 + h^2) / 12, independent of the rotation.
    EXPECT_NEAR(p.polar_moment_m4, 0.1 * (0.25 + 0.04) / 12.0, 1e-15);
}

TEST(Polygon, TriangleProperties) {
    const std::vector<Vec2> v = {{0, 0}, {3, 0}, {0, 3}};
    const PolygonProperties p = polygon_properties(v);
    EXPECT_NEAR(p.area_m2, 4.5, 1e-14);
    EXPECT_NEAR(p.centroid_m.x, 1.0, 1e-14);
    EXPECT_NEAR(p.centroid_m.y, 1.0, 1e-14);
    // Right isosceles triangle, legs a: I_polar about the centroid = a^4 / 18.
    EXPECT_NEAR(p.polar_moment_m4, 81.0 / 18.0, 1e-12);
}

TEST(Polygon, FarFromOriginKeepsPrecision) {
    const auto v = rectangle_vertices(0.2, 0.1, {1e5, -3e4}, 0.0);
    EXPECT_NEAR(polygon_properties(v).polar_moment_m4, 0.02 * (0.04 + 0.01) / 12.0, 1e-12);
}

TEST(Polygon, ConvexityProblemsAreNamed) {
    EXPECT_FALSE(convexity_problem(rectangle_vertices(1, 1, {0, 0}, 0)));
    EXPECT_NE(convexity_problem({{0, 0}, {1, 0}})->find("at least 3"), std::string::npos);
    EXPECT_NE(convexity_problem({{0, 0}, {0, 1}, {1, 1}, {1, 0}})->find("clockwise"), std::string::npos);
    // Reflex corner at vertex 3 (an arrow head).
    EXPECT_NE(convexity_problem({{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}})->find("not strictly convex at vertex 3"),
              std::string::npos);
    // A bow tie crosses itself.
    EXPECT_TRUE(convexity_problem({{0, 0}, {1, 1}, {1, 0}, {0, 1}}).has_value());
    // A star winds twice with every turn to the left.
    std::vector<Vec2> star;
    for (int k = 0; k < 5; ++k) star.push_back({std::cos(4.0 * M_PI * k / 5.0), std::sin(4.0 * M_PI * k / 5.0)});
    EXPECT_NE(convexity_problem(star)->find("crosses itself"), std::string::npos);
    EXPECT_NE(convexity_problem({{0, 0}, {1, 0}, {1, 0}, {0, 1}})->find("coincide"), std::string::npos);
    EXPECT_TRUE(convexity_problem({{0, 0}, {1, 0}, {2, 0}, {1, 1}}).has_value());  // straight corner
}

}  // namespace
}  // namespace blockdem
