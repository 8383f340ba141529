// Narrow phase with rounded corners (geometry/rounded_contact.hpp): face contacts as the sharp
// model's, corner contacts along the line between the arcs' centres, continuity between the two,
// and the rule that refuses a rounding too large for a body.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/polygon_contact.hpp"
#include "geometry/rounded_contact.hpp"
#include "polygon_test_support.hpp"

namespace blockdem {
namespace {

using testing::box;
using testing::Poly;

constexpr double r = 0.01;  // [m]

bool collide(const Poly& a, const Poly& b, ContactManifold& m, std::uint32_t previous = no_reference) {
    AxisCache cache;
    return collide_rounded(a.view(), b.view(), r, previous, m, cache);
}

TEST(RoundedContact, FlatBlockOnTableAsSharpButInsetByTheRadius) {
    const double overlap = 1e-4;
    const Poly table = box(4.0, 0.2, {0.0, -0.1});
    const Poly block = box(0.5, 0.2, {0.3, 0.1 - overlap});
    ContactManifold sharp, round;
    ASSERT_TRUE(collide_polygons(table.view(), block.view(), no_reference, sharp));
    ASSERT_TRUE(collide(table, block, round));
    ASSERT_EQ(round.count, 2u);
    EXPECT_NEAR(round.normal.x, 0.0, 1e-15);
    EXPECT_NEAR(round.normal.y, 1.0, 1e-15);
    EXPECT_EQ(round.stiffness_scale, 1.0);
    std::vector<double> xs;
    for (std::uint32_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(round.points[i].overlap_m, overlap, 1e-12);           // the same overlap as sharp
        EXPECT_NEAR(round.points[i].point_m.y, -0.5 * overlap, 1e-12);    // midway between the surfaces
        EXPECT_EQ(round.points[i].feature, sharp.points[i].feature);       // the same corners keep history
        xs.push_back(round.points[i].point_m.x);
    }
    std::sort(xs.begin(), xs.end());
    EXPECT_NEAR(xs[0], 0.05 + r, 1e-12);  // where the arcs start: r in from each bottom corner
    EXPECT_NEAR(xs[1], 0.55 - r, 1e-12);
}

TEST(RoundedContact, ApartWhenTheArcsDoNotMeet) {
    // The drawn squares overlap corner to corner (by 2 mm in x and in y), but each arc cuts
    // (sqrt 2 - 1) r = 4 mm off its corner along the diagonal: the rounded bodies stay apart.
    const Poly a = box(1.0, 1.0, {0.0, 0.0});
    const double inset = 0.5 * (std::sqrt(2.0) - 1.0) * r;  // how far each arc lies inside its sharp corner, per axis
    const Poly b = box(1.0, 1.0, {1.0 - inset, 1.0 - inset});
    ContactManifold m;
    EXPECT_FALSE(collide(a, b, m));
    EXPECT_EQ(m.count, 0u);
}

TEST(RoundedContact, CornerToCornerPushesAlongTheLineOfTheArcCentres) {
    // b's bottom-left corner against a's top-right one, offset so that the line between the two
    // arcs' centres is at some angle between the edge normals.
    const Poly a = box(1.0, 1.0, {0.0, 0.0});
    const Vec2 ca{0.5 - r, 0.5 - r};  // arc centre of a's corner
    const double d = 2.0 * r - 2e-4;  // 0.2 mm of overlap
    for (double angle_deg : {10.0, 30.0, 45.0, 60.0, 80.0}) {
        const double t = angle_deg * 3.14159265358979323846 / 180.0;
        const Vec2 dir{std::cos(t), std::sin(t)};
        const Vec2 cb = ca + d * dir;  // arc centre of b's corner
        const Poly b = box(1.0, 1.0, cb + Vec2{0.5 - r, 0.5 - r});
        ContactManifold m;
        ASSERT_TRUE(collide(a, b, m)) << angle_deg;
        ASSERT_EQ(m.count, 1u) << angle_deg;
        EXPECT_NEAR(m.normal.x, dir.x, 1e-9) << angle_deg;
        EXPECT_NEAR(m.normal.y, dir.y, 1e-9) << angle_deg;
        EXPECT_NEAR(m.points[0].overlap_m, 2e-4, 1e-12) << angle_deg;
        const Vec2 mid = ca + 0.5 * d * dir;
        EXPECT_NEAR(m.points[0].point_m.x, mid.x, 1e-12);
        EXPECT_NEAR(m.points[0].point_m.y, mid.y, 1e-12);
        EXPECT_EQ(m.points[0].feature, make_feature(1, 0));  // b's bottom-left corner (rectangle_vertices: corner 0)
    }
}

TEST(RoundedContact, NormalTurnsContinuouslyAsACornerRollsOverACorner) {
    // b's corner arc rolls around a's corner arc at a fixed centre distance: the sharp model's
    // normal jumps from one edge normal to the other; the rounded normal turns by the step.
    const Poly a = box(1.0, 1.0, {0.0, 0.0});
    const Vec2 ca{0.5 - r, 0.5 - r};
    const double d = 2.0 * r - 1e-4;
    Vec2 previous{};
    double largest_turn = 0.0;
    const int steps = 20000;
    double previous_force = 0.0;
    double largest_force_jump = 0.0;
    std::uint32_t reference = no_reference;
    for (int k = 0; k <= steps; ++k) {
        // From b beside a (normal +x) over the corner to b on top of a (normal +y), past both edges.
        const double t = -0.3 + (3.14159265358979323846 / 2.0 + 0.6) * k / steps;
        const Vec2 dir{std::cos(t), std::sin(t)};
        // b's corner nearest a's: bottom-left while dir is in the first quadrant; the block
        // follows the arc with its bottom-left arc centre at ca + d dir.
        const Poly b = box(1.0, 1.0, ca + d * dir + Vec2{0.5 - r, 0.5 - r});
        ContactManifold m;
        ASSERT_TRUE(collide(a, b, m, reference)) << t;
        reference = m.reference;
        // The normal: along the arc centres where both closest points are corners, else the edge's.
        const Vec2 expected = t < 0.0 ? Vec2{1.0, 0.0} : t > 3.14159265358979323846 / 2.0 ? Vec2{0.0, 1.0} : dir;
        EXPECT_NEAR(m.normal.x, expected.x, 1e-9) << t;
        EXPECT_NEAR(m.normal.y, expected.y, 1e-9) << t;
        if (k > 0) largest_turn = std::max(largest_turn, std::acos(std::clamp(dot(m.normal, previous), -1.0, 1.0)));
        previous = m.normal;
        // The pair's force (kn = 1: points x scale x overlap) is one point's at the fixed centre
        // distance while both closest points are corners, and moves smoothly beyond.
        double force = 0.0;
        for (std::uint32_t i = 0; i < m.count; ++i) force += m.stiffness_scale * m.points[i].overlap_m;
        if (t >= 0.0 && t <= 3.14159265358979323846 / 2.0) EXPECT_NEAR(force, 1e-4, 1e-12) << t;
        if (k > 0) largest_force_jump = std::max(largest_force_jump, std::abs(force - previous_force));
        previous_force = force;
    }
    // The step turns the centre line by (pi/2 + 0.6) / 20000 = 1.1e-4 rad; the normal follows.
    EXPECT_LT(largest_turn, 1.2e-4);
    // A step changes the force by at most 1e-6 (the overlap's slope beside the corner, and the
    // softening ramp); a jump where the regimes meet would be of the order of the force, 1e-4.
    EXPECT_LT(largest_force_jump, 2e-6);
}

TEST(RoundedContact, SlidingOffAFaceHandsOverToOneCornerPointContinuously) {
    // Parallel faces: b slides right along a's top face and off its corner. While the faces
    // overlap there are two points; as their span closes the pair softens to one point's
    // stiffness, which is what the corner-to-corner point that follows carries.
    const Poly a = box(1.0, 1.0, {0.0, 0.0});
    const double overlap = 1e-4;
    double last_stiffness = -1.0;
    double largest_jump = 0.0;
    std::uint32_t reference = no_reference;
    for (int k = 0; k <= 2000; ++k) {
        const double shift = 0.95 + 0.04 * k / 2000.0;  // b's left core corner passes a's at shift = 0.98
        const Poly b = box(1.0, 1.0, {shift, 1.0 - overlap});
        ContactManifold m;
        if (!collide(a, b, m, reference)) break;
        reference = m.reference;
        double stiffness_times_overlap = 0.0;  // kn = 1: the pair's normal force
        for (std::uint32_t i = 0; i < m.count; ++i) stiffness_times_overlap += m.stiffness_scale * m.points[i].overlap_m;
        if (last_stiffness >= 0.0) largest_jump = std::max(largest_jump, std::abs(stiffness_times_overlap - last_stiffness));
        last_stiffness = stiffness_times_overlap;
    }
    // Steps of 20 um: the softening ramp changes the force by 2e-7 a step, the arcs' curvature
    // by up to 2e-6 (overlap 2r - sqrt(x^2 + (2r - 1e-4)^2) past the corner); the sharp model's
    // softening to zero would jump by one point's force, 1e-4, at the hand-over.
    EXPECT_LT(largest_jump, 4e-6);
}

TEST(RoundedContact, SeparatingEdgeCachedForPairsApart) {
    const Poly a = box(1.0, 1.0, {0.0, 0.0});
    const Poly b = box(1.0, 1.0, {2.0, 0.0});
    ContactManifold m;
    AxisCache cache;
    EXPECT_FALSE(collide_rounded(a.view(), b.view(), r, no_reference, m, cache));
    ASSERT_NE(cache.separating, no_reference);
    // The drawn polygons are apart along it too (the narrow phase tests it on them).
    EXPECT_TRUE(separated_by_cached_edge(a.view(), b.view(), cache));
}

TEST(RoundedContact, AxisCacheGivesTheFullTestsResultBitForBit) {
    // A block rocking and sliding on a table, and then tipping onto its corner arc: at each pose
    // the contact with the cache kept from step to step (drift and turn added as the narrow
    // phase does) equals the contact found by the full test, bit for bit.
    const Poly table = box(4.0, 0.2, {0.0, -0.1});
    AxisCache cache;
    std::uint32_t reference_cached = no_reference, reference_full = no_reference;
    Vec2 last_centre{};
    double last_angle = 0.0;
    int cached_steps = 0;
    for (int k = 0; k <= 30000; ++k) {
        const double angle = 0.3 * std::sin(0.0002 * k) * std::sin(0.0002 * k);  // to 0.27 rad and back
        const Vec2 centre{0.1 * std::sin(0.0003 * k), 0.0};
        // The rounded block's lowest point (r below its core's, the core being the rectangle
        // 2r smaller) 0.1 mm into the table.
        double lowest = INFINITY;
        for (Vec2 v : rectangle_vertices(0.5 - 2.0 * r, 0.2 - 2.0 * r, centre, angle)) lowest = std::min(lowest, v.y - r);
        const Poly block = box(0.5, 0.2, centre - Vec2{0.0, lowest + 1e-4}, angle);
        if (k > 0) {
            // (Lever: the distance between the centres plus both bounding radii, as the narrow phase.)
            cache.drift_m += norm_bound(centre - last_centre) + std::abs(angle - last_angle) * 2.5 + 1e-12;
            cache.turn_rad += std::abs(angle - last_angle) + 1e-15;
        }
        last_centre = centre;
        last_angle = angle;
        const bool usable = cache.others_max_separation_m < INFINITY;
        ContactManifold with_cache, full;
        AxisCache fresh;
        const bool touch_cached = collide_rounded(table.view(), block.view(), r, reference_cached, with_cache, cache);
        const bool touch_full = collide_rounded(table.view(), block.view(), r, reference_full, full, fresh);
        if (usable && cache.others_max_separation_m < INFINITY && cache.drift_m > 0.0) ++cached_steps;
        ASSERT_TRUE(touch_full) << k;
        ASSERT_EQ(touch_cached, touch_full) << k;
        ASSERT_EQ(with_cache.count, full.count) << k;
        EXPECT_EQ(with_cache.reference, full.reference) << k;
        EXPECT_EQ(with_cache.stiffness_scale, full.stiffness_scale) << k;
        for (std::uint32_t i = 0; i < full.count; ++i) {
            EXPECT_EQ(with_cache.points[i].overlap_m, full.points[i].overlap_m) << k;
            EXPECT_EQ(with_cache.points[i].point_m, full.points[i].point_m) << k;
            EXPECT_EQ(with_cache.points[i].feature, full.points[i].feature) << k;
        }
        reference_cached = with_cache.count > 0 ? with_cache.reference : no_reference;
        reference_full = full.count > 0 ? full.reference : no_reference;
    }
    EXPECT_GT(cached_steps, 20000);  // the cache did serve most steps
}

TEST(RoundedContact, CornerOffsetsGivenWithThePolygonGiveTheSameBits) {
    // The narrow phase hands collide_rounded the corners' core offsets that the body geometry made
    // once a step (world/step.cpp, PolygonView::corner_offsets_m): the contact, the cache and the
    // reference must be those made without them, bit for bit, in face contacts (resting, tilted,
    // opening within a gap), corner contacts and pairs apart; and the offsets given are read.
    auto offsets_of = [](const Poly& p, double rounding_m) {
        std::vector<Vec2> o;
        const std::size_t n = p.n.size();
        for (std::size_t i = 0; i < n; ++i) o.push_back(rounded_corner_offset(p.n[(i + n - 1) % n], p.n[i], rounding_m));
        return o;
    };
    const Poly table = box(4.0, 0.2, {0.0, -0.1});
    int touching = 0, apart = 0;
    for (int k = 0; k < 400; ++k) {
        const double angle = 0.8 * std::sin(0.05 * k);
        // Its drawn lowest corner from 4 mm into the table to 0.8 mm above it (the arc of a
        // tilted corner lies up to r (sqrt 2 - 1) = 4 mm above the drawn corner).
        const double lowest_m = 0.25 * std::abs(std::sin(angle)) + 0.1 * std::cos(angle);
        const Poly block = box(0.5, 0.2, {0.002 * k - 0.4, lowest_m - 0.004 + 0.0008 * (k % 7)}, angle);
        const std::vector<Vec2> oa = offsets_of(table, r), ob = offsets_of(block, r);
        PolygonView va = table.view(), vb = block.view();
        va.corner_offsets_m = oa.data();
        vb.corner_offsets_m = ob.data();
        for (const double gap_m : {0.0, 0.003}) {
            ContactManifold made, given;
            AxisCache cache_made, cache_given;
            const bool touch_made = collide_rounded(table.view(), block.view(), r, no_reference, made, cache_made, gap_m);
            const bool touch_given = collide_rounded(va, vb, r, no_reference, given, cache_given, gap_m);
            ASSERT_EQ(touch_made, touch_given) << k;
            (touch_made ? touching : apart) += 1;
            ASSERT_EQ(made.count, given.count) << k;
            EXPECT_EQ(made.normal, given.normal) << k;
            EXPECT_EQ(made.reference, given.reference) << k;
            EXPECT_EQ(made.stiffness_scale, given.stiffness_scale) << k;
            for (std::uint32_t i = 0; i < made.count; ++i) {
                EXPECT_EQ(made.points[i].overlap_m, given.points[i].overlap_m) << k;
                EXPECT_EQ(made.points[i].point_m, given.points[i].point_m) << k;
                EXPECT_EQ(made.points[i].feature, given.points[i].feature) << k;
            }
            EXPECT_EQ(cache_made.separating, cache_given.separating) << k;
            EXPECT_EQ(cache_made.incident, cache_given.incident) << k;
            EXPECT_EQ(cache_made.others_max_separation_m, cache_given.others_max_separation_m) << k;
            // The cached path (last step's reference kept) reads the given offsets too.
            if (touch_made) {
                ContactManifold again_made, again_given;
                collide_rounded(table.view(), block.view(), r, made.reference, again_made, cache_made, gap_m);
                collide_rounded(va, vb, r, given.reference, again_given, cache_given, gap_m);
                ASSERT_EQ(again_made.count, again_given.count) << k;
                for (std::uint32_t i = 0; i < again_made.count; ++i)
                    EXPECT_EQ(again_made.points[i].overlap_m, again_given.points[i].overlap_m) << k;
            }
        }
    }
    EXPECT_GT(touching, 300);  // the poses cover both
    EXPECT_GT(apart, 50);
    // Offsets given are what the contact is made of: those of a rounding half as large, with r
    // unchanged, move a resting face contact's overlap.
    const Poly block = box(0.5, 0.2, {0.3, 0.1 - 1e-4});
    const std::vector<Vec2> oa = offsets_of(table, 0.5 * r), ob = offsets_of(block, 0.5 * r);
    PolygonView va = table.view(), vb = block.view();
    va.corner_offsets_m = oa.data();
    vb.corner_offsets_m = ob.data();
    ContactManifold made, given;
    AxisCache cache_made, cache_given;
    ASSERT_TRUE(collide_rounded(table.view(), block.view(), r, no_reference, made, cache_made));
    collide_rounded(va, vb, r, no_reference, given, cache_given);
    EXPECT_TRUE(given.count == 0 || given.points[0].overlap_m != made.points[0].overlap_m);
}

TEST(RoundedContact, RefusesARoundingTooLargeForTheBody) {
    const Poly brick = box(0.4, 0.1, {0.0, 0.0});
    EXPECT_FALSE(rounding_problem(brick.v, brick.n, 0.1, 0.0).has_value());
    EXPECT_FALSE(rounding_problem(brick.v, brick.n, 0.1, 0.0249).has_value());
    const auto too_large = rounding_problem(brick.v, brick.n, 0.1, 0.025);
    ASSERT_TRUE(too_large.has_value());
    EXPECT_NE(too_large->find("[contact] rounding"), std::string::npos) << *too_large;
    // A sliver's sharp corner: arcs that fit the width would eat its short edge.
    const Poly sliver({{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.4}, {0.99, 0.4}});
    const auto eaten = rounding_problem(sliver.v, sliver.n, least_width(sliver.v), 0.02);
    ASSERT_TRUE(eaten.has_value());
    EXPECT_NE(eaten->find("removes edge 2"), std::string::npos) << *eaten;
}

}  // namespace
}  // namespace blockdem
