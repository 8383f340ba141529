// The 3-D scenario reader (io/scenario_3d.hpp): each body shape and its placement, the drum
// column, the contact keys shared with 2-D, the table's three components and the azimuth of a
// record's horizontal pair, the derived time step, and the errors naming key and body.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/scenario_3d.hpp"
#include "laws/restitution.hpp"
#include "world/world_3d_start.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;
const std::filesystem::path records_dir = std::filesystem::path(BLOCKDEM_SOURCE_DIR) / "tests/data/records";

// A scenario with a fixed slab (top at z = 0) and the given text after it.
LoadedScenario3d load(const std::string& more) {
    const std::string text = R"(dimension = 3
[simulation]
duration = 0.1
[contact]
kn = 1e6
ks = 1e6
mu = 0.5
[[bodies]]
name = "slab"
kind = "fixed"
shape = "box"
size = [4.0, 4.0, 0.2]
position = [0.0, 0.0, -0.1]
)" + more;
    return load_scenario_3d(toml::parse(text), records_dir / "scenario_3d.toml", {});
}

// The message of the InputError that loading throws ("" if none).
std::string error_of(const std::string& more) {
    try {
        load(more);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// [m] the body's extent along the world axis (0, 1, 2).
double extent_m(const RigidBody3d& b, int axis) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
        const Vec3 v = world_vertex(b, k);
        const double c = axis == 0 ? v.x : axis == 1 ? v.y : v.z;
        lo = std::min(lo, c);
        hi = std::max(hi, c);
    }
    return hi - lo;
}

TEST(Scenario3d, BoxTurnedByARotationVectorInDegrees) {
    const LoadedScenario3d s = load(R"([[bodies]]
name = "block"
shape = "box"
size = [2.0, 1.0, 0.5]
position = [0.5, 0.0, 0.25]
rotation_deg = [0.0, 0.0, 90.0]
density = 100.0
velocity = [1.0, 0.0, 0.0]
)");
    ASSERT_EQ(s.world.bodies.size(), 2u);
    const RigidBody3d& b = s.world.bodies[1];
    EXPECT_EQ(b.name, "block");
    EXPECT_EQ(s.world.kinds[1], BodyKind3d::dynamic);
    EXPECT_NEAR(b.mass_kg, 100.0, 1e-9);
    EXPECT_NEAR(b.position_m.x, 0.5, 1e-12);
    EXPECT_NEAR(b.position_m.z, 0.25, 1e-12);
    // Turned 90 degrees about z: its 2 m edge lies along y.
    EXPECT_NEAR(extent_m(b, 0), 1.0, 1e-12);
    EXPECT_NEAR(extent_m(b, 1), 2.0, 1e-12);
    EXPECT_NEAR(b.velocity_at_t_m_s.x, 1.0, 1e-15);
    EXPECT_NEAR(s.world.gravity_m_s2, 9.81, 0.0);
}

TEST(Scenario3d, PrismOfSidesAndOfAPolygonHaveTheirCentroidAtThePosition) {
    const LoadedScenario3d s = load(R"([[bodies]]
name = "drum"
shape = "prism"
sides = 8
radius = 0.5
height = 0.4
position = [0.0, 0.0, 0.2]
density = 1000.0
[[bodies]]
name = "wedge"
shape = "prism"
polygon = [[0.0, 0.0], [0.6, 0.0], [0.0, 0.3]]
height = 0.2
position = [1.0, 1.0, 0.15]
rotation = [1.5707963267948966, 0.0, 0.0]
density = 1000.0
)");
    const RigidBody3d& drum = s.world.bodies[1];
    EXPECT_EQ(drum.shape.vertices_m.size(), 16u);
    // The regular octagon's area n/2 r^2 sin(2 pi / n) times the height.
    EXPECT_NEAR(drum.mass_kg, 1000.0 * 4.0 * 0.25 * std::sin(2.0 * pi / 8.0) * 0.4, 1e-9);
    EXPECT_NEAR(drum.position_m.z, 0.2, 1e-12);
    EXPECT_NEAR(extent_m(drum, 2), 0.4, 1e-12);
    const RigidBody3d& wedge = s.world.bodies[2];
    EXPECT_NEAR(wedge.mass_kg, 1000.0 * 0.09 * 0.2, 1e-9);
    EXPECT_NEAR(wedge.position_m.x, 1.0, 1e-12);
    EXPECT_NEAR(wedge.position_m.y, 1.0, 1e-12);
    EXPECT_NEAR(wedge.position_m.z, 0.15, 1e-12);
    // Turned a quarter about x: the 0.3 m leg now stands along z, the height along y.
    EXPECT_NEAR(extent_m(wedge, 2), 0.3, 1e-12);
    EXPECT_NEAR(extent_m(wedge, 1), 0.2, 1e-12);
}

