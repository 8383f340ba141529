// The per-body work of the 3-D step (branch pose3d): the pose from one rotation matrix a body
// (world/step_3d.cpp: a box's corners as the centre +/- h_i d_i, its bounding box from |R| h),
// the kick with that matrix, and the drift's rounds stopped by the contraction bound with the
// turn's series for small angles (dynamics/rigid_rotation_3d.cpp). Each against the formulas
// they replace, worked out independently here: the quaternion turns of every vertex, and the
// drift's fixed point solved in long double with the exact turn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "dynamics/rigid_rotation_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

// Round-off of a vector of length about 1, after a few dozen operations.
constexpr double round_off = 1e-15;

TEST(Pose3d, MatrixByProductsIsTheMatrixOfTheTurnedAxes) {
    for (Vec3 v : {Vec3{0.3, -1.2, 2.0}, Vec3{0, 0, 3.1}, Vec3{1e-9, 2e-9, 0}, Vec3{}}) {
        const Quaternion q = from_rotation_vector(v);
        const Matrix3d by_products = rotation_matrix_by_products(q);
        const Matrix3d by_turns = rotation_matrix(q);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) EXPECT_NEAR(by_products.m[i][j], by_turns.m[i][j], round_off);
        const Vec3 u{0.7, -0.2, 0.4};
        EXPECT_NEAR(length(transpose_times(by_products, u) - rotate_inverse(q, u)), 0.0, round_off);
    }
}

// A world with a brick turned about a skew axis (a box: the corner path), a hexagonal prism
// and a pyramid (the general path), all dynamic and spinning, far from the origin.
World3d three_bodies() {
    World3d w;
    w.gravity_m_s2 = 0.0;
    const Vec3 far{120.0, -40.0, 7.0};
    add_body(w,
             make_rigid_body_3d("brick", box_vertices({0.2, 0.1, 0.1}, far, from_rotation_vector({0.4, -0.9, 1.3})),
                                2000.0),
             BodyKind3d::dynamic);
    std::vector<Vec2> hexagon;
    for (int k = 0; k < 6; ++k)
        hexagon.push_back({0.3 * std::cos(k * std::numbers::pi / 3), 0.3 * std::sin(k * std::numbers::pi / 3)});
    std::vector<Vec3> prism = prism_vertices(hexagon, 0.5);
    for (Vec3& v : prism) v = far + Vec3{3.0, 0, 0} + rotate(from_rotation_vector({0.2, 0.1, 0.5}), v);
    add_body(w, make_rigid_body_3d("drum", prism, 2500.0), BodyKind3d::dynamic);
    add_body(w,
             make_rigid_body_3d("pyramid", {far + Vec3{0, 3, 0}, far + Vec3{1, 3, 0}, far + Vec3{0, 4, 0},
                                            far + Vec3{0.2, 3.3, 0.8}},
                                2600.0),
             BodyKind3d::dynamic);
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        set_initial_velocity(w.bodies[i], {0.1, 0, 0}, {3.0 + static_cast<double>(i), -2.0, 1.5});
    return w;
}

