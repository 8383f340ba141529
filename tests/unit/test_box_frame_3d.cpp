// The box-box separating-axis test (geometry/box_frame_3d.hpp, geometry/polyhedron_contact_3d.cpp)
// against the general vertex test it replaces for two boxes: the same points with the same keys,
// overlaps and normals to round-off, over random poses near contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "geometry/box_frame_3d.hpp"
#include "geometry/polyhedron_contact_3d.hpp"

namespace blockdem {
namespace {

// A shape about its centroid, turned by q and moved to c, as the world poses it.
struct PosedBox {
    Polyhedron shape;
    PolyhedronEdges edges;
    BoxFrame3d frame;
    std::vector<Vec3> vertices, normals, directions;
    Vec3 centre;
    PosedBox(const std::vector<Vec3>& body_vertices, Quaternion q, Vec3 c)
        : shape(convex_polyhedron(body_vertices)), edges(polyhedron_edges(shape)), frame(box_frame(shape, edges)),
          centre(c) {
        for (const Vec3& v : shape.vertices_m) vertices.push_back(c + rotate(q, v));
        for (const Vec3& n : shape.face_normals) normals.push_back(rotate(q, n));
        for (const Vec3& d : edges.directions) directions.push_back(rotate(q, d));
    }
    PosedPolyhedron view(bool as_box) const {
        return {&shape, &edges, vertices.data(), normals.data(), directions.data(), &centre, as_box ? &frame : nullptr};
    }
};

TEST(BoxFrame3d, RecognisesBoxesAndOnlyBoxes) {
    const auto frame_of = [](const std::vector<Vec3>& v) {
        const Polyhedron p = convex_polyhedron(v);
        return box_frame(p, polyhedron_edges(p));
    };
    const BoxFrame3d brick = frame_of(box_vertices({0.2, 0.1, 0.05}, {}));
    ASSERT_TRUE(brick.is_box);
    EXPECT_DOUBLE_EQ(brick.half_lengths_m.x + brick.half_lengths_m.y + brick.half_lengths_m.z, 0.175);
    // Turned about its centre: still a box (the directions are the turned axes).
    EXPECT_TRUE(frame_of(box_vertices({0.2, 0.1, 0.05}, {}, from_rotation_vector({0.3, -0.2, 0.7}))).is_box);
    // Not about the origin, sheared, or not six-faced: the general test.
    EXPECT_FALSE(frame_of(box_vertices({0.2, 0.1, 0.05}, {1.0, 0.0, 0.0})).is_box);
    EXPECT_FALSE(frame_of({{-1, -1, -1}, {1, -1, -1}, {-0.5, 1, -1}, {1.5, 1, -1}, {-1, -1, 1}, {1, -1, 1},
                           {-0.5, 1, 1}, {1.5, 1, 1}})
                     .is_box);
    EXPECT_FALSE(frame_of(prism_vertices({{1, 0}, {0, 1}, {-1, 0}, {0, -1.2}, {0.5, -0.9}}, 1.0)).is_box);
}

TEST(BoxFrame3d, TurnedNormalsAreTheTurnedDirectionsToTheBit) {
    // The pose takes a box's turned face normals from its turned directions when the body-frame
    // normals are exactly +/- the directions (world/step_3d.cpp): the same bits as turning them.
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const Polyhedron brick = convex_polyhedron(box_vertices({0.2, 0.1, 0.1}, {}));
    const PolyhedronEdges edges = polyhedron_edges(brick);
    const BoxFrame3d frame = box_frame(brick, edges);
    ASSERT_TRUE(frame.is_box);
    ASSERT_TRUE(frame.normals_are_directions);
    for (int trial = 0; trial < 1000; ++trial) {
        const Quaternion q = from_rotation_vector({u(random), u(random), u(random)});
        for (std::size_t f = 0; f < 6; ++f) {
            const Vec3 turned = rotate(q, brick.face_normals[f]);
            const Vec3 from_direction = frame.face_sign[f] * rotate(q, edges.directions[frame.face_direction[f]]);
            ASSERT_TRUE(turned == from_direction) << "trial " << trial << " face " << f;
        }
    }
    // A box turned in its own body frame has normals that are its directions only to round-off:
    // the flag is then false and the pose turns the normals.
    const Polyhedron turned_box =
        convex_polyhedron(box_vertices({0.2, 0.1, 0.05}, {}, from_rotation_vector({0.3, -0.2, 0.7})));
    const PolyhedronEdges turned_edges = polyhedron_edges(turned_box);
    const BoxFrame3d turned_frame = box_frame(turned_box, turned_edges);
    ASSERT_TRUE(turned_frame.is_box);
    bool exact = true;
    for (std::size_t f = 0; f < 6; ++f)
        exact = exact && turned_box.face_normals[f] ==
                             turned_frame.face_sign[f] * turned_edges.directions[turned_frame.face_direction[f]];
    EXPECT_EQ(turned_frame.normals_are_directions, exact);
}

// The corners listed backwards: each edge direction (from the lower vertex number to the higher,
// geometry/polyhedron_edges_3d.hpp) turns over, so the three directions make a left-handed set, as
// a `polyhedron` or a rock block's corners listed in any order may.
std::vector<Vec3> listed_backwards(std::vector<Vec3> v) {
    std::reverse(v.begin(), v.end());
    return v;
}

// d0 . (d1 x d2) of a box's three edge directions: +1 right-handed, -1 left-handed.
double handedness(const std::vector<Vec3>& body_vertices) {
    const PolyhedronEdges e = polyhedron_edges(convex_polyhedron(body_vertices));
    return dot(e.directions[0], cross(e.directions[1], e.directions[2]));
}

// The box-box test against the general one over random poses, a's and b's corners listed as given.
void expect_general_points_over_random_poses(bool a_backwards, bool b_backwards) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3> brick_b = box_vertices({0.2, 0.1, 0.1}, {});
    std::vector<Vec3> brick = brick_b;
    std::vector<Vec3> slab = box_vertices({2.0, 1.0, 0.5}, {});
    if (a_backwards) {
        brick = listed_backwards(brick);
        slab = listed_backwards(slab);
    }
    if (b_backwards) brick_b = listed_backwards(brick_b);
    ASSERT_NEAR(handedness(brick), a_backwards ? -1.0 : 1.0, 1e-12);
    ASSERT_NEAR(handedness(slab), a_backwards ? -1.0 : 1.0, 1e-12);
    ASSERT_NEAR(handedness(brick_b), b_backwards ? -1.0 : 1.0, 1e-12);
    int touching = 0, apart = 0, edge_on_edge = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        // A brick on a brick or on the slab, small turns (resting, rocking) and larger ones.
        const double turn = trial % 2 == 0 ? 0.02 : 0.6;
        const bool on_slab = trial % 3 == 0;
        const Quaternion qa = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const Quaternion qb = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const double gap = on_slab ? 0.3 : 0.1;
        const PosedBox a(on_slab ? slab : brick, qa, {0.0, 0.0, 0.0});
        const PosedBox b(brick_b, qb, {0.1 * u(random), 0.05 * u(random), gap + 0.01 * u(random)});
        ASSERT_TRUE(a.frame.is_box && b.frame.is_box);
        ContactScratch3d scratch;
        std::vector<ContactGeometry3d> general, boxes;
        polyhedron_contact_3d(a.view(false), b.view(false), scratch, general);
        polyhedron_contact_3d(a.view(true), b.view(true), scratch, boxes);
        ASSERT_EQ(general.size(), boxes.size()) << "trial " << trial;
        (general.empty() ? apart : touching) += 1;
        // One point keyed (edge, edge): an edge axis was taken (a clip gives at least three).
        if (boxes.size() == 1 && feature_kind(boxes[0].feature_a) == FeatureKind3d::edge &&
            feature_kind(boxes[0].feature_b) == FeatureKind3d::edge)
            ++edge_on_edge;
        for (std::size_t k = 0; k < general.size(); ++k) {
            EXPECT_EQ(general[k].feature_a, boxes[k].feature_a);
            EXPECT_EQ(general[k].feature_b, boxes[k].feature_b);
            // Round-off of sums of products of lengths below 2 m.
            EXPECT_NEAR(general[k].overlap_m, boxes[k].overlap_m, 1e-14);
            EXPECT_NEAR(length(general[k].normal - boxes[k].normal), 0.0, 1e-14);
            EXPECT_NEAR(length(general[k].point_m - boxes[k].point_m), 0.0, 1e-14);
        }
    }
    // Both outcomes are exercised, and the edge axes (whose root is taken only when one can win).
    EXPECT_GT(touching, 500);
    EXPECT_GT(apart, 200);
    EXPECT_GT(edge_on_edge, 20);
}