TEST(Scenario3d, PolyhedronFromItsVerticesAndADrumColumn) {
    const LoadedScenario3d s = load(R"([[bodies]]
name = "tetra"
shape = "polyhedron"
vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
position = [1.0, 1.0, 0.0]
density = 600.0
[[assemblies]]
name = "c"
type = "drum_column"
drums = 4
sides = 12
radius = 0.25
height = 0.3
base = [-1.0, 0.0, 0.0]
density = 2500.0
)");
    ASSERT_EQ(s.world.bodies.size(), 6u);
    EXPECT_NEAR(s.world.bodies[1].mass_kg, 600.0 / 6.0, 1e-9);
    EXPECT_NEAR(s.world.bodies[1].position_m.x, 1.25, 1e-12);
    for (int k = 0; k < 4; ++k) {
        const RigidBody3d& d = s.world.bodies[2 + k];
        EXPECT_EQ(d.name, "c_" + std::to_string(k + 1));
        EXPECT_NEAR(d.position_m.x, -1.0, 1e-12);
        EXPECT_NEAR(d.position_m.z, 0.15 + 0.3 * k, 1e-12);  // touching: no gap, no overlap
    }
}

TEST(Scenario3d, BrickWallInRunningBond) {
    // Two courses of three bricks in two wythes: the odd course one shorter and half a brick on.
    const LoadedScenario3d s = load(R"([[assemblies]]
name = "w"
type = "brick_wall"
courses = 2
bricks_per_course = 3
wythes = 2
brick = [0.4, 0.2, 0.1]
origin = [-0.6, -0.2, 0.0]
density = 2000.0
)");
    ASSERT_EQ(s.world.bodies.size(), 1u + 3 * 2 + 2 * 2);
    EXPECT_EQ(s.world.bodies[1].name, "w_0_0_0");
    EXPECT_NEAR(s.world.bodies[1].mass_kg, 2000.0 * 0.4 * 0.2 * 0.1, 1e-9);
    EXPECT_NEAR(s.world.bodies[1].position_m.x, -0.4, 1e-12);
    EXPECT_NEAR(s.world.bodies[1].position_m.y, -0.1, 1e-12);
    EXPECT_NEAR(s.world.bodies[1].position_m.z, 0.05, 1e-12);
    const RigidBody3d& odd = s.world.bodies[7];  // course 1, wythe 0, first brick
    EXPECT_EQ(odd.name, "w_1_0_0");
    EXPECT_NEAR(odd.position_m.x, -0.2, 1e-12);
    EXPECT_NEAR(odd.position_m.z, 0.15, 1e-12);
    EXPECT_EQ(s.world.bodies.back().name, "w_1_1_1");
}

TEST(Scenario3d, BrickWallOfOneBrickACourseIsRefusedAboveOneCourse) {
    // Its odd courses, one brick shorter, were empty: the bricks above floated.
    const std::string wall = R"([[assemblies]]
name = "w"
type = "brick_wall"
bricks_per_course = 1
brick = [0.4, 0.2, 0.2]
origin = [0.0, 0.0, 0.0]
density = 2000.0
)";
    const std::string three = error_of(wall + "courses = 3\n");
    EXPECT_NE(three.find("key 'assemblies.w.bricks_per_course': is 1 with 3 courses: in running bond the odd courses, shifted "
                         "half a brick, hold one brick fewer, so they would be empty and the bricks above would float"),
              std::string::npos)
        << three;
    EXPECT_NE(error_of(wall + "courses = 2\n").find("bricks_per_course"), std::string::npos);
    EXPECT_EQ(load(wall + "courses = 1\n").world.bodies.size(), 2u);  // one brick (and the table)
}