TEST(Pose3d, CornersNormalsAndBoxesAreTheTurnedShapesToRoundOff) {
    World3d w = three_bodies();
    ASSERT_TRUE(w.box_frames[0].is_box);
    ASSERT_FALSE(w.box_frames[1].is_box);
    for (int step = 0; step < 30; ++step) {
        step_begin(w);
        const WorldScratch3d& s = w.scratch;
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const RigidBody3d& b = w.bodies[i];
            // A vertex 120 m from the origin carries 120 m times the unit round-off (2.2e-16) a
            // sum; the turned vector itself (bodies within 1 m of their centroid) a few 1e-16 m.
            const double far_round_off_m = 120.0 * 4.4e-16;
            for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
                const Vec3 posed = s.world_vertices_m[s.vertex_start[i] + k];
                // Relative to the body: the centroid's own coordinates (about 120 m) carry their round-off.
                EXPECT_NEAR(length(posed - (b.position_m + rotate(b.orientation, b.shape.vertices_m[k]))), 0.0,
                            far_round_off_m + 4 * round_off)
                    << "body " << i << " vertex " << k;
                const Aabb3d& box = s.boxes[i];
                // The box holds every vertex (to the round-off of 120 m coordinates).
                const double slack_m = far_round_off_m;
                EXPECT_LE(box.lo.x, posed.x + slack_m);
                EXPECT_LE(box.lo.y, posed.y + slack_m);
                EXPECT_LE(box.lo.z, posed.z + slack_m);
                EXPECT_GE(box.hi.x, posed.x - slack_m);
                EXPECT_GE(box.hi.y, posed.y - slack_m);
                EXPECT_GE(box.hi.z, posed.z - slack_m);
            }
            // ... and is no larger than the vertices' extent.
            Vec3 lo = s.world_vertices_m[s.vertex_start[i]], hi = lo;
            for (std::uint32_t k = s.vertex_start[i]; k < s.vertex_start[i + 1]; ++k) {
                const Vec3 v = s.world_vertices_m[k];
                lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
                hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
            }
            EXPECT_NEAR(length(lo - s.boxes[i].lo), 0.0, 120.0 * 4.4e-16) << "body " << i;
            EXPECT_NEAR(length(hi - s.boxes[i].hi), 0.0, 120.0 * 4.4e-16) << "body " << i;
            // The normals as the narrow phase reads them (a box's from its directions, stored for the others).
            for (std::uint32_t k = 0; k < b.shape.face_normals.size(); ++k)
                EXPECT_NEAR(length(face_normal(s.posed[i], k) - rotate(b.orientation, b.shape.face_normals[k])), 0.0,
                            round_off);
            for (std::size_t k = 0; k < w.edges[i].directions.size(); ++k)
                EXPECT_NEAR(length(s.world_directions[s.direction_start[i] + k] -
                                   rotate(b.orientation, w.edges[i].directions[k])),
                            0.0, round_off);
            EXPECT_NEAR(length(s.angular_velocity_world_rad_s[i] - rotate(b.orientation, b.angular_velocity_body_rad_s)),
                        0.0, 10 * round_off);
        }
        step_end(w);
    }
}

// Two bricks 0.2 x 0.1 x 0.05 m, the upper on the lower sunk 1e-4 m into it, and a third far away.
World3d resting_bricks() {
    World3d w;
    const Vec3 size_m{0.2, 0.1, 0.05};
    add_body(w, make_rigid_body_3d("lower", box_vertices(size_m, {0, 0, 0}), 2000.0), BodyKind3d::fixed);
    add_body(w, make_rigid_body_3d("upper", box_vertices(size_m, {0.05, 0, 0.05 - 1e-4}), 2000.0), BodyKind3d::dynamic);
    add_body(w, make_rigid_body_3d("far", box_vertices(size_m, {5, 0, 0}), 2000.0), BodyKind3d::fixed);
    return w;
}

// Every view points into its own world: its body's shape, edges, frame and centroid and its runs
// in the pose arrays.
void expect_views_point_into(const World3d& w) {
    const WorldScratch3d& s = w.scratch;
    ASSERT_EQ(s.posed.size(), w.bodies.size());
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const PosedPolyhedron& p = s.posed[i];
        EXPECT_EQ(p.shape, &w.bodies[i].shape) << "body " << i;
        EXPECT_EQ(p.edges, &w.edges[i]) << "body " << i;
        EXPECT_EQ(p.box, &w.box_frames[i]) << "body " << i;
        EXPECT_EQ(p.centroid_m, s.centroids_m.data() + i) << "body " << i;
        EXPECT_EQ(p.vertices_m, s.world_vertices_m.data() + s.vertex_start[i]) << "body " << i;
        EXPECT_EQ(p.directions, s.world_directions.data() + s.direction_start[i]) << "body " << i;
    }
}

// A box whose normals are its directions stores none: the brick's view reads them from its
// directions, the same bits as its normals turned by the pose's matrix (here a skew turn).
TEST(Pose3d, ABoxsNormalsAreItsTurnedDirectionsToTheBit) {
    World3d w = resting_bricks();
    ASSERT_TRUE(w.box_frames[0].normals_are_directions);
    w.bodies[0].orientation = from_rotation_vector({0.4, -0.9, 1.3});
    step_begin(w);
    const WorldScratch3d& s = w.scratch;
    EXPECT_EQ(s.posed[0].face_normals, nullptr);
    EXPECT_EQ(s.face_start[1], 0u);
    const Matrix3d rotation = rotation_matrix_by_products(w.bodies[0].orientation);
    for (std::uint32_t k = 0; k < 6; ++k) {
        const Vec3 turned = rotation * w.bodies[0].shape.face_normals[k];
        const Vec3 read = face_normal(s.posed[0], k);
        EXPECT_TRUE(turned.x == read.x && turned.y == read.y && turned.z == read.z) << "face " << k;
    }
}

