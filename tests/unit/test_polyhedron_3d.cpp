// Convex polyhedra: the hull, the checks that name a mistake, and the mass properties against
// closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "dynamics/rigid_body_3d.hpp"
#include "geometry/polyhedron.hpp"
#include "world/world.hpp"

namespace blockdem {
namespace {

// The message of the std::invalid_argument that convex_polyhedron throws, or "" if none.
std::string hull_problem(const std::vector<Vec3>& v) {
    try {
        convex_polyhedron(v);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

std::string faces_problem(const std::vector<Vec3>& v, const std::vector<std::vector<std::size_t>>& faces) {
    try {
        convex_polyhedron(v, faces);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

void expect_matrix_near(const Matrix3d& a, const Matrix3d& b, double tolerance) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tolerance) << "entry " << i << "," << j;
}

Matrix3d diagonal(Vec3 d) { return {{{{d.x, 0, 0}, {0, d.y, 0}, {0, 0, d.z}}}}; }

TEST(Polyhedron3d, BoxHullAndProperties) {
    const Vec3 lengths{0.3, 0.2, 0.1};
    const Polyhedron p = convex_polyhedron(box_vertices(lengths, {1.0, 2.0, 3.0}));
    ASSERT_EQ(p.faces.size(), 6u);
    for (std::size_t f = 0; f < 6; ++f) {
        EXPECT_EQ(p.faces[f].size(), 4u);
        // Outward: the face's points lie on the side of its normal away from the centre.
        const Vec3 corner = p.vertices_m[p.faces[f][0]];
        EXPECT_GT(dot(p.face_normals[f], corner - Vec3{1.0, 2.0, 3.0}), 0.04);
        // Counter-clockwise seen from outside: (v1 - v0) x (v2 - v1) along the normal.
        const Vec3 e1 = p.vertices_m[p.faces[f][1]] - corner;
        const Vec3 e2 = p.vertices_m[p.faces[f][2]] - p.vertices_m[p.faces[f][1]];
        EXPECT_GT(dot(cross(e1, e2), p.face_normals[f]), 0.0);
    }
    const PolyhedronProperties props = polyhedron_properties(p);
    const double v = 0.3 * 0.2 * 0.1;
    EXPECT_NEAR(props.volume_m3, v, 1e-14 * v);  // a sum of 12 tetrahedra: a few round-offs
    EXPECT_NEAR(props.centroid_m.x, 1.0, 1e-14);
    EXPECT_NEAR(props.centroid_m.y, 2.0, 1e-14);
    EXPECT_NEAR(props.centroid_m.z, 3.0, 1e-14);
    // Box: I_xx = V (b^2 + c^2) / 12 per unit density, and so on; no products of inertia.
    expect_matrix_near(props.inertia_m5, diagonal({v * (0.04 + 0.01) / 12, v * (0.09 + 0.01) / 12, v * (0.09 + 0.04) / 12}),
                       1e-18);
}

TEST(Polyhedron3d, RegularTetrahedron) {
    const double a = 0.7;  // edge
    const double s = a / (2.0 * std::sqrt(2.0));
    const std::vector<Vec3> v = {{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
    const Polyhedron p = convex_polyhedron(v);
    EXPECT_EQ(p.faces.size(), 4u);
    const PolyhedronProperties props = polyhedron_properties(p);
    const double volume = a * a * a / (6.0 * std::sqrt(2.0));
    EXPECT_NEAR(props.volume_m3, volume, 1e-15);
    EXPECT_NEAR(length(props.centroid_m), 0.0, 1e-15);
    // A regular tetrahedron's inertia is isotropic: m a^2 / 20 about any axis through the centroid.
    expect_matrix_near(props.inertia_m5, diagonal(Vec3{1, 1, 1} * (volume * a * a / 20.0)), 1e-16);
}

TEST(Polyhedron3d, CornerTetrahedronProductsOfInertia) {
    // The tetrahedron cut from the corner of a box a x b x c: integrals about the origin
    // int x^2 dV = a^3 b c / 60, int x y dV = a^2 b^2 c / 120, volume a b c / 6, centroid (a, b, c) / 4;
    // about the centroid by the parallel-axis theorem. Products of inertia are not zero here.
    const double a = 0.5, b = 0.3, c = 0.2;
    const Polyhedron p = convex_polyhedron({{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}});
    const PolyhedronProperties props = polyhedron_properties(p);
    const double volume = a * b * c / 6.0;
    EXPECT_NEAR(props.volume_m3, volume, 1e-16);
    EXPECT_NEAR(props.centroid_m.x, a / 4, 1e-15);
    EXPECT_NEAR(props.centroid_m.y, b / 4, 1e-15);
    EXPECT_NEAR(props.centroid_m.z, c / 4, 1e-15);
    const double xx = a * a * a * b * c / 60, yy = a * b * b * b * c / 60, zz = a * b * c * c * c / 60;
    const double xy = a * a * b * b * c / 120, xz = a * a * b * c * c / 120, yz = a * b * b * c * c / 120;
    const Matrix3d second_origin{{{{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}}}};
    const Vec3 g{a / 4, b / 4, c / 4};
    const Matrix3d second_centroid = second_origin - volume * Matrix3d::outer(g, g);
    expect_matrix_near(props.inertia_m5, second_centroid.trace() * Matrix3d::identity() - second_centroid, 1e-17);
}

TEST(Polyhedron3d, ThirtyTwoSidedPrismAgainstCylinder) {
    constexpr int n = 32;
    const double radius = 0.4, height = 0.9;
    std::vector<Vec2> polygon;
    for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / n;
        polygon.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    const Polyhedron p = convex_polyhedron(prism_vertices(polygon, height));
    EXPECT_EQ(p.faces.size(), static_cast<std::size_t>(n + 2));
    const PolyhedronProperties props = polyhedron_properties(p);
    // The regular n-gon of circumradius R: area n R^2 sin(2 pi / n) / 2, polar moment
    // A R^2 (1 + 2 cos^2(pi / n)) / 6, exact for the prism.
    const double area = 0.5 * n * radius * radius * std::sin(2.0 * std::numbers::pi / n);
    const double volume = area * height;
    const double polar_per_area = radius * radius * (1.0 + 2.0 * std::pow(std::cos(std::numbers::pi / n), 2)) / 6.0;
    EXPECT_NEAR(props.volume_m3, volume, 1e-15);
    EXPECT_NEAR(props.centroid_m.z, height / 2, 1e-15);
    const double axial = volume * polar_per_area, transverse = volume * (polar_per_area / 2 + height * height / 12);
    expect_matrix_near(props.inertia_m5, diagonal({transverse, transverse, axial}), 1e-15);
    // Against the cylinder it approximates: pi R^2 h, m R^2 / 2, m (3 R^2 + h^2) / 12. The 32-gon
    // holds 0.64% less area (1 - sin(2 pi/n) / (2 pi/n)) and its polar moment per area is 0.64%
    // less again (1 - (1 + 2 cos^2(pi/n)) / 3): 1.28% less about the axis, 0.88% across it; the
    // bounds are these differences, rounded up.
    const double cylinder_volume = std::numbers::pi * radius * radius * height;
    EXPECT_NEAR(props.volume_m3 / cylinder_volume, 1.0, 0.0065);
    EXPECT_NEAR(props.inertia_m5.m[2][2] / (cylinder_volume * radius * radius / 2), 1.0, 0.013);
    EXPECT_NEAR(props.inertia_m5.m[0][0] / (cylinder_volume * (3 * radius * radius + height * height) / 12), 1.0, 0.013);
}

TEST(Polyhedron3d, RotatedTranslatedBoxPrincipalAxes) {
    // A box turned about a skew axis and moved far from the origin: the tensor in the world frame
    // is R diag R^T, its principal moments the box's, its principal axes the box's edges.
    const Vec3 lengths{0.3, 0.2, 0.1};
    const Quaternion turn = from_rotation_vector({0.4, -1.1, 0.7});
    const Vec3 center{1e3, -2e3, 50.0};
    const PolyhedronProperties props = polyhedron_properties(convex_polyhedron(box_vertices(lengths, center, turn)));
    const double v = 0.3 * 0.2 * 0.1;
    const Vec3 moments{v * (0.04 + 0.01) / 12, v * (0.09 + 0.01) / 12, v * (0.09 + 0.04) / 12};
    // 1e3 m away the corners carry round-off of 1e3 * 1e-16 m against edges of 0.1 m: 1e-12
    // relative in each, 1e-11 in the sums.
    EXPECT_NEAR(props.volume_m3, v, 1e-11 * v);
    EXPECT_NEAR(length(props.centroid_m - center), 0.0, 1e-11);
    const Matrix3d r = rotation_matrix(turn);
    expect_matrix_near(props.inertia_m5, r * diagonal(moments) * transpose(r), 1e-15);
    const PrincipalAxes axes = principal_axes(props.inertia_m5);
    EXPECT_NEAR(axes.moments.x, moments.x, 1e-16);
    EXPECT_NEAR(axes.moments.y, moments.y, 1e-16);
    EXPECT_NEAR(axes.moments.z, moments.z, 1e-16);
    for (Vec3 e : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})  // each principal axis along a box edge (either sign)
        EXPECT_NEAR(std::abs(dot(rotate(axes.orientation, e), rotate(turn, e))), 1.0, 1e-12);
}

TEST(Polyhedron3d, CubeHasRepeatedMomentsAndAFrame) {
    const PolyhedronProperties props = polyhedron_properties(convex_polyhedron(box_vertices({1, 1, 1}, {})));
    const PrincipalAxes axes = principal_axes(props.inertia_m5);
    EXPECT_NEAR(axes.moments.x, 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(axes.moments.z, 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(determinant(rotation_matrix(axes.orientation)), 1.0, 1e-14);
}

TEST(Polyhedron3d, BadVertexSetsAreNamed) {
    std::vector<Vec3> box = box_vertices({1, 1, 1}, {});
    EXPECT_NE(hull_problem({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).find("at least 4"), std::string::npos);
    EXPECT_NE(hull_problem({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}).find("one line"), std::string::npos);
    EXPECT_NE(hull_problem({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}).find("one plane"), std::string::npos);
    std::vector<Vec3> repeated = box;
    repeated.push_back(box[3]);
    EXPECT_NE(hull_problem(repeated).find("vertices 3 and 8 coincide"), std::string::npos);
    std::vector<Vec3> inside = box;
    inside.push_back({0.1, 0.0, -0.2});
    EXPECT_NE(hull_problem(inside).find("vertex 8 (0.1, 0, -0.2) lies inside the hull"), std::string::npos)
        << hull_problem(inside);
    // A point in the middle of a face or of an edge is not a corner: a mistake, not a vertex.
    std::vector<Vec3> on_face = box;
    on_face.insert(on_face.begin() + 2, Vec3{0.5, 0.1, 0.2});
    EXPECT_NE(hull_problem(on_face).find("vertex 2 (0.5, 0.1, 0.2) lies on an edge or inside a face"), std::string::npos)
        << hull_problem(on_face);
    std::vector<Vec3> on_edge = box;
    on_edge.push_back({0.5, 0.5, 0.0});
    EXPECT_NE(hull_problem(on_edge).find("vertex 8"), std::string::npos);
    EXPECT_EQ(hull_problem(box), "");
}

TEST(Polyhedron3d, ListedFacesAreChecked) {
    // A unit cube's corners and its faces counter-clockwise from outside.
    const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    std::vector<std::vector<std::size_t>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    EXPECT_EQ(faces_problem(v, faces), "");
    EXPECT_EQ(convex_polyhedron(v, faces).faces[0], faces[0]);  // kept as listed
    auto inverted = faces;
    inverted[2] = {4, 5, 1, 0};
    EXPECT_NE(faces_problem(v, inverted).find("face 2 is inverted"), std::string::npos) << faces_problem(v, inverted);
    auto scrambled = faces;
    scrambled[1] = {4, 6, 5, 7};
    EXPECT_NE(faces_problem(v, scrambled).find("face 1 lists its vertices out of order"), std::string::npos);
    auto not_a_face = faces;
    not_a_face[3] = {0, 2, 6, 4};  // a diagonal plane through the cube
    EXPECT_NE(faces_problem(v, not_a_face).find("face 3 is not a face of the convex hull"), std::string::npos);
    auto missing = faces;
    missing.pop_back();
    EXPECT_NE(faces_problem(v, missing).find("leave out the hull's face through vertices"), std::string::npos)
        << faces_problem(v, missing);
}

TEST(Polyhedron3d, BodyErrorsNameTheBody) {
    std::vector<Vec3> box = box_vertices({1, 1, 1}, {});
    box.push_back({0, 0, 0});
    try {
        make_rigid_body_3d("drum_2", box, 2500.0);
        FAIL() << "a vertex inside the hull was accepted";
    } catch (const ModelError& e) {
        EXPECT_NE(std::string(e.what()).find("body 'drum_2': vertex 8"), std::string::npos) << e.what();
    }
    EXPECT_THROW(make_rigid_body_3d("b", box_vertices({1, 1, 1}, {}), 0.0), ModelError);
    // Listed faces: an inverted one is named with the body.
    const std::vector<Vec3> cube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const std::vector<std::vector<std::size_t>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 5, 1},
                                                         {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    try {
        make_rigid_body_3d("slab", cube, faces, 2500.0);
        FAIL() << "an inverted face was accepted";
    } catch (const ModelError& e) {
        EXPECT_NE(std::string(e.what()).find("body 'slab': face 2 is inverted"), std::string::npos) << e.what();
    }
}

TEST(Polyhedron3d, BodyFrameIsPrincipal) {
    const Quaternion turn = from_rotation_vector({0.3, 0.2, -0.5});
    const Vec3 center{2, 3, 4};
    const RigidBody3d b = make_rigid_body_3d("block", box_vertices({0.3, 0.2, 0.1}, center, turn), 2000.0);
    EXPECT_NEAR(b.mass_kg, 2000.0 * 0.006, 1e-12);
    EXPECT_NEAR(b.principal_moments_kg_m2.x, 12.0 * (0.04 + 0.01) / 12, 1e-13);
    EXPECT_NEAR(b.principal_moments_kg_m2.z, 12.0 * (0.09 + 0.04) / 12, 1e-13);
    EXPECT_NEAR(length(b.position_m - center), 0.0, 1e-14);
    // The world corners are those given: the body frame only relabels them.
    const std::vector<Vec3> given = box_vertices({0.3, 0.2, 0.1}, center, turn);
    for (std::size_t i = 0; i < given.size(); ++i) EXPECT_NEAR(length(world_vertex(b, i) - given[i]), 0.0, 1e-14);
}

}  // namespace
}  // namespace blockdem
