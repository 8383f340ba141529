// A 3-D state file (io/state_file_3d.hpp): a world saved between two steps and restored into a
// fresh world of the same scenario goes on bit for bit as the world that never stopped (bodies,
// contact points with their keys and shear history, ledger); the monitor's peaks come back; a
// state is refused, naming the file, by a scenario with another body or another dt.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <string>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/scenario_3d.hpp"
#include "io/state_file_3d.hpp"
#include "support/bit_checks.hpp"
#include "world/external_loads_3d.hpp"
#include "world/run_checks_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;
using testing::expect_same_loads;
using testing::same_bits;

// A block tilted on a shaken slab: it rocks and slides, so every kind of history is live.
// extra_bodies: more [[bodies]] tables, appended.
LoadedScenario3d load(const std::string& block_name = "block", const std::string& dt = "",
                      const std::string& extra_bodies = "") {
    const std::string text = fmt::format(R"(dimension = 3
[simulation]
duration = 0.2
{}
[contact]
kn = 1e6
ks = 1e6
mu = 0.3
e = 0.5
[[bodies]]
name = "slab"
kind = "driven"
shape = "box"
size = [4.0, 4.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "{}"
shape = "box"
size = [0.3, 0.2, 0.6]
position = [0.0, 0.0, 0.3]
density = 2000.0
[table_motion.x]
type = "sine"
amplitude = 0.5
unit = "g"
period = 0.1
[table_motion.y]
type = "sine"
amplitude = 0.3
unit = "g"
period = 0.07
{}
)",
                                         dt, block_name, extra_bodies);
    return load_scenario_3d(toml::parse(text), "state_3d.toml", {});
}

void advance(World3d& w, ResponseMonitor3d& monitor, int steps) {
    const std::vector<double> widths_m = least_widths_m(w);
    for (int i = 0; i < steps; ++i) {
        step_begin(w);
        monitor.update(w);
        watch_overlap_3d(w, widths_m, 0.25);  // the run's deepest overlap, kept in the state
        step_end(w);
    }
}


class StateFile3dTest : public ::testing::Test {
protected:
    fs::path dir_ = fs::temp_directory_path() / fmt::format("blockdem_state_3d_test_{}", ::getpid());
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }

    // The whole run's world after 400 steps, and a world saved after 200 and restored.
    fs::path save_after(LoadedScenario3d& s, ResponseMonitor3d& monitor, int steps) {
        advance(s.world, monitor, steps);
        const fs::path file = dir_ / "t.h5";
        Monitor3dStatePart part(monitor);
        write_state_file(file, 3, s.world.time_s, s.world.steps, StateFileInfo{}, [&](StateGroup& root) { write_world_3d(root, s.world); },
                         {&part});
        return file;
    }
};