// The narrow phase's views are written when what they point into moves, not at every step
// (world/step_3d.cpp, size_pose_arrays): a world copied, or assigned from another (as a state is
// restored over a world), and a body added, each step their own bodies.
TEST(Pose3d, ViewsFollowTheirWorldWhenCopiedAssignedOrGrown) {
    World3d original = resting_bricks();
    step_3d(original);
    ASSERT_GT(original.contacts.size(), 0u);
    // A copy steps its own bodies: the original's upper brick lifted away changes nothing in it.
    World3d copy = original;
    original.bodies[1].position_m.z += 1.0;
    step_3d(copy);
    step_3d(original);
    expect_views_point_into(copy);
    expect_views_point_into(original);
    EXPECT_EQ(original.contacts.size(), 0u);
    EXPECT_GT(copy.contacts.size(), 0u);
    // Assigned over a world of the same bodies (the bodies' buffer kept, the views the other's).
    World3d restored = resting_bricks();
    step_3d(restored);
    restored = original;
    step_3d(restored);
    expect_views_point_into(restored);
    EXPECT_EQ(restored.contacts.size(), 0u);
    restored.bodies[1].position_m = copy.bodies[1].position_m;
    restored.bodies[1].orientation = copy.bodies[1].orientation;
    step_3d(restored);
    EXPECT_GT(restored.contacts.size(), 0u);
    // A body added on the far brick: its own contact, the others' as before.
    const std::size_t before = copy.contacts.size();
    add_body(copy, make_rigid_body_3d("added", box_vertices({0.2, 0.1, 0.05}, {5, 0, 0.05 - 1e-4}), 2000.0),
             BodyKind3d::dynamic);
    step_3d(copy);
    expect_views_point_into(copy);
    std::size_t on_added = 0, on_upper = 0;
    for (const ContactPoint3d& c : copy.contacts) {
        on_added += c.key.body_a == 2 && c.key.body_b == 3;
        on_upper += c.key.body_a == 0 && c.key.body_b == 1;
    }
    EXPECT_EQ(on_upper, before);
    EXPECT_GT(on_added, 0u);
}

TEST(Pose3d, BoxFrameNamesEachVertexCorner) {
    const RigidBody3d b =
        make_rigid_body_3d("brick", box_vertices({0.4, 0.2, 0.1}, {}, from_rotation_vector({0.3, 0.2, -0.6})), 2000.0);
    const BoxFrame3d frame = box_frame(b.shape, polyhedron_edges(b.shape));
    ASSERT_TRUE(frame.is_box);
    const PolyhedronEdges edges = polyhedron_edges(b.shape);
    std::vector<bool> seen(8, false);
    for (std::size_t k = 0; k < 8; ++k) {
        const std::uint8_t corner = frame.vertex_corner[k];
        ASSERT_LT(corner, 8);
        EXPECT_FALSE(seen[corner]) << "two vertices at corner " << int(corner);
        seen[corner] = true;
        const double h[3] = {frame.half_lengths_m.x, frame.half_lengths_m.y, frame.half_lengths_m.z};
        Vec3 expected;
        for (int i = 0; i < 3; ++i) expected += ((corner >> i) & 1 ? h[i] : -h[i]) * edges.directions[i];
        EXPECT_NEAR(length(expected - b.shape.vertices_m[k]), 0.0, round_off);
    }
}

TEST(Pose3d, KickWithTheMatrixIsTheKickWithTheQuaternion) {
    RigidBody3d a = make_rigid_body_3d("a", box_vertices({0.3, 0.2, 0.1}, {}, from_rotation_vector({0.5, 1, 0})), 900.0);
    set_initial_velocity(a, {1, 2, 3}, {0.4, -3.0, 2.0});
    a.force_n = {3, -1, 2};
    a.torque_n_m = {0.2, 0.1, -0.3};
    RigidBody3d b = a;
    const double energy_j = update_velocity_3d(a, 1e-3, true);
    // The quaternion's kick, written out: L at t turned into the body, divided, turned back.
    const double dt_s = 1e-3;
    const Vec3 l_at_t = b.angular_momentum_kg_m2_s;  // starting: the stored momentum is the one at t
    const Vec3 omega_body = hadamard(b.inverse_moments_1_kg_m2, rotate_inverse(b.orientation, l_at_t));
    EXPECT_NEAR(length(a.angular_velocity_at_t_rad_s - rotate(b.orientation, omega_body)), 0.0, 10 * round_off);
    EXPECT_NEAR(length(a.velocity_at_t_m_s - b.velocity_m_s), 0.0, round_off);
    EXPECT_NEAR(length(a.angular_momentum_kg_m2_s - (l_at_t + 0.5 * dt_s * b.torque_n_m)), 0.0, round_off);
    EXPECT_NEAR(energy_j, kinetic_energy(a), 1e-14 * energy_j);
}