TEST(Scenario3d, AssemblyTooLargeForTheMachineIsRefusedBeforeGenerating) {
    // 1e5 courses of 12 bricks in 2 wythes were generated and ran the machine out of memory.
    const std::string wall = error_of(R"([[assemblies]]
name = "w"
type = "brick_wall"
courses = 100000
bricks_per_course = 100000
wythes = 2
brick = [0.4, 0.2, 0.1]
origin = [0.0, 0.0, 0.0]
density = 2000.0
)");
    EXPECT_NE(wall.find("key 'assemblies.w.courses': the assembly would have about 2e+10 blocks (courses x bricks_per_course x "
                        "wythes = 100000 x 100000 x 2), needing about 500.0 TB at 25.0 kB a block; the limit is"),
              std::string::npos)
        << wall;
}

TEST(Scenario3d, ContactKeysAreReadAsIn2d) {
    const LoadedScenario3d s = load(R"([[bodies]]
name = "block"
shape = "box"
size = [0.2, 0.2, 0.2]
position = [0.0, 0.0, 0.1]
density = 100.0
)");
    EXPECT_EQ(s.world.contact.kn_N_m, 1e6);
    EXPECT_EQ(s.world.contact.mu, 0.5);
    EXPECT_EQ(s.world.contact.h_s, 1.0);  // the 2-D default
    const LoadedScenario3d e = load_scenario_3d(
        toml::parse("dimension = 3\n[simulation]\nduration = 0.1\n[contact]\nkn = 1e6\nks = 2e6\nfriction_deg = 30\n"
                    "e = 0.4\nh_s = 0.3\n[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\nposition = [0, 0, 5]\n"
                    "density = 1.0\n"),
        "x.toml", {"simulation.dt=1e-4"});
    EXPECT_NEAR(e.world.contact.mu, std::tan(pi / 6.0), 1e-15);
    EXPECT_EQ(e.world.contact.h_n, damping_ratio_for(0.4, RestitutionMeaning::paper, ContactTermination::no_tension));
    EXPECT_EQ(e.world.contact.h_s, 0.3);
    EXPECT_EQ(e.world.dt_s, 1e-4);
}

TEST(Scenario3d, TableComponentsAndTheAzimuthOfARecordsPair) {
    const std::string block = R"([[bodies]]
name = "block"
shape = "box"
size = [0.2, 0.2, 0.2]
position = [0.0, 0.0, 0.1]
density = 100.0
)";
    const LoadedScenario3d sine = load(block + R"([table_motion.x]
type = "sine"
amplitude = 2.0
period = 0.5
[table_motion.z]
type = "sine"
amplitude = 0.1
unit = "g"
period = 0.25
)");
    EXPECT_NEAR(sample(sine.world.table.x, 0.125).acceleration_m_s2, 2.0, 1e-12);
    EXPECT_EQ(sample(sine.world.table.y, 0.125).acceleration_m_s2, 0.0);
    EXPECT_NEAR(sample(sine.world.table.z, 0.0625).acceleration_m_s2, 0.980665, 1e-12);
    const std::string record = R"([table_motion.record]
file = "jma_sample.csv"
components = ["NS", "EW", "UD"]
)";
    const LoadedScenario3d plain = load(block + "[table_motion]\n" + record);
    const LoadedScenario3d turned = load(block + "[table_motion]\nazimuth_deg = 30\n" + record);
    const double c = std::cos(pi / 6.0), s = std::sin(pi / 6.0);
    for (double t : {0.02, 0.055, 0.095}) {  // within the 0.11 s record
        const double ns = sample(plain.world.table.x, t).acceleration_m_s2;
        const double ew = sample(plain.world.table.y, t).acceleration_m_s2;
        EXPECT_NE(ns, 0.0);
        EXPECT_NEAR(sample(turned.world.table.x, t).acceleration_m_s2, c * ns - s * ew, 1e-12);
        EXPECT_NEAR(sample(turned.world.table.y, t).acceleration_m_s2, s * ns + c * ew, 1e-12);
        EXPECT_NEAR(sample(turned.world.table.x, t).displacement_m,
                    c * sample(plain.world.table.x, t).displacement_m - s * sample(plain.world.table.y, t).displacement_m,
                    1e-12);
        EXPECT_EQ(sample(turned.world.table.z, t).acceleration_m_s2, sample(plain.world.table.z, t).acceleration_m_s2);
    }
    // The file's third column is the vertical one: -0.1 gal at t = 0.01 s (its second row).
    EXPECT_NEAR(sample(plain.world.table.z, 0.01).acceleration_m_s2, -0.1 * 0.01, 1e-12);
    EXPECT_NE(error_of(block + "[table_motion]\nazimuth_deg = 30\n[table_motion.x]\ntype = \"sine\"\namplitude = 1.0\n"
                               "period = 1.0\n")
                  .find("table_motion.azimuth_deg"),
              std::string::npos);
}