TEST_F(StateFile3dTest, ARestoredWorldGoesOnBitForBit) {
    LoadedScenario3d whole = load();
    ResponseMonitor3d whole_monitor(whole.world);
    advance(whole.world, whole_monitor, 400);

    LoadedScenario3d first = load();
    ResponseMonitor3d first_monitor(first.world);
    const fs::path file = save_after(first, first_monitor, 200);
    ASSERT_GT(first.world.contacts.size(), 0u);
    bool any_shear = false;
    for (const ContactPoint3d& c : first.world.contacts) any_shear = any_shear || length(c.shear.spring_n) > 0.0;
    ASSERT_TRUE(any_shear) << "the saved points carry no shear history: the test would not test it";

    LoadedScenario3d second = load();
    ResponseMonitor3d second_monitor(second.world);
    const StateFile state(file);
    EXPECT_EQ(state.dimension(), 3);
    // The points' dashpot masses, which this build makes from the table and does not read, are
    // still written: a build from before the fifteenth session requires them.
    const std::vector<double> masses_kg = point_dashpot_masses_kg(first.world, first.world.contacts);
    const std::vector<double> written_kg = state.root().open_group("contacts3d").doubles(
        "dashpot_mass_kg", static_cast<std::int64_t>(first.world.contacts.size()));
    ASSERT_EQ(written_kg.size(), masses_kg.size());
    for (std::size_t k = 0; k < masses_kg.size(); ++k) EXPECT_TRUE(same_bits(written_kg[k], masses_kg[k])) << k;
    restore_world_3d(state, second.world, "state_3d.toml");
    Monitor3dStatePart part(second_monitor);
    state.restore(part);
    EXPECT_EQ(second.world.steps, 200);
    // The deepest overlap so far comes back with the state (summary.json's checks.overlap).
    const StabilityWatch3d& saved = first.world.stability;
    const StabilityWatch3d& restored = second.world.stability;
    ASSERT_GT(saved.max_overlap_ratio, 0.0);
    EXPECT_TRUE(same_bits(restored.max_overlap_ratio, saved.max_overlap_ratio));
    EXPECT_TRUE(same_bits(restored.max_overlap_m, saved.max_overlap_m));
    EXPECT_TRUE(same_bits(restored.max_overlap_time_s, saved.max_overlap_time_s));
    EXPECT_EQ(restored.max_overlap_body_a, saved.max_overlap_body_a);
    EXPECT_EQ(restored.max_overlap_body_b, saved.max_overlap_body_b);
    advance(second.world, second_monitor, 200);

    const World3d& a = whole.world;
    const World3d& b = second.world;
    EXPECT_TRUE(same_bits(a.time_s, b.time_s));
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        const RigidBody3d& x = a.bodies[i];
        const RigidBody3d& y = b.bodies[i];
        for (auto [p, q] : {std::pair{x.position_m, y.position_m}, std::pair{x.velocity_m_s, y.velocity_m_s},
                            std::pair{x.angular_momentum_kg_m2_s, y.angular_momentum_kg_m2_s}})
            EXPECT_TRUE(same_bits(p.x, q.x) && same_bits(p.y, q.y) && same_bits(p.z, q.z)) << x.name;
        EXPECT_TRUE(same_bits(x.orientation.w, y.orientation.w) && same_bits(x.orientation.z, y.orientation.z)) << x.name;
    }
    ASSERT_EQ(a.contacts.size(), b.contacts.size());
    for (std::size_t k = 0; k < a.contacts.size(); ++k) {
        EXPECT_TRUE(a.contacts[k].key == b.contacts[k].key);
        EXPECT_TRUE(same_bits(a.contacts[k].shear.spring_n.x, b.contacts[k].shear.spring_n.x));
    }
    EXPECT_TRUE(same_bits(a.ledger.residual_j(), b.ledger.residual_j()));
    EXPECT_TRUE(same_bits(a.stability.max_overlap_ratio, b.stability.max_overlap_ratio));
    EXPECT_TRUE(same_bits(a.stability.max_overlap_time_s, b.stability.max_overlap_time_s));
    EXPECT_TRUE(same_bits(a.ledger.friction_j, b.ledger.friction_j));
    EXPECT_TRUE(same_bits(whole_monitor.bodies()[1].peak_tilt_rad, second_monitor.bodies()[1].peak_tilt_rad));
    EXPECT_TRUE(same_bits(whole_monitor.bodies()[1].peak_slip_m, second_monitor.bodies()[1].peak_slip_m));
}

// A two-box stack to stand beside the block: several pairs touch, their runs at other places in
// two tables.
const char* const stack = R"([[bodies]]
name = "lower"
shape = "box"
size = [0.3, 0.2, 0.2]
position = [1.0, 0.0, 0.1]
density = 2000.0
[[bodies]]
name = "upper"
shape = "box"
size = [0.3, 0.2, 0.2]
position = [1.0, 0.0, 0.3]
density = 2000.0)";

TEST_F(StateFile3dTest, AWorldThatSteppedBeforeTheRestoreGoesOnAsTheWholeRun) {
    // A caller that ran a world and then restores a saved state into it (going back to a
    // checkpoint): what the step kept about its own last table (where each pair's run began)
    // must not be taken for the restored table's, or the points of a pair before that place lose
    // their history. The block and a two-box stack beside it, so that several pairs touch and
    // their runs sit at other places in the two tables; saved after 350 steps, restored into
    // worlds that stepped 37 to 420 steps, then 200 steps against the whole run of 550.
    LoadedScenario3d whole = load("block", "", stack);
    ResponseMonitor3d whole_monitor(whole.world);
    advance(whole.world, whole_monitor, 550);
    LoadedScenario3d first = load("block", "", stack);
    ResponseMonitor3d first_monitor(first.world);
    const StateFile state(save_after(first, first_monitor, 350));
    for (int before : {37, 100, 173, 420}) {
        LoadedScenario3d again = load("block", "", stack);
        ResponseMonitor3d monitor(again.world);
        advance(again.world, monitor, before);
        restore_world_3d(state, again.world, "state_3d.toml");
        advance(again.world, monitor, 200);
        for (std::size_t i = 0; i < whole.world.bodies.size(); ++i) {
            const Vec3 p = whole.world.bodies[i].position_m;
            const Vec3 q = again.world.bodies[i].position_m;
            EXPECT_TRUE(same_bits(p.x, q.x) && same_bits(p.y, q.y) && same_bits(p.z, q.z))
                << whole.world.bodies[i].name << ", restored into a world that stepped " << before << " steps";
        }
    }
}

TEST_F(StateFile3dTest, AStateOfAnotherScenarioIsRefusedNamingTheFile) {
    LoadedScenario3d first = load();
    ResponseMonitor3d monitor(first.world);
    const fs::path file = save_after(first, monitor, 20);
    const StateFile state(file);

    LoadedScenario3d renamed = load("statue");
    try {
        restore_world_3d(state, renamed.world, "other.toml");
        FAIL() << "a state with another body was taken";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("t.h5"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("body 2 is 'block' in the state but 'statue'"), std::string::npos) << e.what();
    }
    LoadedScenario3d finer = load("block", "dt = 1e-5");
    EXPECT_THROW(restore_world_3d(state, finer.world, "finer.toml"), InputError);
}



