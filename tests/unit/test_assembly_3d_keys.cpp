// The generated 3-D assemblies through the scenario keys (io/assembly_3d_keys.hpp): the rock
// mass (block count, ground by face and by base, names) and the random packing (no overlap at the
// start, the same bytes for the same seed, the volume fraction), and bad input refused naming
// the file and the key.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include <fmt/format.h>

#include "geometry/polyhedron.hpp"
#include "io/input_error.hpp"
#include "io/scenario_3d.hpp"
#include "scenes/random_packing_3d.hpp"

namespace blockdem {
namespace {

// dt below the start bound of the 100-block rock mass with every joint counted touching (5.99e-5 s:
// the start probe counts faces, edges and corners placed touching, world/world_3d_start.hpp).
const std::string head = R"(dimension = 3
[simulation]
duration = 0.1
dt = 2.5e-5
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
)";

// A 10 x 6 x 4 m box cut every 2 m along x, 1.5 m along y, 1 m along z from 0.3 m, plus `more`
// in the assembly's table and `last_set` in the last joint set's.
std::string rock_mass(const std::string& more, const std::string& last_set = "") {
    return head + R"([[assemblies]]
name = "rock"
type = "rock_mass"
region_min = [0.0, 0.0, 0.0]
region_max = [10.0, 6.0, 4.0]
density = 2600.0
)" + more + R"(
[[assemblies.joint_sets]]
dip_direction_deg = 90.0
dip_deg = 90.0
spacing = 2.0
[[assemblies.joint_sets]]
dip_direction_deg = 0.0
dip_deg = 90.0
spacing = 1.5
[[assemblies.joint_sets]]
dip_direction_deg = 0.0
dip_deg = 0.0
spacing = 1.0
origin = [0.0, 0.0, 0.3]
)" + last_set;
}

std::string packing(const std::string& more) {
    return head + R"([[assemblies]]
name = "pack"
type = "random_packing"
container_min = [0.0, 0.0, 0.0]
container_max = [1.0, 0.8, 1.2]
min_size = 0.06
max_size = 0.12
density = 2000.0
)" + more;
}

LoadedScenario3d load(const std::string& text) { return load_scenario_3d(toml::parse(text), "assemblies.toml", {}); }

