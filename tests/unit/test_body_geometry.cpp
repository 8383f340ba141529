// The body geometry of a step (update_body_geometry, world/step.cpp) against the formulas it
// stands for, bit for bit: each corner at x + R v, each normal R n (Rotation::apply), each core
// offset rounded_corner_offset(normal before, normal after, r) and each part's box the
// std::min/std::max of its corners. place_corners writes these out lane by lane for speed
// (docs/performance.md, "Body geometry in two lanes"); a different rounding anywhere would show
// here as a differing bit, and in every output downstream.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "geometry/rounded_contact.hpp"
#include "scenes/assemblies.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

bool same_bits(Vec2 x, Vec2 y) { return std::memcmp(&x, &y, sizeof(Vec2)) == 0; }

// Every body of a small S3 wall, and of a few polygons whose corners are not right angles (a
// brick's offsets divide by 1 + n_before . n_after = 1), turned and moved to assorted places
// (angles of both signs, a full turn and more, exact zero), with rounding_m (0: sharp).
void check_geometry(double rounding_m) {
    Model m = scenes::bonded_wall_scene(20, 1.0);
    for (int sides = 3; sides <= 9; ++sides) {
        BodyDef polygon{.name = "polygon " + std::to_string(sides), .density_kg_m3 = 2000.0};
        for (int k = 0; k < sides; ++k) {
            const double angle = 2.0 * std::acos(-1.0) * (k + 0.13 * (k % 3)) / sides;
            polygon.vertices_m.push_back({20.0 + sides + 0.4 * std::cos(angle), 5.0 + 0.3 * std::sin(angle)});
        }
        m.bodies.push_back(polygon);
    }
    World w = build_world(m);
    w.contact.rounding_m = rounding_m;
    Bodies& b = w.bodies;
    for (std::size_t i = 0; i < b.size(); ++i) {
        b.rotation_rad[i] = i % 5 == 0 ? 0.0 : std::sin(1.7 * static_cast<double>(i)) * (1.0 + 0.37 * (i % 11));
        b.position_m[i] = b.position_m[i] + Vec2{1e-3 * std::cos(0.3 * i), -2e-3 * std::sin(0.7 * i)};
    }
    update_body_geometry(w);
    std::size_t corners = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const Rotation r = Rotation::from_angle(b.rotation_rad[i]);
        for (std::uint32_t j = b.part_begin[i]; j < b.part_begin[i] + b.part_count[i]; ++j) {
            const std::uint32_t first = b.part_vertex_begin[j], count = b.part_vertex_count[j];
            Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
            for (std::uint32_t k = first; k < first + count; ++k) {
                const Vec2 v = b.position_m[i] + r.apply(b.local_vertices_m[k]);
                const Vec2 n = r.apply(b.local_normals[k]);
                ASSERT_TRUE(same_bits(b.world_vertices_m[k], v)) << "body " << i << " corner " << k;
                ASSERT_TRUE(same_bits(b.world_normals[k], n)) << "body " << i << " corner " << k;
                if (rounding_m > 0.0) {
                    const Vec2 before = r.apply(b.local_normals[k == first ? first + count - 1 : k - 1]);
                    ASSERT_TRUE(same_bits(b.world_corner_offsets_m[k], rounded_corner_offset(before, n, rounding_m)))
                        << "body " << i << " corner " << k;
                }
                lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
                hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
                ++corners;
            }
            EXPECT_TRUE(same_bits(b.part_box_m[j].lo, lo)) << "part " << j;
            EXPECT_TRUE(same_bits(b.part_box_m[j].hi, hi)) << "part " << j;
        }
    }
    EXPECT_GT(corners, 4 * b.size() - 1);
    EXPECT_EQ(b.corner_offsets_rounding_m, rounding_m);
}

TEST(BodyGeometry, RoundedCornersOffsetsAndBoxesAreTheFormulasBits) { check_geometry(0.002); }

TEST(BodyGeometry, SharpCornersAndBoxesAreTheFormulasBits) { check_geometry(0.0); }

}  // namespace
}  // namespace blockdem