// The drift's fixed point, omega = I^-1 (L + exp(omega dt)^T L) / 2, solved in long double with
// the exact turn (Rodrigues' formula) and rounds to 1e-19.
struct LongVec {
    long double x, y, z;
};
LongVec reference_omega(Vec3 l_body, Vec3 inverse, double dt_s) {
    LongVec w{inverse.x * (long double)l_body.x, inverse.y * (long double)l_body.y, inverse.z * (long double)l_body.z};
    for (int round = 0; round < 200; ++round) {
        const long double tx = dt_s * w.x, ty = dt_s * w.y, tz = dt_s * w.z;
        const long double angle = std::sqrt(tx * tx + ty * ty + tz * tz);
        // exp(t)^T L = L cos a - (k x L) sin a + k (k . L)(1 - cos a), k = t / a.
        long double ex = l_body.x, ey = l_body.y, ez = l_body.z;
        if (angle > 0) {
            const long double kx = tx / angle, ky = ty / angle, kz = tz / angle;
            const long double c = std::cos(angle), s = std::sin(angle);
            const long double kl = kx * l_body.x + ky * l_body.y + kz * l_body.z;
            ex = l_body.x * c - (ky * l_body.z - kz * l_body.y) * s + kx * kl * (1 - c);
            ey = l_body.y * c - (kz * l_body.x - kx * l_body.z) * s + ky * kl * (1 - c);
            ez = l_body.z * c - (kx * l_body.y - ky * l_body.x) * s + kz * kl * (1 - c);
        }
        const LongVec next{inverse.x * (l_body.x + ex) / 2, inverse.y * (l_body.y + ey) / 2,
                           inverse.z * (l_body.z + ez) / 2};
        const long double change = std::abs(next.x - w.x) + std::abs(next.y - w.y) + std::abs(next.z - w.z);
        w = next;
        if (change <= 1e-19L * (std::abs(w.x) + std::abs(w.y) + std::abs(w.z))) break;
    }
    return w;
}

TEST(Pose3d, DriftStopsAtTheFixedPointWithinRoundOff) {
    const Vec3 inverse{1.0 / 0.0125, 1.0 / 0.0340, 1.0 / 0.0410};
    const double dt_s = 1e-4;
    // |omega| dt from 1e-12 (a brick at rest: one round, the series) through 2e-6 (the series'
    // end) to 0.05 (the exact turn, several rounds).
    for (double scale : {1e-8, 1e-5, 1e-3, 0.02, 0.1, 1.0, 10.0, 500.0}) {
        const Vec3 l_body = scale * Vec3{0.0123, -0.0311, 0.0207};
        Quaternion q;
        const Vec3 omega = free_rotation(q, l_body, inverse, dt_s);
        const LongVec r = reference_omega(l_body, inverse, dt_s);
        const double size = std::abs(omega.x) + std::abs(omega.y) + std::abs(omega.z);
        EXPECT_NEAR(omega.x, (double)r.x, 4e-16 * size) << "scale " << scale;
        EXPECT_NEAR(omega.y, (double)r.y, 4e-16 * size) << "scale " << scale;
        EXPECT_NEAR(omega.z, (double)r.z, 4e-16 * size) << "scale " << scale;
        // The body turned by omega dt: the identity turned is exp(omega dt).
        const Quaternion turned = from_rotation_vector(dt_s * omega);
        EXPECT_NEAR(std::abs(q.w * turned.w + q.x * turned.x + q.y * turned.y + q.z * turned.z), 1.0, 1e-15);
        EXPECT_NEAR(length(rotation_vector(q) - dt_s * omega), 0.0, 1e-15 * (1 + length(dt_s * omega)));
    }
}

}  // namespace
}  // namespace blockdem
