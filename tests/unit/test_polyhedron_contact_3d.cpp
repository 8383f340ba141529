// The 3-D narrow phase (geometry/polyhedron_contact_3d.hpp) and broad phase
// (broad_phase/grid_broad_phase_3d.hpp) against hand-worked cases and brute force.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "broad_phase/grid_broad_phase_3d.hpp"
#include "geometry/polyhedron_contact_3d.hpp"

namespace blockdem {
namespace {

// A polyhedron posed in the world at its listed coordinates (the body frame is the world's).
struct Posed {
    Polyhedron shape;
    PolyhedronEdges edges;
    std::vector<Vec3> directions;
    Vec3 centroid;
    explicit Posed(const std::vector<Vec3>& vertices)
        : shape(convex_polyhedron(vertices)), edges(polyhedron_edges(shape)), directions(edges.directions) {
        for (const Vec3& v : shape.vertices_m) centroid += (1.0 / static_cast<double>(vertices.size())) * v;
    }
    PosedPolyhedron view() const {
        return {&shape, &edges, shape.vertices_m.data(), shape.face_normals.data(), directions.data(), &centroid};
    }
};

std::vector<ContactGeometry3d> contact(const Posed& a, const Posed& b) {
    ContactScratch3d scratch;
    std::vector<ContactGeometry3d> out;
    polyhedron_contact_3d(a.view(), b.view(), scratch, out);
    return out;
}

TEST(PolyhedronEdges3d, BoxAndPrismEdgesAndDirections) {
    const Posed cube(box_vertices({1, 1, 1}, {}));
    EXPECT_EQ(cube.edges.edges.size(), 12u);
    EXPECT_EQ(cube.edges.directions.size(), 3u);
    for (const auto& f : cube.edges.face_edges) EXPECT_EQ(f.size(), 4u);
    const Posed hexagonal(prism_vertices({{1, 0}, {0.5, 0.8660254037844386}, {-0.5, 0.8660254037844386}, {-1, 0},
                                          {-0.5, -0.8660254037844386}, {0.5, -0.8660254037844386}},
                                         1.0));
    EXPECT_EQ(hexagonal.edges.edges.size(), 18u);
    EXPECT_EQ(hexagonal.edges.directions.size(), 4u);  // three across the hexagon, one vertical
}

TEST(PolyhedronContact3d, OffsetCubesGiveTheFourCornersOfTheOverlapWithTheirFeatures) {
    // Unit cube [0,1]^3 under a unit cube shifted by (0.5, 0.5) and sunk 0.01 into it. The overlap's
    // plan is [0.5,1]^2: its corner (0.5,0.5) is the upper cube's vertex on the lower's face, (1,1)
    // the lower cube's vertex under the upper's face, the other two where edges cross.
    const Posed lower(box_vertices({1, 1, 1}, {0.5, 0.5, 0.5}));
    const Posed upper(box_vertices({1, 1, 1}, {1.0, 1.0, 1.49}));
    const auto points = contact(lower, upper);
    ASSERT_EQ(points.size(), 4u);
    int face_vertex = 0, vertex_face = 0, edge_edge = 0;
    for (const ContactGeometry3d& p : points) {
        EXPECT_NEAR(p.overlap_m, 0.01, 1e-14);
        EXPECT_NEAR(p.normal.z, 1.0, 1e-15);
        EXPECT_NEAR(p.point_m.z, 0.995, 1e-14);
        const FeatureKind3d a = feature_kind(p.feature_a), b = feature_kind(p.feature_b);
        if (a == FeatureKind3d::face && b == FeatureKind3d::vertex) {
            ++face_vertex;
            EXPECT_NEAR(p.point_m.x, 0.5, 1e-12);
            EXPECT_NEAR(p.point_m.y, 0.5, 1e-12);
        } else if (a == FeatureKind3d::vertex && b == FeatureKind3d::face) {
            ++vertex_face;
            EXPECT_NEAR(p.point_m.x, 1.0, 1e-12);
            EXPECT_NEAR(p.point_m.y, 1.0, 1e-12);
        } else if (a == FeatureKind3d::edge && b == FeatureKind3d::edge) {
            ++edge_edge;
        }
    }
    EXPECT_EQ(face_vertex, 1);
    EXPECT_EQ(vertex_face, 1);
    EXPECT_EQ(edge_edge, 2);
    // Sorted by keys, and the same keys after a small slide: the history survives.
    for (std::size_t i = 1; i < points.size(); ++i)
        EXPECT_TRUE(points[i - 1].feature_a < points[i].feature_a ||
                    (points[i - 1].feature_a == points[i].feature_a && points[i - 1].feature_b < points[i].feature_b));
    const auto moved = contact(lower, Posed(box_vertices({1, 1, 1}, {1.0003, 0.9998, 1.4901})));
    ASSERT_EQ(moved.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(moved[i].feature_a, points[i].feature_a);
        EXPECT_EQ(moved[i].feature_b, points[i].feature_b);
    }
    // The same contact seen with the bodies swapped: the normal turns, the points stay.
    const auto swapped = contact(upper, lower);
    ASSERT_EQ(swapped.size(), 4u);
    for (const ContactGeometry3d& p : swapped) EXPECT_NEAR(p.normal.z, -1.0, 1e-15);
}

TEST(PolyhedronContact3d, SeparatedBodiesGiveNoPoints) {
    const Posed lower(box_vertices({1, 1, 1}, {0.5, 0.5, 0.5}));
    EXPECT_TRUE(contact(lower, Posed(box_vertices({1, 1, 1}, {1.0, 1.0, 1.51}))).empty());
    EXPECT_TRUE(contact(lower, Posed(box_vertices({1, 1, 1}, {2.01, 0.5, 0.5}))).empty());
    // Crossed edges 1 mm apart: every face axis sees an overlap, only the edge-edge axis separates.
    const double quarter = std::numbers::pi / 4.0;
    const double half_diagonal = 0.5 * std::sqrt(2.0);
    const Posed a(box_vertices({3, 1, 1}, {0, 0, -half_diagonal}, from_rotation_vector({quarter, 0, 0})));
    const Posed b_apart(box_vertices({1, 3, 1}, {0, 0, half_diagonal + 1e-3}, from_rotation_vector({0, quarter, 0})));
    EXPECT_TRUE(contact(a, b_apart).empty());
    const Posed b_touching(
        box_vertices({1, 3, 1}, {0, 0, half_diagonal - 1e-3}, from_rotation_vector({0, quarter, 0})));
    const auto points = contact(a, b_touching);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(feature_kind(points[0].feature_a), FeatureKind3d::edge);
    EXPECT_EQ(feature_kind(points[0].feature_b), FeatureKind3d::edge);
    // The lower box's top edge at z = 0, the upper's bottom edge at z = -1 mm: the point midway.
    EXPECT_NEAR(points[0].overlap_m, 1e-3, 1e-12);
    EXPECT_NEAR(points[0].normal.z, 1.0, 1e-12);
    EXPECT_NEAR(length(points[0].point_m - Vec3{0, 0, -0.5e-3}), 0.0, 1e-12);
}

TEST(GridBroadPhase3d, PairsAreTheBruteForceOnes) {
    // 400 random boxes of mixed sizes and one large slab, some static: the grid's pairs are
    // exactly the overlapping ones, each once, sorted.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> where(0.0, 5.0), size(0.05, 0.6);
    std::vector<Aabb3d> boxes;
    std::vector<std::uint8_t> is_static;
    for (int i = 0; i < 400; ++i) {
        const Vec3 lo{where(random), where(random), where(random)};
        boxes.push_back({lo, lo + Vec3{size(random), size(random), size(random)}});
        is_static.push_back(i % 7 == 0);
    }
    boxes.push_back({{-1, -1, -1}, {6, 6, 0.3}});
    is_static.push_back(1);
    std::vector<BodyPair> pairs;
    GridBroadPhase3d grid;
    grid.find_pairs(boxes, is_static, pairs);
    std::vector<BodyPair> brute;
    for (std::uint32_t a = 0; a < boxes.size(); ++a)
        for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
            if (!(is_static[a] && is_static[b]) && overlaps(boxes[a], boxes[b])) brute.emplace_back(a, b);
    EXPECT_GT(brute.size(), 100u);
    EXPECT_EQ(pairs, brute);
}

}  // namespace
}  // namespace blockdem