TEST(BoxFrame3d, BoxBoxTestGivesTheGeneralTestsPointsToRoundOff) { expect_general_points_over_random_poses(false, false); }

// The edge axes' sign comes from the world, not from the directions' handedness: a box whose
// corners are listed in another order takes the same points (an edge-on-edge normal pointing
// from b to a would drop the point or hand it to a face).
TEST(BoxFrame3d, BoxBoxTestIsTheGeneralTestForLeftHandedBoxes) {
    expect_general_points_over_random_poses(true, false);
    expect_general_points_over_random_poses(false, true);
    expect_general_points_over_random_poses(true, true);
}

TEST(BoxFrame3d, FacesAlongEachDirectionAreFoundBothWays) {
    // face_of inverts face_direction and face_sign: the box-box test picks a face per direction.
    const Polyhedron brick = convex_polyhedron(box_vertices({0.2, 0.1, 0.05}, {}, from_rotation_vector({0.3, -0.2, 0.7})));
    const BoxFrame3d frame = box_frame(brick, polyhedron_edges(brick));
    ASSERT_TRUE(frame.is_box);
    for (int i = 0; i < 3; ++i) {
        for (int side = 0; side < 2; ++side) {
            const std::uint8_t f = frame.face_of[i][side];
            EXPECT_EQ(frame.face_direction[f], i);
            EXPECT_EQ(frame.face_sign[f], side == 0 ? 1.0 : -1.0);
        }
    }
}