std::string error_of(const std::string& text) {
    try {
        load(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::size_t count_of(const World3d& w, BodyKind3d kind) {
    std::size_t n = 0;
    for (BodyKind3d k : w.kinds) n += k == kind ? 1 : 0;
    return n;
}

TEST(RockMassKeys, BlocksTheirGroundAndNames) {
    const LoadedScenario3d s = load(rock_mass("fixed = [\"bottom\"]\n"));
    ASSERT_EQ(s.world.bodies.size(), 100u);              // 5 x 4 x 5
    EXPECT_EQ(count_of(s.world, BodyKind3d::fixed), 20u);  // the lowest layer, on the bottom face
    EXPECT_EQ(s.world.bodies.front().name, "rock_1");
    EXPECT_EQ(s.world.bodies.back().name, "rock_100");
    EXPECT_NEAR(s.world.bodies.front().position_m.z, 0.15, 1e-12);  // in order of height
    double mass_kg = 0.0;
    for (const RigidBody3d& b : s.world.bodies) mass_kg += b.mass_kg;
    EXPECT_NEAR(mass_kg / (2600.0 * 240.0), 1.0, 1e-12);
    ASSERT_EQ(s.assembly_notes.size(), 1u);
    EXPECT_NE(s.assembly_notes[0].find("100 blocks (20 fixed, 80 free)"), std::string::npos) << s.assembly_notes[0];

    // base: the layer from 0.3 to 1.3 m has its centroids at 0.8 m; the back wall (east) too.
    const LoadedScenario3d b = load(rock_mass("base = 1.0\nfixed = [\"east\"]\nground = \"driven\"\n"));
    EXPECT_EQ(count_of(b.world, BodyKind3d::driven), 40u + 12u);
    EXPECT_EQ(count_of(b.world, BodyKind3d::fixed), 0u);
}

TEST(RockMassKeys, ASlopeFaceIsNamedByWhereItFaces) {
    // The slope face of the prism faces west and up (normal (-8, 0, 4)): "west".
    const std::string text = head + R"([[assemblies]]
name = "slope"
type = "rock_mass"
region_vertices = [[0, 0, 0], [12, 0, 0], [12, 0, 8], [4, 0, 8], [0, 4, 0], [12, 4, 0], [12, 4, 8], [4, 4, 8]]
density = 2600.0
fixed = ["west"]
[[assemblies.joint_sets]]
dip_direction_deg = 90.0
dip_deg = 90.0
spacing = 3.0
)";
    const LoadedScenario3d s = load(text);
    ASSERT_EQ(s.world.bodies.size(), 4u);  // joints at x = 3, 6, 9
    EXPECT_EQ(count_of(s.world, BodyKind3d::fixed), 2u);  // x from 0 to 3 and 3 to 6 reach the face (it ends at x = 4)
}

TEST(RockMassKeys, BadInputNamesTheFileAndKey) {
    const auto expect_error = [](const std::string& text, const std::string& key) {
        const std::string e = error_of(text);
        EXPECT_NE(e.find("assemblies.toml"), std::string::npos) << e;
        EXPECT_NE(e.find(key), std::string::npos) << e;
    };
    expect_error(rock_mass("", "dip_deg_typo = 3\n"), "unknown key");
    expect_error(rock_mass("colour = 3\n"), "unknown key");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = 0\ndip_deg = 95\nspacing = 1\n"), "'assemblies.rock.joint_sets[3].dip_deg'");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = 360\ndip_deg = 5\nspacing = 1\n"), "dip_direction_deg");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = -1\ndip_deg = 5\nspacing = 1\n"), "dip_direction_deg");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = 0\ndip_deg = 5\nspacing = 0\n"), "spacing");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = 0\ndip_deg = 5\nspacing = 1e-5\n"), "blocks");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = 0\ndip_deg = 5\nspacing = 1\norigin = [0, 0, 1e300]\n"), "2^52");
    expect_error(rock_mass("fixed = [\"up\"]\n"), "fixed");
    expect_error(rock_mass("region_vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"), "region_vertices");
    // A vertex inside the hull of the others: not a convex region.
    const std::string concave = head + R"([[assemblies]]
name = "r"
type = "rock_mass"
region_vertices = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2], [0.2, 0.2, 0.2]]
density = 2600.0
[[assemblies.joint_sets]]
dip_direction_deg = 0.0
dip_deg = 0.0
spacing = 1.0
)";
    expect_error(concave, "not a convex polyhedron");
    expect_error(rock_mass("", "[[assemblies.joint_sets]]\ndip_direction_deg = 0\ndip_deg = 5\n"), "spacing");
}

TEST(RandomPackingKeys, PlacedWithoutOverlapInTheContainer) {
    // Loading runs the start check (no two bodies overlap, world/world_3d_start.hpp).
    const LoadedScenario3d s = load(packing("count = 40\nseed = 7\n"));
    ASSERT_EQ(s.world.bodies.size(), 45u);  // and the floor and four walls
    EXPECT_EQ(count_of(s.world, BodyKind3d::driven), 5u);
    double solids_m3 = 0.0;
    for (std::size_t i = 0; i < 40; ++i) {
        const RigidBody3d& b = s.world.bodies[i];
        solids_m3 += b.mass_kg / 2000.0;
        for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
            const Vec3 v = world_vertex(b, k);
            EXPECT_TRUE(v.x > 0.0 && v.x < 1.0 && v.y > 0.0 && v.y < 0.8 && v.z > 0.0 && v.z < 1.2) << b.name;
        }
    }
    scenes::RandomPacking3dDef def{.count = 40, .min_size_m = 0.06, .max_size_m = 0.12,
                                   .container_max_m = {1.0, 0.8, 1.2}, .seed = 7};
    const scenes::RandomPacking3d p = scenes::random_packing_3d(def);
    EXPECT_NEAR(p.volume_fraction, solids_m3 / 0.96, 1e-12);
    EXPECT_NE(s.assembly_notes.at(0).find(fmt::format("volume fraction {:.4f}", p.volume_fraction)), std::string::npos)
        << s.assembly_notes[0];
}