const std::string motion_block = "[[bodies]]\nname = \"block\"\nshape = \"box\"\nsize = [0.2, 0.2, 0.2]\n"
                                 "position = [0.0, 0.0, 0.1]\ndensity = 100.0\n";

// As in 2-D (test_scenario_errors.cpp): the table would be moving when the run begins.
TEST(Scenario3d, MotionStartBeforeZeroIsRefused) {
    const std::string x = "[table_motion.x]\ntype = \"one_sine\"\namplitude = 1.0\nperiod = 1.0\n";
    const std::string start = error_of(motion_block + x + "start = -5\n");
    EXPECT_NE(start.find("key 'table_motion.x.start': must be >= 0 [s], got -5: a motion starts at rest"), std::string::npos)
        << start;
    EXPECT_EQ(error_of(motion_block + x + "start = 0.5\n"), "");
}

// As in 2-D: a period under 4 time steps, here of the derived dt, known only after the motion.
TEST(Scenario3d, MotionPeriodUnderFourTimeStepsIsRefused) {
    const std::string period = error_of(motion_block + "[table_motion.z]\ntype = \"sine\"\namplitude = 1.0\nperiod = 1e-12\n");
    EXPECT_NE(period.find("key 'table_motion.z.period': the period 1e-12 s spans"), std::string::npos) << period;
    EXPECT_NE(period.find("it must span at least 4"), std::string::npos) << period;
}

TEST(Scenario3d, DerivedTimeStepIsHalfTheStartBoundOnWholeOutputSteps) {
    const LoadedScenario3d s = load(R"([[bodies]]
name = "block"
shape = "box"
size = [0.2, 0.2, 0.2]
position = [0.0, 0.0, 0.1]
density = 100.0
)");
    const CriticalTimeStep3d bound = start_time_step_3d(s.world).highest_mode;
    EXPECT_EQ(bound.dt_s, s.critical_dt_s);
    // Placed touching, the cube has no point at t = 0; the probe finds its four corners. With
    // kn only (ks 1e-6 N/m, no dashpots), the bound is tests/validation/test_world_3d.cpp's
    // hand-computed row sum: 4 kn (sqrt(6)/2)(1 + sqrt(6)) / m, dt = 2 / sqrt of it.
    const LoadedScenario3d cube = load_scenario_3d(
        toml::parse(R"(dimension = 3
[simulation]
duration = 0.1
[contact]
kn = 1e6
ks = 1e-6
mu = 0.6
e = 1.0
h_s = 0.0
[[bodies]]
name = "slab"
kind = "fixed"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "cube"
shape = "box"
size = [0.5, 0.5, 0.5]
position = [0.0, 0.0, 0.25]
density = 800.0
)"),
        "cube.toml", {});
    const double lambda = 4.0 * 1e6 * (std::sqrt(6.0) / 2.0) * (1.0 + std::sqrt(6.0)) / 100.0;
    EXPECT_NEAR(start_time_step_3d(cube.world).proven.dt_s, 2.0 / std::sqrt(lambda), 1e-9 * cube.critical_dt_s);
    // The limit dt is checked against is the highest mode's: the cube's rocking on its four
    // corners' normal springs at lever a = 0.25 m, 4 kn a^2 / I with I = m (0.5^2 + 0.5^2) / 12,
    // is 6 kn / m (its bounce 4 kn / m): dt = 2 / sqrt(6 kn / m), 1.68 times the proven bound.
    EXPECT_NEAR(cube.critical_dt_s, 2.0 / std::sqrt(6.0 * 1e6 / 100.0), 1e-3 * cube.critical_dt_s);
    EXPECT_LE(s.world.dt_s, 0.5 * bound.dt_s);
    EXPECT_GT(s.world.dt_s, 0.45 * bound.dt_s);
    const double per_output = 1e-3 / s.world.dt_s;
    EXPECT_NEAR(per_output, std::round(per_output), 1e-9);
    // A body in the air over the slab is taken as landing flat on it (world/world_3d_start.hpp):
    // the same limit as the same cube placed on the slab, whose probe finds those four corners.
    const char* cube_at = "[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [0.2, 0.2, 0.2]\nposition = [0, 0, {}]\n"
                          "density = 100.0\n";
    const LoadedScenario3d air = load(fmt::format(fmt::runtime(cube_at), 5.0));
    const LoadedScenario3d placed = load(fmt::format(fmt::runtime(cube_at), 0.1));
    EXPECT_NEAR(air.critical_dt_s, placed.critical_dt_s, 1e-4 * placed.critical_dt_s);
    // With nothing to land on, no limit: dt must be given.
    try {
        load_scenario_3d(toml::parse("dimension = 3\n[simulation]\nduration = 0.1\n[contact]\nkn = 1e6\nks = 1e6\nmu = 0.5\n"
                                     "[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\nposition = [0, 0, 5]\n"
                                     "density = 1.0\n"),
                         "air.toml", {});
        ADD_FAILURE() << "a body with nothing to land on got a time step";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("give simulation.dt"), std::string::npos) << e.what();
    }
}