TEST(BoxFrame3d, BoxBoxTestBreaksExactTiesAsTheGeneralTest) {
    // Aligned bricks (the dots exactly 0 or 1): the centres' offset is exactly 0 along a direction
    // when a brick sits centred, and every off-axis dot is 0, so two faces separate exactly as much
    // and two incident faces are exactly as opposed. The box test's choice per direction must be
    // the general loop's (the lower face number): the same points and keys, the overlaps to the bit
    // (both clips cut at the same coordinates here), the shares to round-off: the general test
    // measures a box corner's right angle, the box test knows it, and a cut 1e-6 m from a corner
    // leaves a side whose direction carries 1e-16 m / 1e-6 m = 1e-10 rad of round-off (9e-13 seen).
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    int pairs = 0;
    for (double x_m : {0.0, 0.05, -0.1, 0.2 - 1e-6}) {
        for (double y_m : {0.0, 0.02, -0.1 + 1e-6}) {
            for (double z_m : {0.1 - 1e-6, -0.1 + 1e-5, 0.0}) {
                const PosedBox a(brick, Quaternion{}, {0.0, 0.0, 0.0});
                const PosedBox b(brick, Quaternion{}, {x_m, y_m, z_m});
                ContactScratch3d scratch;
                std::vector<ContactGeometry3d> general, boxes;
                polyhedron_contact_3d(a.view(false), b.view(false), scratch, general);
                polyhedron_contact_3d(a.view(true), b.view(true), scratch, boxes);
                ASSERT_EQ(general.size(), boxes.size()) << x_m << " " << y_m << " " << z_m;
                for (std::size_t k = 0; k < general.size(); ++k) {
                    EXPECT_EQ(general[k].feature_a, boxes[k].feature_a);
                    EXPECT_EQ(general[k].feature_b, boxes[k].feature_b);
                    EXPECT_EQ(general[k].overlap_m, boxes[k].overlap_m);
                    EXPECT_NEAR(general[k].stiffness_share, boxes[k].stiffness_share, 1e-10);
                }
                pairs += general.empty() ? 0 : 1;
            }
        }
    }
    EXPECT_GT(pairs, 20);
}