// The block pushed and twisted from step 0, the lower box of the stack held (sliding and
// turning under the upper one) from step 50.
void steer(LoadedScenario3d& s, ResponseMonitor3d& monitor, int steps) {
    set_external_load(s.world, 1, {30.0, -10.0, 0.0}, {0.0, 0.0, 2.0});
    advance(s.world, monitor, 50);
    hold_body_velocity(s.world, 2, {0.05, 0.02, 0.0}, {0.0, 0.0, 0.3});
    advance(s.world, monitor, steps - 50);
}

TEST_F(StateFile3dTest, ExternalLoadsAndHeldVelocitiesGoOnBitForBit) {
    LoadedScenario3d whole = load("block", "", stack);
    ResponseMonitor3d whole_monitor(whole.world);
    steer(whole, whole_monitor, 400);

    LoadedScenario3d first = load("block", "", stack);
    ResponseMonitor3d first_monitor(first.world);
    steer(first, first_monitor, 200);
    ASSERT_NE(length(first.world.external_loads.force_n[2]), 0.0) << "no holding force: the test would not test it";
    const fs::path file = save_after(first, first_monitor, 0);
    const StateFile state(file);
    EXPECT_TRUE(state.has_group("external_loads3d"));

    LoadedScenario3d second = load("block", "", stack);
    ResponseMonitor3d second_monitor(second.world);
    restore_world_3d(state, second.world, "state_3d.toml");
    Monitor3dStatePart part(second_monitor);
    state.restore(part);
    expect_same_loads(second.world.external_loads, first.world.external_loads);
    EXPECT_TRUE(same_bits(second.world.ledger.external_work_j, first.world.ledger.external_work_j));
    advance(second.world, second_monitor, 200);

    for (std::size_t i = 0; i < whole.world.bodies.size(); ++i) {
        const RigidBody3d& x = whole.world.bodies[i];
        const RigidBody3d& y = second.world.bodies[i];
        EXPECT_TRUE(same_bits(x.position_m, y.position_m)) << x.name;
        EXPECT_TRUE(same_bits(x.velocity_m_s, y.velocity_m_s)) << x.name;
        EXPECT_TRUE(same_bits(x.angular_momentum_kg_m2_s, y.angular_momentum_kg_m2_s)) << x.name;
    }
    expect_same_loads(second.world.external_loads, whole.world.external_loads);
    EXPECT_NE(whole.world.ledger.external_work_j, 0.0);
    EXPECT_TRUE(same_bits(whole.world.ledger.external_work_j, second.world.ledger.external_work_j));
    EXPECT_TRUE(same_bits(whole.world.ledger.residual_j(), second.world.ledger.residual_j()));
}

TEST_F(StateFile3dTest, AStateWithoutLoadsRestoresNoneAndABadLoadsGroupIsRefused) {
    // A world without loads writes no /external_loads3d group (as every earlier file): restored,
    // no loads, also into a world that had some. A damaged group is refused naming the file and
    // the dataset.
    LoadedScenario3d first = load();
    ResponseMonitor3d monitor(first.world);
    const StateFile plain(save_after(first, monitor, 20));
    EXPECT_FALSE(plain.has_group("external_loads3d"));
    LoadedScenario3d loaded = load();
    set_external_load(loaded.world, 1, {1.0, 2.0, 3.0}, {});
    restore_world_3d(plain, loaded.world, "state_3d.toml");
    EXPECT_FALSE(loaded.world.external_loads.any());

    struct Case {
        std::vector<std::uint32_t> body;
        std::size_t force_rows;
        const char* message;
    };
    const Case cases[] = {
        {{7}, 1, "/external_loads3d/body: row 1: body 7, but the state has 2 bodies"},
        {{1}, 2, "/external_loads3d/force_n: 2 rows, expected 1"},
    };
    for (const Case& c : cases) {
        const fs::path file = dir_ / "bad.h5";
        write_state_file(file, 3, first.world.time_s, first.world.steps, StateFileInfo{}, [&](StateGroup& root) {
            write_world_3d(root, first.world);
            StateGroup g = root.create_group("external_loads3d");
            g.write("body", c.body);
            g.write("force_n", std::vector<double>(3 * c.force_rows, 1.0), 3);
            g.write("torque_n_m", std::vector<double>(3, 0.0), 3);
            g.write("held", std::vector<std::uint8_t>{0});
            g.write("held_velocity_m_s", std::vector<double>(3, 0.0), 3);
            g.write("held_angular_velocity_rad_s", std::vector<double>(3, 0.0), 3);
        }, {});
        LoadedScenario3d again = load();
        try {
            restore_world_3d(StateFile(file), again.world, "state_3d.toml");
            FAIL() << "a bad loads group was taken: " << c.message;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("bad.h5"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace blockdem
