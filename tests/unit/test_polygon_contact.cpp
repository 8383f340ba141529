// Narrow phase: contact points of the corner-to-edge model, feature ids, degenerate cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/polygon_contact.hpp"
#include "polygon_test_support.hpp"

namespace blockdem {
namespace {

using testing::box;
using testing::Poly;

const Poly table = box(4.0, 0.2, {0.0, -0.1});

TEST(PolygonContact, FlatBlockTouchesAtItsTwoBottomCorners) {
    const double overlap = 1e-4;
    const Poly block = box(0.5, 0.2, {0.3, 0.1 - overlap});
    ContactManifold m;
    ASSERT_TRUE(collide_polygons(table.view(), block.view(), no_reference, m));
    ASSERT_EQ(m.count, 2u);
    EXPECT_NEAR(m.normal.x, 0.0, 1e-15);
    EXPECT_NEAR(m.normal.y, 1.0, 1e-15);
    std::vector<double> xs;
    for (std::uint32_t i = 0; i < m.count; ++i) {
        EXPECT_NEAR(m.points[i].overlap_m, overlap, 1e-12);
        EXPECT_NEAR(m.points[i].point_m.y, -0.5 * overlap, 1e-12);  // midway between the surfaces
        EXPECT_EQ(feature_owner(m.points[i].feature), 1u);          // corners of the block
        xs.push_back(m.points[i].point_m.x);
    }
    std::sort(xs.begin(), xs.end());
    EXPECT_NEAR(xs[0], 0.05, 1e-12);
    EXPECT_NEAR(xs[1], 0.55, 1e-12);
}

TEST(PolygonContact, RockingBlockTouchesAtOneCorner) {
    const double tilt = 0.05;
    // Rotate about the bottom-left corner, then press it 1e-5 m into the table.
    const Vec2 pivot{-0.25, -1e-5};
    const Vec2 center = pivot + Rotation::from_angle(tilt).apply(Vec2{0.25, 0.1});
    const Poly block = box(0.5, 0.2, center, tilt);
    ContactManifold m;
    ASSERT_TRUE(collide_polygons(table.view(), block.view(), no_reference, m));
    ASSERT_EQ(m.count, 1u);
    EXPECT_NEAR(m.points[0].overlap_m, 1e-5, 1e-12);
    EXPECT_NEAR(m.points[0].point_m.x, -0.25, 1e-9);
}

TEST(PolygonContact, SeparatedAndTouchingGiveNoPoints) {
    ContactManifold m;
    EXPECT_FALSE(collide_polygons(table.view(), box(0.5, 0.2, {0.0, 0.2}).view(), no_reference, m));
    EXPECT_EQ(m.count, 0u);
    EXPECT_FALSE(collide_polygons(table.view(), box(0.5, 0.2, {0.0, 0.1}).view(), no_reference, m));  // exactly touching
}

TEST(PolygonContact, NormalPointsFromAToB) {
    const Poly block = box(0.5, 0.2, {0.0, 0.1 - 1e-4});
    ContactManifold ab, ba;
    ASSERT_TRUE(collide_polygons(table.view(), block.view(), no_reference, ab));
    ASSERT_TRUE(collide_polygons(block.view(), table.view(), no_reference, ba));
    EXPECT_NEAR(ab.normal.y, 1.0, 1e-15);
    EXPECT_NEAR(ba.normal.y, -1.0, 1e-15);
}

TEST(PolygonContact, EqualAlignedFacesKeepTwoPointsAndOverlap) {
    // Two identical blocks stacked with coinciding corners: parallel faces of equal length.
    const Poly lower = box(0.4, 0.2, {0.0, 0.1});
    const Poly upper = box(0.4, 0.2, {0.0, 0.3 - 1e-5});
    ContactManifold m;
    ASSERT_TRUE(collide_polygons(lower.view(), upper.view(), no_reference, m));
    ASSERT_EQ(m.count, 2u);
    for (std::uint32_t i = 0; i < 2; ++i) EXPECT_NEAR(m.points[i].overlap_m, 1e-5, 1e-12);
}

TEST(PolygonContact, ParallelEdgesOfDifferentLengthGiveSameFeaturesWhicheverReference) {
    // A block on a wider block: whichever face is the reference, the two points are named after
    // the narrow block's corners, so shear history survives a change of reference.
    const Poly wide = box(1.0, 0.2, {0.0, 0.1});
    const Poly narrow = box(0.4, 0.2, {0.1, 0.3 - 1e-5});
    ContactManifold natural, forced;
    ASSERT_TRUE(collide_polygons(wide.view(), narrow.view(), no_reference, natural));
    // Force the narrow block's bottom edge (edge 0, owner 1) as the reference through hysteresis.
    ASSERT_TRUE(collide_polygons(wide.view(), narrow.view(), make_feature(1, 0), forced));
    EXPECT_EQ(forced.reference, make_feature(1, 0));
    ASSERT_EQ(natural.count, 2u);
    ASSERT_EQ(forced.count, 2u);
    auto features = [](const ContactManifold& m) {
        std::vector<std::uint32_t> f = {m.points[0].feature, m.points[1].feature};
        std::sort(f.begin(), f.end());
        return f;
    };
    EXPECT_EQ(features(natural), features(forced));
    for (std::uint32_t i = 0; i < 2; ++i) EXPECT_NEAR(forced.points[i].overlap_m, 1e-5, 1e-12);
}

TEST(PolygonContact, SlidingAcrossAnEdgeEndHasNoForceJump) {
    // A block slides off the end of a step: as its corner passes the step's corner the
    // contact's spring force (stiffness_scale times the summed overlap) fades continuously.
    const Poly step = box(1.0, 0.2, {0.0, 0.1});
    double previous = -1.0;
    for (double x = 0.60; x < 0.80; x += 0.001) {
        const Poly block = box(0.4, 0.2, {x, 0.3 - 1e-5});
        ContactManifold m;
        collide_polygons(step.view(), block.view(), no_reference, m);
        double total = 0.0;
        for (std::uint32_t i = 0; i < m.count; ++i) total += m.stiffness_scale * m.points[i].overlap_m;
        // Steps of 1 mm against l = 4 mm: at most a quarter of the full 2e-5 m per step.
        if (previous >= 0.0) EXPECT_NEAR(total, previous, 0.26 * 2e-5) << "x = " << x;
        previous = total;
    }
}

TEST(PolygonContact, CornerToCornerIsContinuousWithHysteresis) {
    // A square pressed diagonally onto the corner of another: as the pressing block moves
    // sideways across the corner, the chosen reference keeps the depth continuous.
    const Poly base = box(0.4, 0.4, {0.0, 0.0});
    std::uint32_t reference = no_reference;
    double previous = -1.0;
    for (double s = -0.0009; s <= 0.0009; s += 1e-5) {
        const Poly corner = box(0.2, 0.2, Vec2{0.2 + 0.1 - 1e-3 + s, 0.2 + 0.1 - 1e-3 - s}, 0.0);
        ContactManifold m;
        ASSERT_TRUE(collide_polygons(base.view(), corner.view(), reference, m));
        reference = m.reference;
        double deepest = 0.0;
        for (std::uint32_t i = 0; i < m.count; ++i) deepest = std::max(deepest, m.points[i].overlap_m);
        if (previous >= 0.0) EXPECT_LT(std::abs(deepest - previous), 0.03 * previous + 2e-5) << "s = " << s;
        previous = deepest;
    }
}

}  // namespace
}  // namespace blockdem
