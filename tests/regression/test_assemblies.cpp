// Generators (scenes/assemblies.hpp): every block convex, no two blocks overlapping, and the
// blocks tiling the region: their areas sum to the region's area within 1e-9 (relative).
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/convex_decomposition.hpp"
#include "geometry/half_plane_clip.hpp"
#include "geometry/polygon.hpp"
#include "io/scenario.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem::scenes {
namespace {

double total_area(const std::vector<Polygon>& blocks) {
    double sum = 0.0;
    for (const Polygon& b : blocks) sum += polygon_area(b);
    return sum;
}

// Area of the intersection of two convex polygons: a clipped by every edge of b.
double overlap_area(const Polygon& a, const Polygon& b) {
    Polygon inside = a;
    for (std::size_t i = 0; i < b.size() && !inside.empty(); ++i) {
        const Vec2 edge = b[(i + 1) % b.size()] - b[i];
        inside = clip_convex(inside, half_plane_through(b[i], Vec2{edge.y, -edge.x}));
    }
    return inside.empty() ? 0.0 : polygon_area(inside);
}

void expect_valid_tiling(const std::vector<Polygon>& blocks, double region_area_m2) {
    ASSERT_FALSE(blocks.empty());
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const auto problem = convexity_problem(blocks[i]);
        EXPECT_FALSE(problem) << "block " << i << ": " << problem.value_or("");
    }
    EXPECT_NEAR(total_area(blocks), region_area_m2, 1e-9 * region_area_m2);
    // Pairwise: shared edges give zero-area intersections; anything more is an overlap.
    for (std::size_t i = 0; i < blocks.size(); ++i)
        for (std::size_t j = i + 1; j < blocks.size(); ++j)
            EXPECT_LT(overlap_area(blocks[i], blocks[j]), 1e-12 * region_area_m2) << "blocks " << i << " and " << j;
}

TEST(Assemblies, ColumnStacksDrumsOfGivenSizes) {
    const auto drums = block_column({{0.6, 0.5}, {0.55, 0.5}, {0.5, 0.4}}, {1.0, 0.0});
    ASSERT_EQ(drums.size(), 3u);
    EXPECT_DOUBLE_EQ(drums[2][2].y, 1.4);  // top of the third drum
    expect_valid_tiling(drums, 0.6 * 0.5 + 0.55 * 0.5 + 0.5 * 0.4);
}

TEST(Assemblies, WallWithWindowAndDoorTilesTheWallMinusItsOpenings) {
    WallSpec w;
    w.length_m = 2.1;  // not a whole number of bricks: end pieces join their neighbours
    w.courses = 12;
    w.openings = {{0.3, 0.5, 0.45, 0.4, 0.1}, {1.3, 0.0, 0.4, 0.9, 0.1}};
    const auto bricks = masonry_wall(w);
    // Openings are rounded to whole courses: the window spans courses 5-8 (y 0.5 to 0.9).
    expect_valid_tiling(bricks, 2.1 * 1.2 - 0.45 * 0.4 - 0.4 * 0.9);
    for (const Polygon& b : bricks) EXPECT_GE(b[1].x - b[0].x, 0.25 * 0.2 - 1e-12);
}

TEST(Assemblies, SteppedWallMatchesTheS3Layout) {
    const Model s3 = s3_wall_scene(100);
    ASSERT_EQ(s3.bodies.size(), 101u);  // the table and 100 bricks
    // C = round(sqrt(200)) = 14: the second row starts half a brick in.
    EXPECT_DOUBLE_EQ(s3.bodies[15].vertices_m[0].x, 0.1);
    EXPECT_DOUBLE_EQ(s3.bodies[15].vertices_m[0].y, 0.1);
}

TEST(Assemblies, JointedRockMassInANonConvexSlopeTilesIt) {
    RockMassSpec spec;
    spec.region_m = slope_region(2.0, 6.0, 60.0, 3.0, 4.0);
    spec.joint_sets = {JointSet{35.0, 0.7, 0.3, 5.0, {0.0, 0.0}}, JointSet{110.0, 0.9, 0.3, 5.0, {0.2, 0.1}}};
    spec.seed = 11;
    const GeneratedBlocks rock = jointed_rock_mass(spec);
    EXPECT_EQ(rock.dropped, 0u);
    EXPECT_GT(rock.polygons.size(), 60u);
    expect_valid_tiling(rock.polygons, std::abs(polygon_area(spec.region_m)));
    // The same seed gives the same blocks; another seed, other blocks.
    EXPECT_EQ(jointed_rock_mass(spec).polygons, rock.polygons);
    spec.seed = 12;
    EXPECT_NE(jointed_rock_mass(spec).polygons, rock.polygons);
}

