// The stiffness shares of a clipped overlap polygon's corners (geometry/corner_share_3d.hpp) against
// hand-worked turns, and on the narrow phase's manifold of two flush bricks
// (geometry/polyhedron_contact_3d.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "contact/contact_table_3d.hpp"
#include "geometry/box_frame_3d.hpp"
#include "geometry/corner_share_3d.hpp"
#include "geometry/polyhedron_contact_3d.hpp"

namespace blockdem {
namespace {

std::vector<double> shares_of(const std::vector<Vec3>& corners) {
    std::vector<double> shares(corners.size(), -1.0);
    corner_shares_3d(corners.data(), corners.size(), shares.data());
    return shares;
}

double sum(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s;
}

// A point of the plane spanned by u and v through origin (u, v orthonormal).
Vec3 in_plane(Vec3 origin, Vec3 u, Vec3 v, double x, double y) { return origin + x * u + y * v; }

TEST(CornerShare3d, RectangleInAnyPlaneWeighsOneACorner) {
    // A 0.2 x 0.1 m rectangle in a tilted plane far from the origin, both ways round.
    const Vec3 u = normalized(Vec3{1, 2, 0.5});
    const Vec3 v = normalized(cross(Vec3{0.3, -0.2, 1}, u));
    const Vec3 o{100, -50, 7};
    std::vector<Vec3> r{in_plane(o, u, v, 0, 0), in_plane(o, u, v, 0.2, 0), in_plane(o, u, v, 0.2, 0.1),
                        in_plane(o, u, v, 0, 0.1)};
    for (double s : shares_of(r)) EXPECT_NEAR(s, 1.0, 1e-12);
    std::reverse(r.begin(), r.end());
    for (double s : shares_of(r)) EXPECT_NEAR(s, 1.0, 1e-12);
}

TEST(CornerShare3d, RegularPolygonsShareFourEqually) {
    for (int n : {3, 6, 32}) {
        std::vector<Vec3> p;
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * std::numbers::pi * k / n;
            p.push_back({0.3 * std::cos(a), 0.3 * std::sin(a), 1.0});
        }
        for (double s : shares_of(p)) EXPECT_NEAR(s, 4.0 / n, 1e-12);  // turn 2 pi / n over pi / 2
    }
}

TEST(CornerShare3d, ACornerCutInTwoSplitsItsWeightContinuously) {
    // The rectangle's corner (0.2, 0.1) cut off by a line at theta to the top side: the cut's corner
    // on the top side turns by theta, the one on the right side by pi/2 - theta. theta = 1e-7 rad is
    // the flush bricks' case: the nearly straight corner weighs 6.4e-8, not 1.
    for (double theta : {1e-7, 0.3, 1.2}) {
        for (double a : {1e-3, 1e-6}) {  // how far the cut reaches along the top side [m]
            const std::vector<Vec3> p{{0, 0, 0}, {0.2, 0, 0}, {0.2, 0.1 - a * std::tan(theta), 0}, {0.2 - a, 0.1, 0},
                                      {0, 0.1, 0}};
            const std::vector<double> s = shares_of(p);
            EXPECT_NEAR(s[2], 1.0 - theta / (0.5 * std::numbers::pi), 1e-9);
            EXPECT_NEAR(s[3], theta / (0.5 * std::numbers::pi), 1e-9);
            EXPECT_NEAR(s[2] + s[3], 1.0, 1e-12);  // the uncut corner's weight, however small the cut
            EXPECT_NEAR(sum(s), 4.0, 1e-12);
        }
    }
}

TEST(CornerShare3d, CoincidentCornersShareTheirTurnAndDegenerateShapesKeepTheSum) {
    // A corner listed twice (a reference corner found from both its sides): half each.
    const std::vector<Vec3> doubled{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<double> s = shares_of(doubled);
    EXPECT_NEAR(s[1], 0.5, 1e-12);
    EXPECT_NEAR(s[2], 0.5, 1e-12);
    EXPECT_NEAR(sum(s), 4.0, 1e-12);
    // Nearly coincident (1e-12 m apart, below 1e-9 of the longest side): the same.
    const std::vector<Vec3> near{{0, 0, 0}, {1, 0, 0}, {1, 1e-12, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_NEAR(shares_of(near)[1], 0.5, 1e-12);
    // A segment's two ends turn by pi; one point is the whole turn.
    for (double x : shares_of({{0, 0, 0}, {1, 0, 0}})) EXPECT_NEAR(x, 2.0, 1e-12);
    EXPECT_NEAR(shares_of({{1, 2, 3}})[0], 4.0, 0.0);
    for (double x : shares_of({{1, 2, 3}, {1, 2, 3}})) EXPECT_NEAR(x, 2.0, 0.0);
}

TEST(CornerShare3d, TurnsNearAQuarterOrNearStraightAgreeWithTheArctangentToRoundOff) {
    // The turn at corner 1 of the triangle (0,0,0), (1,0,0), (1,0,0) + (cos t, sin t, 0) is t. Near a
    // quarter and near zero the shares take the arctangent's series; elsewhere atan2. Either way the
    // share is atan2(|a x b|, a . b) / (pi / 2) of the same sides to within two units in the last
    // place (4.5e-16 for shares below 2), over ratios from 1e-14 to beyond the series' 1e-3.
    for (double offset : {0.0, 1e-14, 1e-9, 3e-7, 1e-4, 9.99e-4, 1.001e-3, 0.01, 0.3}) {
        for (double t : {0.5 * std::numbers::pi + offset, 0.5 * std::numbers::pi - offset, offset}) {
            if (t <= 0.0) continue;
            const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, Vec3{1, 0, 0} + Vec3{std::cos(t), std::sin(t), 0}};
            const Vec3 a = p[1] - p[0];
            const Vec3 b = p[2] - p[1];
            const double expected = std::atan2(length(cross(a, b)), dot(a, b)) / (0.5 * std::numbers::pi);
            EXPECT_NEAR(shares_of(p)[1], expected, 4.5e-16) << "turn " << t;
        }
    }
}

TEST(CornerShare3d, CornersKnownToBeRightAnglesWeighExactlyOne) {
    // A rectangle turned in space: measured, its corners weigh 1 to round-off; marked as a box
    // face's own corners, exactly 1. A corner cut off keeps its measured turns; the marked ones stay 1.
    const Vec3 u = normalized(Vec3{1, 2, 0.5});
    const Vec3 v = normalized(cross(Vec3{0.3, -0.2, 1}, u));
    const Vec3 o{3, -5, 7};
    const std::vector<Vec3> cut{in_plane(o, u, v, 0, 0), in_plane(o, u, v, 0.2, 0), in_plane(o, u, v, 0.2, 0.07),
                                in_plane(o, u, v, 0.15, 0.1), in_plane(o, u, v, 0, 0.1)};
    const std::uint8_t kept[5] = {1, 1, 0, 0, 1};
    std::vector<double> s(cut.size());
    corner_shares_3d(cut.data(), cut.size(), s.data(), kept);
    EXPECT_EQ(s[0], 1.0);
    EXPECT_EQ(s[1], 1.0);
    EXPECT_EQ(s[4], 1.0);
    const std::vector<double> measured = shares_of(cut);
    EXPECT_EQ(s[2], measured[2]);
    // The last corner not marked takes what the others leave of 4 (branch clip1p): its measured
    // turn to round-off, sums of five shares near 1 (a few 1e-16).
    EXPECT_NEAR(s[3], measured[3], 1e-14);
    EXPECT_NEAR(sum(s), 4.0, 1e-12);
    // With a short side (two corners 1e-12 m apart) the groups need every turn: the marks are not used.
    const std::vector<Vec3> doubled{{0, 0, 0}, {1, 0, 0}, {1, 1e-12, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::uint8_t all[5] = {1, 1, 1, 1, 1};
    std::vector<double> d(doubled.size());
    corner_shares_3d(doubled.data(), doubled.size(), d.data(), all);
    EXPECT_NEAR(d[1], 0.5, 1e-12);
    EXPECT_NEAR(d[2], 0.5, 1e-12);
}

// A box of the given size centred at c, turned by angle about the vertical through c.
std::vector<Vec3> turned_box(Vec3 size, Vec3 c, double angle_rad) {
    std::vector<Vec3> v = box_vertices(size, {});
    for (Vec3& p : v)
        p = c + Vec3{std::cos(angle_rad) * p.x - std::sin(angle_rad) * p.y,
                     std::sin(angle_rad) * p.x + std::cos(angle_rad) * p.y, p.z};
    return v;
}

struct Posed {
    Polyhedron shape;
    PolyhedronEdges edges;
    Vec3 centroid;
    Posed(const std::vector<Vec3>& vertices, Vec3 c)
        : shape(convex_polyhedron(vertices)), edges(polyhedron_edges(shape)), centroid(c) {}
    PosedPolyhedron view() const {
        return {&shape, &edges, shape.vertices_m.data(), shape.face_normals.data(), edges.directions.data(), &centroid};
    }
};

TEST(CornerShare3d, FlushBricksCutAlongTheirSidesGiveNearlyWeightlessCuts) {
    // Two 0.2 x 0.1 x 0.1 m bricks of equal width, the upper shifted 0.05 m along x, sunk 1e-5 m and
    // turned 1e-7 rad about the vertical: each long edge of its bottom face crosses the lower top
    // face's side plane near its middle, so the clipped polygon has 6 corners. The two cuts weigh
    // about 1e-7 / (pi/2); the four others about 1; the sum is 4 (a full kn each made it 6).
    const Posed lower(turned_box({0.2, 0.1, 0.1}, {0, 0, 0}, 0.0), {0, 0, 0});
    const Posed upper(turned_box({0.2, 0.1, 0.1}, {0.05, 0, 0.1 - 1e-5}, 1e-7), {0.05, 0, 0.1 - 1e-5});
    ContactScratch3d scratch;
    std::vector<ContactGeometry3d> points;
    polyhedron_contact_3d(lower.view(), upper.view(), scratch, points);
    ASSERT_EQ(points.size(), 6u);
    double total = 0.0;
    int cuts = 0;
    for (const ContactGeometry3d& p : points) {
        total += p.stiffness_share;
        if (p.stiffness_share < 1e-6) {
            ++cuts;
            EXPECT_NEAR(p.stiffness_share, 1e-7 / (0.5 * std::numbers::pi), 1e-9);
        } else {
            EXPECT_NEAR(p.stiffness_share, 1.0, 1e-6);
        }
    }
    EXPECT_EQ(cuts, 2);
    EXPECT_NEAR(total, 4.0, 1e-12);
}

// A box about its centroid (as a body's shape is held), turned by the rotation vector turn and
// moved to c, with its box frame: the narrow phase's box paths.
struct PosedBox {
    Polyhedron shape;
    PolyhedronEdges edges;
    BoxFrame3d frame;
    std::vector<Vec3> vertices, normals, directions;
    Vec3 centre;
    PosedBox(Vec3 size_m, Vec3 c, Vec3 turn_rad)
        : shape(convex_polyhedron(box_vertices(size_m, {}))), edges(polyhedron_edges(shape)),
          frame(box_frame(shape, edges)), centre(c) {
        const Quaternion q = from_rotation_vector(turn_rad);
        for (const Vec3& v : shape.vertices_m) vertices.push_back(c + rotate(q, v));
        for (const Vec3& n : shape.face_normals) normals.push_back(rotate(q, n));
        for (const Vec3& d : edges.directions) directions.push_back(rotate(q, d));
    }
    PosedPolyhedron view() const {
        return {&shape, &edges, vertices.data(), normals.data(), directions.data(), &centre, &frame};
    }
};

TEST(CornerShare3d, ABoxFacesKeptCornersWeighExactlyOne) {
    // A brick half over the edge of a slab (2 x 1 x 0.5 m), sunk 1e-3 m and tilted 1e-3 rad: the
    // slab's top face is the reference, its side x = 1 cuts the brick's bottom face. The brick's two
    // kept corners weigh exactly 1 (a box face's right angles, not measured); the two cuts, measured,
    // add to 2 (a line across two parallel edges turns by t and pi - t) to round-off.
    for (const Vec3 tilt : {Vec3{1e-3, 0, 0}, Vec3{1e-3, 2e-4, 0}, Vec3{-3e-4, -2e-4, 0}}) {
        SCOPED_TRACE(testing::Message() << "tilt " << tilt.x << " " << tilt.y << " " << tilt.z);
        const PosedBox slab({2.0, 1.0, 0.5}, {0, 0, -0.25}, {});
        const PosedBox brick({0.2, 0.1, 0.1}, {1.0, 0, 0.05 - 1e-3}, tilt);
        ASSERT_TRUE(slab.frame.is_box && brick.frame.is_box);
        ContactScratch3d scratch;
        std::vector<ContactGeometry3d> points;
        polyhedron_contact_3d(slab.view(), brick.view(), scratch, points);
        int kept = 0, cut = 0;
        double cuts = 0.0;
        for (const ContactGeometry3d& p : points) {
            if (feature_kind(p.feature_b) == FeatureKind3d::vertex) {
                ++kept;
                EXPECT_EQ(feature_kind(p.feature_a), FeatureKind3d::face);  // the slab's top face is the reference
                EXPECT_EQ(p.stiffness_share, 1.0);
            } else {
                ++cut;
                cuts += p.stiffness_share;
            }
        }
        EXPECT_EQ(kept, 2);
        EXPECT_EQ(cut, 2);
        EXPECT_NEAR(cuts, 2.0, 1e-12);
    }
}

TEST(CornerShare3d, AKeptPointsShearSpringKeepsItsDisplacementWhenItsShareChanges) {
    // The spring carried is the displacement times w ks: a share going from 1 to 0.25 carries a
    // quarter of the force; from 0 (no stiffness, nothing stored) it starts at zero; the dashpot's
    // last force (the trapezoid's end, not a state of the spring) is carried as it was.
    ContactPoint3d before;
    before.key = {0, 1, 5, 7};
    before.stiffness_share = 1.0;
    before.shear = {{2.0, -1.0, 0.0}, {0.5, 0.0, 0.0}};
    std::vector<ContactPoint3d> previous{before};
    std::vector<ContactPoint3d> current(1);
    current[0].key = before.key;
    current[0].stiffness_share = 0.25;
    carry_history(previous, current);
    EXPECT_EQ(current[0].shear.spring_n, (Vec3{0.5, -0.25, 0.0}));
    EXPECT_EQ(current[0].shear.dashpot_n, (Vec3{0.5, 0.0, 0.0}));
    previous[0].stiffness_share = 0.0;
    current[0] = {};
    current[0].key = before.key;
    current[0].stiffness_share = 1.0;
    carry_history(previous, current);
    EXPECT_EQ(current[0].shear.spring_n, (Vec3{}));
}

}  // namespace
}  // namespace blockdem