TEST(RandomPackingKeys, TheSameSeedGivesTheSameBytes) {
    scenes::RandomPacking3dDef def{.count = 60, .shape = scenes::PackedShape::hull, .min_size_m = 0.05,
                                   .max_size_m = 0.1, .hull_points = 10, .container_max_m = {0.8, 0.8, 1.0}, .seed = 42};
    const scenes::RandomPacking3d a = scenes::random_packing_3d(def);
    const scenes::RandomPacking3d b = scenes::random_packing_3d(def);
    ASSERT_EQ(a.bodies_m.size(), 60u);
    for (std::size_t i = 0; i < a.bodies_m.size(); ++i) {
        ASSERT_EQ(a.bodies_m[i].size(), b.bodies_m[i].size());
        EXPECT_EQ(std::memcmp(a.bodies_m[i].data(), b.bodies_m[i].data(), a.bodies_m[i].size() * sizeof(Vec3)), 0);
        EXPECT_NO_THROW(convex_polyhedron(a.bodies_m[i]));  // every point a corner
    }
    def.seed = 43;
    const scenes::RandomPacking3d c = scenes::random_packing_3d(def);
    EXPECT_NE(std::memcmp(a.bodies_m[0].data(), c.bodies_m[0].data(), sizeof(Vec3)), 0);
    // Through the scenario: the hulls load (the start check passes) and the bodies are the same bytes.
    // (At dt = 2.5e-6 s: pack_19, landing flat on the container's floor, has a limit of 5.8e-6 s,
    // world/world_3d_start.hpp; run at 2.5e-5 s its live limit falls to 3.4e-6 s, docs/3d.md.)
    std::string text = packing("count = 30\nshape = \"hull\"\nhull_points = 10\nseed = 42\ncontainer = \"fixed\"\n");
    text.replace(text.find("dt = 2.5e-5"), 11, "dt = 2.5e-6");
    const LoadedScenario3d s1 = load(text), s2 = load(text);
    for (std::size_t i = 0; i < s1.world.bodies.size(); ++i) {
        EXPECT_EQ(std::memcmp(&s1.world.bodies[i].position_m, &s2.world.bodies[i].position_m, sizeof(Vec3)), 0);
        EXPECT_EQ(std::memcmp(&s1.world.bodies[i].orientation, &s2.world.bodies[i].orientation, sizeof(Quaternion)), 0);
    }
}

TEST(RandomPackingKeys, APackingThatDoesNotFitIsRefused) {
    // Cells of sqrt(3) 0.12 m (1.001): 4 x 3 x 5 = 60 of them.
    EXPECT_NO_THROW(load(packing("count = 60\n")));
    const std::string e = error_of(packing("count = 61\n"));
    EXPECT_NE(e.find("assemblies.toml"), std::string::npos) << e;
    EXPECT_NE(e.find("'assemblies.pack.count'"), std::string::npos) << e;
    EXPECT_NE(e.find("= 60 cells"), std::string::npos) << e;
    std::string smaller = packing("count = 5\n");
    smaller.replace(smaller.find("max_size = 0.12"), 15, "max_size = 0.05");
    EXPECT_NE(error_of(smaller).find("'assemblies.pack.max_size'"), std::string::npos) << error_of(smaller);
    EXPECT_NE(error_of(packing("count = 5\nshape = \"ball\"\n")).find("shape"), std::string::npos);
    EXPECT_NE(error_of(packing("count = 5\nhull_points = 8\n")).find("unknown key"), std::string::npos);
}

}  // namespace
}  // namespace blockdem