TEST(Assemblies, ConvexDecompositionOfAnLShape) {
    const Polygon l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const auto pieces = convex_decomposition(l);
    EXPECT_EQ(pieces.size(), 2u);
    expect_valid_tiling(pieces, 3.0);
}

TEST(Assemblies, VoronoiPackingTilesANonConvexRegion) {
    VoronoiSpec spec;
    spec.region_m = {{0, 0}, {3, 0}, {3, 1}, {1.5, 1.2}, {1, 2}, {0, 2}};
    spec.cell_size_m = 0.25;
    spec.seed = 3;
    const GeneratedBlocks cells = voronoi_packing(spec);
    EXPECT_EQ(cells.dropped, 0u);
    EXPECT_GT(cells.polygons.size(), 50u);
    expect_valid_tiling(cells.polygons, polygon_area(spec.region_m));
}

TEST(Assemblies, ScenarioKeysGenerateBlocksAndSettling) {
    const toml::table root = toml::parse(R"(
[simulation]
duration = 0.1
dt = 1e-4
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
e = 0.5
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 4.0
height = 0.2
center = [1.0, -0.1]
[[assemblies]]
type = "wall"
name = "brick"
density = 2000.0
length = 1.0
courses = 3
[[assemblies.openings]]
x = 0.4
y = 0.0
width = 0.2
height = 0.1
[[assemblies]]
type = "column"
name = "drum"
density = 2500.0
base_center = [3.0, 0.0]
count = 2
width = 0.4
height = 0.5
[settling]
kinetic_ratio = 1e-6
)");
    const Model m = read_model(root, "test.toml", ".");
    // Courses of 5 bricks (minus one at the opening), 4 + 2 half bricks, 5; 2 drums; the table.
    EXPECT_EQ(m.bodies.size(), 1u + (4u + 6u + 5u) + 2u);
    EXPECT_EQ(m.bodies[1].name, "brick0");
    EXPECT_EQ(m.bodies.back().name, "drum1");
    ASSERT_TRUE(m.settling);
    EXPECT_DOUBLE_EQ(m.settling->kinetic_ratio, 1e-6);
}

TEST(Assemblies, ScenarioKeysRejectAMisspelledKey) {
    const toml::table root = toml::parse(R"(
[simulation]
duration = 0.1
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
[[assemblies]]
type = "voronoi"
name = "fill"
density = 2000.0
region = [[0, 0], [1, 0], [1, 1], [0, 1]]
cell_sise = 0.2
)");
    try {
        read_model(root, "test.toml", ".");
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("cell_size"), std::string::npos) << e.what();
    }
}

}  // namespace
// Each assembly is its own collapse group and "all" is every block's: an assembly named "all", or
// two with one name (a column "d" and a column "d" elsewhere make blocks d0, d1 and d0, d1: the
// body names refuse that, but a wall "d" and a column "d" would not clash), are refused by name.
TEST(Assemblies, AssemblyNamedAllOrTwiceIsRefusedByName) {
    const auto read_with = [](const std::string& first, const std::string& second) {
        const std::string text = R"(
[simulation]
duration = 0.1
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
[[assemblies]]
type = "column"
name = ")" + first + R"("
density = 2500.0
base_center = [0.0, 0.0]
count = 2
width = 0.4
height = 0.5
[[assemblies]]
type = "wall"
name = ")" + second + R"("
density = 2000.0
length = 1.0
courses = 1
origin = [3.0, 0.0]
)";
        try {
            read_model(toml::parse(text), "test.toml", ".");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(read_with("drum", "wall"), "");
    const std::string all = read_with("all", "wall");
    EXPECT_NE(all.find("assemblies"), std::string::npos) << all;
    EXPECT_NE(all.find("'all' names the collapse summary"), std::string::npos) << all;
    const std::string twice = read_with("d", "d");
    EXPECT_NE(twice.find("another assembly is named 'd'"), std::string::npos) << twice;
}

}  // namespace blockdem::scenes
