// The plane cut of a convex polyhedron and the rock mass cut by joint sets
// (geometry/polyhedron_cut.hpp, geometry/joint_set_3d.hpp): the geological normal, cuts through
// vertices, edges and faces, slivers merged, and a region cut into blocks whose volumes sum to
// the region's and whose every face lies on a joint or on the region's boundary.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "dynamics/rigid_body_3d.hpp"
#include "geometry/joint_set_3d.hpp"
#include "geometry/polyhedron.hpp"
#include "geometry/polyhedron_cut.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;

void expect_near(Vec3 a, Vec3 b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

CutPolyhedron unit_cube() { return cut_polyhedron_of(convex_polyhedron(box_vertices({1, 1, 1}, {0.5, 0.5, 0.5})), 0); }

TEST(JointNormal, FollowsTheGeologicalConvention) {
    expect_near(joint_normal(90.0, 90.0), {1, 0, 0}, 1e-15);     // vertical, striking north: normal east
    expect_near(joint_normal(0.0, 90.0), {0, 1, 0}, 1e-15);      // striking east-west: normal north
    expect_near(joint_normal(217.0, 0.0), {0, 0, 1}, 1e-15);     // horizontal, whatever its dip direction
    const double h = std::sqrt(0.5);
    expect_near(joint_normal(180.0, 45.0), {0, -h, h}, 1e-15);   // dipping south: the pole leans south
    // The line of steepest descent points along the dip direction, at the dip below the horizontal.
    const double a = 30.0 * pi / 180.0, b = 50.0 * pi / 180.0;
    const Vec3 down_dip{std::sin(a) * std::cos(b), std::cos(a) * std::cos(b), -std::sin(b)};
    EXPECT_NEAR(dot(joint_normal(30.0, 50.0), down_dip), 0.0, 1e-15);
}

TEST(PolyhedronCut, ThroughTwoEdgesGivesTwoPrisms) {
    // x = y passes through the vertical edges at (0, 0) and (1, 1): no vertex is cut off or doubled.
    const Plane3d plane{normalized(Vec3{1, -1, 0}), 0.0};
    const HalfSpaceCut cut = cut_by_plane(unit_cube(), plane, 99, 1e-12);
    ASSERT_TRUE(cut.below && cut.above);
    EXPECT_NEAR(cut_polyhedron_volume(*cut.below), 0.5, 1e-15);
    EXPECT_NEAR(cut_polyhedron_volume(*cut.above), 0.5, 1e-15);
    EXPECT_EQ(cut_polyhedron_vertices(*cut.below, 1e-12).size(), 6u);
    EXPECT_EQ(cut_polyhedron_vertices(*cut.above, 1e-12).size(), 6u);
    EXPECT_EQ(cut.below->faces.size(), 5u);  // a triangular prism
    EXPECT_EQ(cut.below->faces.back().plane, 99u);
    EXPECT_NO_THROW(make_rigid_body_3d("half", cut_polyhedron_vertices(*cut.below, 1e-12), 1.0));
}

TEST(PolyhedronCut, OnAFaceOrAVertexCutsNothing) {
    const HalfSpaceCut on_face = cut_by_plane(unit_cube(), {{0, 0, 1}, 1.0}, 7, 1e-12);
    EXPECT_TRUE(on_face.below && !on_face.above);
    const HalfSpaceCut on_vertex = cut_by_plane(unit_cube(), {normalized(Vec3{1, 1, 1}), 0.0}, 7, 1e-12);
    EXPECT_TRUE(!on_vertex.below && on_vertex.above);
    EXPECT_NEAR(cut_polyhedron_volume(*on_vertex.above), 1.0, 1e-15);
    // A vertex within the tolerance of the plane counts as on it: no sliver of 1e-30 m^3.
    const HalfSpaceCut near_vertex = cut_by_plane(unit_cube(), {normalized(Vec3{1, 1, 1}), 1e-14}, 7, 1e-12);
    EXPECT_TRUE(!near_vertex.below && near_vertex.above);
}

TEST(PolyhedronCut, ThroughAVertexAndAcrossFaces) {
    // x + y + z = 1 passes through three vertices: the corner tetrahedron, volume 1/6.
    const HalfSpaceCut cut = cut_by_plane(unit_cube(), {normalized(Vec3{1, 1, 1}), 1.0 / std::sqrt(3.0)}, 5, 1e-12);
    ASSERT_TRUE(cut.below && cut.above);
    EXPECT_NEAR(cut_polyhedron_volume(*cut.below), 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(cut_polyhedron_volume(*cut.above), 5.0 / 6.0, 1e-15);
    EXPECT_EQ(cut_polyhedron_vertices(*cut.below, 1e-12).size(), 4u);
    EXPECT_EQ(cut_polyhedron_vertices(*cut.above, 1e-12).size(), 7u);
    EXPECT_NO_THROW(make_rigid_body_3d("rest", cut_polyhedron_vertices(*cut.above, 1e-12), 1.0));
}

TEST(PolyhedronCut, ASliverIsMergedNotCut) {
    const std::vector<Plane3d> planes = {{{0, 0, 1}, 1e-4}, {{0, 0, 1}, 0.5}};
    const CutIntoBlocks blocks = cut_into_blocks(unit_cube(), planes, 6, 1e-3, 1e-12);
    EXPECT_EQ(blocks.slivers_merged, 1u);
    ASSERT_EQ(blocks.blocks.size(), 2u);
    EXPECT_NEAR(cut_polyhedron_volume(blocks.blocks[0]), 0.5, 1e-15);
    EXPECT_NEAR(cut_polyhedron_volume(blocks.blocks[1]), 0.5, 1e-15);
}

// Every face of every block on the plane of its label: a region face (label < region faces) or
// a joint; its corners on that plane to round-off, its outward normal along the plane's normal.
void expect_faces_on_their_planes(const CutIntoBlocks& cut, const Polyhedron& region, const std::vector<Plane3d>& joints,
                                  double size_m) {
    for (const CutPolyhedron& block : cut.blocks) {
        for (const CutFace& f : block.faces) {
            ASSERT_LT(f.plane, region.faces.size() + joints.size());
            Plane3d plane;
            if (f.plane < region.faces.size()) {
                plane.normal = region.face_normals[f.plane];
                plane.offset_m = dot(plane.normal, region.vertices_m[region.faces[f.plane][0]]);
            } else {
                plane = joints[f.plane - region.faces.size()];
            }
            for (Vec3 c : f.corners_m) EXPECT_NEAR(dot(plane.normal, c), plane.offset_m, 1e-12 * size_m);
            Vec3 area;
            for (std::size_t i = 0; i < f.corners_m.size(); ++i)
                area += cross(f.corners_m[i], f.corners_m[(i + 1) % f.corners_m.size()]);
            EXPECT_NEAR(std::abs(dot(normalized(area), plane.normal)), 1.0, 1e-12);
            if (f.plane < region.faces.size()) EXPECT_GT(dot(area, plane.normal), 0.0);  // outward, as the region's
        }
    }
}

std::vector<Plane3d> planes_of(const std::vector<JointSet3d>& sets, const Polyhedron& region) {
    std::vector<Plane3d> planes;
    for (const JointSet3d& s : sets) {
        const std::vector<Plane3d> p = joint_planes(s, region.vertices_m);
        planes.insert(planes.end(), p.begin(), p.end());
    }
    return planes;
}

TEST(RockMassCut, OrthogonalSetsGiveTheProductOfTheCuts) {
    // A 10 x 6 x 4 m box from the origin: joints every 2 m along x (four inside, the two on the
    // end faces cut nothing), every 1.5 m along y (three inside), every 1 m along z from 0.3 m (four).
    const Polyhedron region = convex_polyhedron(box_vertices({10, 6, 4}, {5, 3, 2}));
    const std::vector<JointSet3d> sets = {{90.0, 90.0, 2.0, {}}, {0.0, 90.0, 1.5, {}}, {0.0, 0.0, 1.0, {0, 0, 0.3}}};
    const std::vector<Plane3d> joints = planes_of(sets, region);
    const CutIntoBlocks cut = cut_into_blocks(cut_polyhedron_of(region, 0), joints, region.faces.size(), 1e-6, 1e-9);
    EXPECT_EQ(cut.blocks.size(), 5u * 4u * 5u);
    EXPECT_EQ(cut.slivers_merged, 0u);
    double volume_m3 = 0.0;
    for (const CutPolyhedron& b : cut.blocks) {
        volume_m3 += cut_polyhedron_volume(b);
        EXPECT_EQ(cut_polyhedron_vertices(b, 1e-9).size(), 8u);  // each a box
    }
    std::printf("orthogonal sets: %zu blocks, volume off by %.2g of the region's\n", cut.blocks.size(), volume_m3 / 240.0 - 1.0);
    EXPECT_NEAR(volume_m3 / 240.0, 1.0, 1e-12);
    expect_faces_on_their_planes(cut, region, joints, 10.0);
}

TEST(RockMassCut, ObliqueSetsInASlopeTileItExactly) {
    // The slope prism of examples/3d/rock_slope.toml and its three sets: the blocks are convex
    // bodies, fill the region to round-off and sit on their planes.
    const Polyhedron region = convex_polyhedron(
        {{0, 0, 0}, {12, 0, 0}, {12, 0, 8}, {4, 0, 8}, {0, 4, 0}, {12, 4, 0}, {12, 4, 8}, {4, 4, 8}});
    const std::vector<JointSet3d> sets = {{270.0, 35.0, 2.0, {0, 0, 0.5}}, {10.0, 80.0, 2.5, {}}, {90.0, 70.0, 3.0, {}}};
    const std::vector<Plane3d> joints = planes_of(sets, region);
    const CutIntoBlocks cut = cut_into_blocks(cut_polyhedron_of(region, 0), joints, region.faces.size(), 0.0, 1e-8);
    EXPECT_GT(cut.blocks.size(), 40u);
    double volume_m3 = 0.0;
    for (const CutPolyhedron& b : cut.blocks) {
        volume_m3 += cut_polyhedron_volume(b);
        EXPECT_GT(cut_polyhedron_volume(b), 0.0);
        EXPECT_NO_THROW(make_rigid_body_3d("block", cut_polyhedron_vertices(b, 1e-8), 2600.0));
    }
    const double region_m3 = polyhedron_properties(region).volume_m3;
    std::printf("slope, three oblique sets: %zu blocks, volume off by %.2g of the region's\n", cut.blocks.size(), volume_m3 / region_m3 - 1.0);
    EXPECT_NEAR(volume_m3 / region_m3, 1.0, 1e-12);
    expect_faces_on_their_planes(cut, region, joints, 12.0);
}


TEST(RockMassCut, ManyOrientationsAndJointsThroughVertices) {
    // Sets at many orientations, some with a joint through a corner of the region (origin on a
    // vertex) or along its faces (dip 0 and 90): the blocks always tile the region and are valid
    // bodies, whatever vertices lie on the joints.
    const Polyhedron region = convex_polyhedron(box_vertices({3, 2, 1.5}, {1.5, 1, 0.75}));
    int cases = 0;
    for (double dd : {0.0, 45.0, 90.0, 123.4, 270.0, 333.0})
        for (double dip : {0.0, 30.0, 45.0, 60.0, 90.0}) {
            const std::vector<JointSet3d> sets = {{dd, dip, 0.5, {0, 0, 0}},
                                                  {std::fmod(dd + 100.0, 360.0), 90.0 - 0.5 * dip, 0.7, {3, 2, 1.5}},
                                                  {std::fmod(dd + 200.0, 360.0), 75.0, 0.5, {1.5, 0, 0}}};
            const std::vector<Plane3d> joints = planes_of(sets, region);
            const CutIntoBlocks cut =
                cut_into_blocks(cut_polyhedron_of(region, 0), joints, region.faces.size(), 1e-6, 3e-9);
            double volume_m3 = 0.0;
            for (const CutPolyhedron& b : cut.blocks) {
                volume_m3 += cut_polyhedron_volume(b);
                EXPECT_NO_THROW(make_rigid_body_3d("block", cut_polyhedron_vertices(b, 3e-9), 1.0))
                    << "dip direction " << dd << ", dip " << dip;
            }
            EXPECT_NEAR(volume_m3 / 9.0, 1.0, 1e-12) << "dip direction " << dd << ", dip " << dip;
            expect_faces_on_their_planes(cut, region, joints, 3.0);
            ++cases;
        }
    EXPECT_EQ(cases, 30);
}

}  // namespace
}  // namespace blockdem