TEST(Scenario3d, BadInputNamesTheKeyAndTheBody) {
    const std::string e1 = error_of("[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\nposition = [0, 0, 0.5]\n"
                                    "density = 1.0\nvelocty = [0, 0, 0]\n");
    EXPECT_NE(e1.find("bodies.b.velocty"), std::string::npos) << e1;
    EXPECT_NE(e1.find("velocity"), std::string::npos) << e1;
    const std::string e2 = error_of("[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\nposition = [0, 0, 0.5]\n");
    EXPECT_NE(e2.find("body 'b' needs 'density'"), std::string::npos) << e2;
    const std::string e3 = error_of("[[bodies]]\nname = \"flat\"\nshape = \"polyhedron\"\n"
                                    "vertices = [[0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]]\ndensity = 1.0\n");
    EXPECT_NE(e3.find("body 'flat'"), std::string::npos) << e3;
    const std::string e4 = error_of("[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\nposition = [0, 0, 0.5]\n"
                                    "density = 1.0\nrotation = [0, 0, 1]\nrotation_deg = [0, 0, 1]\n");
    EXPECT_NE(e4.find("rotation_deg"), std::string::npos) << e4;
    const std::string e5 = error_of("[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1]\nposition = [0, 0, 0.5]\n"
                                    "density = 1.0\n");
    EXPECT_NE(e5.find("bodies.b.size"), std::string::npos) << e5;
    // A nan among the vertices was reported as vertices lying in one plane.
    const std::string nan_vertex = error_of("[[bodies]]\nname = \"tet\"\nshape = \"polyhedron\"\ndensity = 1000.0\n"
                                            "vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, nan]]\n");
    EXPECT_NE(nan_vertex.find("key 'bodies.tet.vertices': point 3 holds a value that is not a finite number"), std::string::npos)
        << nan_vertex;
    // A concave prism polygon was named by a vertex of the centred prism the user never wrote.
    const std::string concave = error_of("[[bodies]]\nname = \"pr\"\nshape = \"prism\"\nheight = 0.5\ndensity = 1000.0\n"
                                         "position = [0, 0, 0.25]\npolygon = [[0, 0], [0.2, 0], [0.1, 0.05], [0.2, 0.2], [0, 0.2]]\n");
    EXPECT_NE(concave.find("key 'bodies.pr.polygon': is not a convex polygon: not strictly convex at vertex 2 (0.1, 0.05) m"),
              std::string::npos)
        << concave;
    // A tetrahedron's faces listed, one of them inverted (seen from outside it runs clockwise).
    const std::string tetra = "[[bodies]]\nname = \"tet\"\nshape = \"polyhedron\"\n"
                              "vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\ndensity = 1.0\n";
    EXPECT_EQ(error_of(tetra + "faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"), "");
    const std::string e6 = error_of(tetra + "faces = [[0, 1, 2], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n");
    EXPECT_NE(e6.find("body 'tet'"), std::string::npos) << e6;
    EXPECT_NE(e6.find("face 0"), std::string::npos) << e6;
    const std::string e7 = error_of("[[bodies]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\nposition = [0, 0, 0.5]\n"
                                    "density = 1.0\n[output]\nvtk_contact = true\n");
    EXPECT_NE(e7.find("output.vtk_contact"), std::string::npos) << e7;  // (report and vtk_contacts are read in 3-D)
    EXPECT_THROW(scenario_dimension(toml::parse("dimension = 4"), "x.toml"), InputError);
    EXPECT_EQ(scenario_dimension(toml::parse("title = \"t\""), "x.toml"), 2);
}

}  // namespace
}  // namespace blockdem