TEST(BoxFrame3d, NearlyAlignedBoxesGiveTheGeneralTestsPoints) {
    // A wall's case: b turned from a by 1e-13 to 1e-2 rad (the dots' diagonal within that of 1),
    // resting on a or beside it with overlaps from 1e-9 to 1e-4 m, and faces touching to round-off.
    // Here the box test skips b's faces and the six crossed edge axes where a bound shows none can
    // win; where the tilt is large against the overlap an edge axis does win (edge on edge), and the
    // bound must leave those pairs to the full test. The same points, keys and overlaps as the
    // general test.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_real_distribution<double> decade(0.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    int touching = 0, edge_on_edge = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double turn = std::pow(10.0, -13.0 + 11.0 * decade(random));  // [rad]
        const double overlap_m = trial % 5 == 0 ? 0.0 : std::pow(10.0, -9.0 + 5.0 * decade(random));
        const Quaternion qb = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const PosedBox a(brick, Quaternion{}, {0.0, 0.0, 0.0});
        // On top (along z), or beside (along x), half a brick along the other axis as in a bond.
        const bool on_top = trial % 2 == 0;
        const Vec3 centre = on_top ? Vec3{0.1 * u(random), 0.02 * u(random), 0.1 - overlap_m}
                                   : Vec3{0.2 - overlap_m, 0.02 * u(random), 0.05 * u(random)};
        const PosedBox b(brick, qb, centre);
        ContactScratch3d scratch;
        std::vector<ContactGeometry3d> general, boxes;
        polyhedron_contact_3d(a.view(false), b.view(false), scratch, general);
        polyhedron_contact_3d(a.view(true), b.view(true), scratch, boxes);
        ASSERT_EQ(general.size(), boxes.size()) << "trial " << trial;
        touching += general.empty() ? 0 : 1;
        if (boxes.size() == 1 && feature_kind(boxes[0].feature_a) == FeatureKind3d::edge &&
            feature_kind(boxes[0].feature_b) == FeatureKind3d::edge)
            ++edge_on_edge;
        for (std::size_t k = 0; k < general.size(); ++k) {
            EXPECT_EQ(general[k].feature_a, boxes[k].feature_a) << "trial " << trial;
            EXPECT_EQ(general[k].feature_b, boxes[k].feature_b) << "trial " << trial;
            // Round-off of sums of products of lengths below 0.3 m.
            EXPECT_NEAR(general[k].overlap_m, boxes[k].overlap_m, 1e-14);
            EXPECT_NEAR(length(general[k].point_m - boxes[k].point_m), 0.0, 1e-14);
        }
    }
    EXPECT_GT(touching, 2000);
    EXPECT_GT(edge_on_edge, 20);
}

TEST(BoxFrame3d, PointsComeSortedByKeyEachKeyOnce) {
    // The narrow phase sorts a pair's points by (feature_a, feature_b) and merges a key found twice
    // into one point (the contact table matches them by key). Over random poses, turned little
    // (the clip's corners one step round from key order, as on a wall) and much, on both paths.
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    int with_points = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double turn = trial % 2 == 0 ? 1e-6 : 0.6;
        const Quaternion qa = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const Quaternion qb = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const PosedBox a(brick, qa, {0.0, 0.0, 0.0});
        const PosedBox b(brick, qb, {0.15 * u(random), 0.05 * u(random), 0.099 + 0.002 * u(random)});
        for (bool as_box : {true, false}) {
            ContactScratch3d scratch;
            std::vector<ContactGeometry3d> points;
            polyhedron_contact_3d(a.view(as_box), b.view(as_box), scratch, points);
            with_points += points.empty() ? 0 : 1;
            for (std::size_t k = 1; k < points.size(); ++k) {
                const auto before = std::make_pair(points[k - 1].feature_a, points[k - 1].feature_b);
                const auto here = std::make_pair(points[k].feature_a, points[k].feature_b);
                EXPECT_LT(before, here) << "trial " << trial << " point " << k;
            }
        }
    }
    EXPECT_GT(with_points, 2000);
}

}  // namespace
}  // namespace blockdem
