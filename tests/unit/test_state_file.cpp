// State files (io/state_file.hpp, world/world_state.hpp): a world saved between two steps and
// restored into a fresh world from the same model goes on bit for bit as the world that never
// stopped; the file round trip loses nothing; bad files are refused with the file's name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include <fmt/format.h>
#include <unistd.h>

#include "io/input_error.hpp"
#include "io/run_state_parts.hpp"
#include "io/state_file.hpp"
#include "scenes/assemblies.hpp"
#include "support/bit_checks.hpp"
#include "support/world_helpers.hpp"
#include "world/external_loads.hpp"
#include "world/response_monitor.hpp"
#include "world/step.hpp"
#include "world/world_state.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;
using testing::expect_same_loads;
using testing::same_bits;

// A folder of its own for each test, removed after it.
class StateFileTest : public ::testing::Test {
protected:
    fs::path dir_ = fs::temp_directory_path() / fmt::format("blockdem_state_test_{}", ::getpid());
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path temp_file(const std::string& name) const { return dir_ / name; }
};

void advance(World& w, ResponseMonitor& monitor, int steps) {
    for (int i = 0; i < steps; ++i) {
        step_begin(w);
        monitor.observe(w);
        step_end(w);
    }
}


// A wall of bricks laid touching on a shaken table: contacts open, close and slide.
Model wall() { return scenes::s3_wall_scene(60, 1.0, 1e-4); }

TEST_F(StateFileTest, RestoredWorldGoesOnBitForBit) {
    World straight = build_world(wall());
    ResponseMonitor straight_monitor(straight);
    advance(straight, straight_monitor, 1500);
    const fs::path file = temp_file("wall.h5");
    MonitorStatePart saved_monitor(straight_monitor);
    write_state_file(file, straight, {"save_state", "wall", "", "", 0}, {&saved_monitor});

    World restored = build_world(wall());
    ResponseMonitor restored_monitor(restored);
    const StateFile state(file);
    ASSERT_FALSE(state_mismatch(restored, state.world()));
    restore_state(restored, state.world());
    MonitorStatePart monitor_part(restored_monitor);
    state.restore(monitor_part);
    EXPECT_EQ(restored.step_index, 1500);
    EXPECT_TRUE(same_bits(restored.time_s, straight.time_s));

    advance(straight, straight_monitor, 1500);
    advance(restored, restored_monitor, 1500);
    const Bodies& a = straight.bodies;
    const Bodies& b = restored.bodies;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_TRUE(same_bits(a.position_m[i], b.position_m[i])) << a.name[i];
        EXPECT_TRUE(same_bits(a.rotation_rad[i], b.rotation_rad[i])) << a.name[i];
        EXPECT_TRUE(same_bits(a.velocity_m_s[i], b.velocity_m_s[i])) << a.name[i];
        const BodyResponse& ra = straight_monitor.responses()[i];
        const BodyResponse& rb = restored_monitor.responses()[i];
        EXPECT_TRUE(same_bits(ra.peak_abs_base_slip_m, rb.peak_abs_base_slip_m)) << a.name[i];
        EXPECT_TRUE(same_bits(ra.sliding_time_s, rb.sliding_time_s)) << a.name[i];
        EXPECT_EQ(ra.supporters, rb.supporters) << a.name[i];
    }
    EXPECT_TRUE(same_bits(straight.energy.residual_j(), restored.energy.residual_j()));
    EXPECT_TRUE(same_bits(straight.energy.friction_j, restored.energy.friction_j));
    EXPECT_EQ(straight.broad_phase_rebuilds, restored.broad_phase_rebuilds);
    ASSERT_EQ(straight.contacts.size(), restored.contacts.size());
    for (std::size_t p = 0; p < straight.contacts.size(); ++p)
        for (int k = 0; k < 2; ++k)
            EXPECT_TRUE(same_bits(straight.contacts[p].points[k].shear_spring_n, restored.contacts[p].points[k].shear_spring_n));
}

// A bonded cantilever whose joints have 6 sub-contacts (contact/sub_contacts.hpp) on a table
// tilting so that its root cracks: saved while it bends, it goes on bit for bit, interior
// points (their history and bonds) included.
Model bonded_cantilever() {
    std::vector<BodyDef> bodies{testing::rectangle_body("wall", BodyKind::fixed, 0.4, 1.0, {-0.2, 0.0})};
    for (int i = 0; i < 4; ++i)
        bodies.push_back(testing::rectangle_body("block" + std::to_string(i), BodyKind::dynamic, 0.5, 0.2,
                                                 {(i + 0.5) * 0.5, 0.0}, 0.0, 200.0));
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e10;
    p.ks_pa_m = 4e9;
    p.mu = 0.6;
    p.h_n = p.h_s = 0.5;
    p.cohesion_pa = 1e6;
    p.tensile_strength_pa = 3.2e5;
    Model m = testing::model_with(bodies, p, 0.0, 9.81, 2.0);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    m.contact.sub_contacts = 6;
    m.settings.tilt_rad = 85.0 * std::numbers::pi / 180.0;
    m.settings.tilt_rate_rad_s = -40.0 * std::numbers::pi / 180.0;
    return m;
}

TEST_F(StateFileTest, SubContactsGoOnBitForBit) {
    World straight = build_world(bonded_cantilever());
    ResponseMonitor straight_monitor(straight);
    advance(straight, straight_monitor, 4000);
    const fs::path file = temp_file("cantilever.h5");
    MonitorStatePart saved_monitor(straight_monitor);
    write_state_file(file, straight, {"save_state", "cantilever", "", "", 0}, {&saved_monitor});

    World restored = build_world(bonded_cantilever());
    ResponseMonitor restored_monitor(restored);
    const StateFile state(file);
    restore_state(restored, state.world());
    MonitorStatePart monitor_part(restored_monitor);
    state.restore(monitor_part);
    std::uint32_t interior = 0;
    for (const SubContacts& sub : restored.sub_contacts) interior += sub.count;
    EXPECT_EQ(interior, 16u);  // 4 bonded joints of 6 points, as saved
    for (int round = 0; round < 3; ++round) {
        advance(straight, straight_monitor, 4000);
        advance(restored, restored_monitor, 4000);
        for (std::size_t i = 0; i < straight.bodies.size(); ++i)
            EXPECT_TRUE(same_bits(straight.bodies.position_m[i], restored.bodies.position_m[i])) << round;
        ASSERT_EQ(straight.sub_contacts.size(), restored.sub_contacts.size());
        for (std::size_t p = 0; p < straight.sub_contacts.size(); ++p) {
            const SubContacts& a = straight.sub_contacts[p];
            const SubContacts& b = restored.sub_contacts[p];
            ASSERT_EQ(a.count, b.count);
            EXPECT_EQ(a.broken_memory, b.broken_memory);
            EXPECT_TRUE(same_bits(a.memory_first_m, b.memory_first_m));
            for (std::uint32_t k = 0; k < a.count; ++k) {
                EXPECT_TRUE(same_bits(a.points[k].shear_spring_n, b.points[k].shear_spring_n));
                EXPECT_EQ(a.points[k].bond, b.points[k].bond);
            }
        }
    }
    EXPECT_TRUE(same_bits(straight.energy.residual_j(), restored.energy.residual_j()));
    // Bonds broke after the save (the root cracked: bond_breakage_j was 0 then).
    EXPECT_EQ(state.world().energy.bond_breakage_j, 0.0);
    EXPECT_GT(straight.energy.bond_breakage_j, 0.0);
    EXPECT_TRUE(same_bits(straight.energy.bond_breakage_j, restored.energy.bond_breakage_j));
}

// A block sliding down a 40 deg table on a dilating joint (psi = 20 deg): saved while it
// slides and has dilated, it goes on bit for bit (the points' dilation is history).
Model dilating_slide() {
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e9;
    p.ks_pa_m = 5e8;
    p.mu = 0.6;
    p.h_n = p.h_s = 0.5;
    p.tan_dilation = std::tan(20.0 * std::numbers::pi / 180.0);
    Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 3.0, 0.2, {0.0, -0.1}),
                                   testing::rectangle_body("block", BodyKind::dynamic, 2.0, 0.05, {0.0, 0.025}, 0.0, 1000.0)},
                                  p, 0.0, 9.81, 1.0);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    m.settings.tilt_rad = 40.0 * std::numbers::pi / 180.0;
    return m;
}

TEST_F(StateFileTest, DilatedJointGoesOnBitForBit) {
    World straight = build_world(dilating_slide());
    ResponseMonitor straight_monitor(straight);
    advance(straight, straight_monitor, 1000);
    const fs::path file = temp_file("dilating.h5");
    write_state_file(file, straight, {"save_state", "dilating", "", "", 0}, {});
    World restored = build_world(dilating_slide());
    ResponseMonitor restored_monitor(restored);
    const StateFile state(file);
    restore_state(restored, state.world());
    ASSERT_EQ(restored.contacts.size(), 1u);
    EXPECT_GT(restored.contacts[0].points[0].dilation_m, 1e-4);  // it had dilated when saved (0.43 mm)
    EXPECT_TRUE(same_bits(restored.contacts[0].points[0].dilation_m, straight.contacts[0].points[0].dilation_m));
    advance(straight, straight_monitor, 1000);
    advance(restored, restored_monitor, 1000);
    EXPECT_TRUE(same_bits(straight.bodies.position_m[1], restored.bodies.position_m[1]));
}

TEST_F(StateFileTest, RoundTripKeepsTheHistoryOfEveryContact) {
    World w = build_world(wall());
    ResponseMonitor monitor(w);
    advance(w, monitor, 800);
    const fs::path file = temp_file("round_trip.h5");
    write_state_file(file, w, {"save_state", "wall", "toml text", "/runs/wall", 17}, {});
    const StateFile state(file);
    EXPECT_EQ(state.info().output_rows, 17);
    EXPECT_EQ(state.info().scenario_toml, "toml text");
    const WorldState& s = state.world();
    const WorldState now = capture_state(w);
    ASSERT_EQ(s.contacts.size(), now.contacts.size());
    int loaded_points = 0;
    for (std::size_t p = 0; p < s.contacts.size(); ++p) {
        EXPECT_EQ(std::memcmp(&s.contacts[p].axis_cache, &now.contacts[p].axis_cache, sizeof(AxisCache)), 0);
        EXPECT_EQ(s.contacts[p].count, now.contacts[p].count);
        for (int k = 0; k < 2; ++k) {
            const ContactPoint& x = s.contacts[p].points[k];
            const ContactPoint& y = now.contacts[p].points[k];
            EXPECT_EQ(x.feature, y.feature);
            EXPECT_TRUE(same_bits(x.shear_spring_n, y.shear_spring_n));
            EXPECT_TRUE(same_bits(x.normal_dashpot_n, y.normal_dashpot_n));
            EXPECT_TRUE(same_bits(x.shear_dashpot_n, y.shear_dashpot_n));
        }
        loaded_points += static_cast<int>(s.contacts[p].count);
    }
    EXPECT_GT(loaded_points, 60);  // the wall rests on its contacts
    EXPECT_TRUE(same_bits(s.energy.normal_dashpot_j, w.energy.normal_dashpot_j));
    EXPECT_EQ(s.stability.least_limit_body, w.stability.least_limit_body);
    EXPECT_EQ(s.velocities_staggered, true);
}

TEST_F(StateFileTest, StartFromStateRestartsTheClock) {
    World settled = build_world(wall());
    ResponseMonitor monitor(settled);
    advance(settled, monitor, 500);
    World fresh = build_world(wall());
    start_from_state(fresh, capture_state(settled));
    EXPECT_EQ(fresh.time_s, 0.0);
    EXPECT_EQ(fresh.step_index, 0);
    EXPECT_EQ(fresh.energy.friction_j, 0.0);
    EXPECT_EQ(fresh.energy.initial_j, fresh.energy.stored_j());
    const std::uint32_t brick = fresh.body_id(settled.bodies.name.back());
    EXPECT_TRUE(same_bits(fresh.bodies.initial_position_m[brick], settled.bodies.position_m[brick]));
}

TEST_F(StateFileTest, AnotherScenariosStateIsNamed) {
    World small = build_world(scenes::s3_wall_scene(30, 1.0, 1e-4));
    World large = build_world(wall());
    const auto mismatch = state_mismatch(large, capture_state(small));
    ASSERT_TRUE(mismatch);
    EXPECT_NE(mismatch->find("the state has"), std::string::npos) << *mismatch;
}

std::string error_of(const fs::path& file) {
    try {
        StateFile state(file);
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
        return e.what();
    }
    return "";
}

TEST_F(StateFileTest, BadFilesAreRefusedWithTheirName) {
    EXPECT_NE(error_of(temp_file("missing.h5")).find("no such state file"), std::string::npos);
    const fs::path folder = temp_file("a_run");
    fs::create_directories(folder);
    EXPECT_NE(error_of(folder).find("a folder, not a state file"), std::string::npos);
    const fs::path garbage = temp_file("garbage.h5");
    std::ofstream(garbage) << "not hdf5 at all\n";
    EXPECT_NE(error_of(garbage).find("not an HDF5 file"), std::string::npos);

    World w = build_world(wall());
    const fs::path whole = temp_file("whole.h5");
    write_state_file(whole, w, {"save_state", "wall", "", "", 0}, {});
    const fs::path cut = temp_file("cut.h5");
    fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, fs::file_size(whole) / 2);
    EXPECT_NE(error_of(cut), "");
}

// The dynamic bodies of w, in body order.
std::vector<std::uint32_t> dynamic_bodies(const World& w) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies.kind[i] == BodyKind::dynamic) out.push_back(i);
    return out;
}


TEST_F(StateFileTest, ExternalLoadsAndHeldVelocitiesGoOnBitForBit) {
    // A caller's loads of each kind on the shaken wall (a pushed and twisted brick, a held one,
    // one held and released, whose held velocity stays behind, and a torque of -0.0): saved
    // while they act, read back equal to the bit, and the restored world goes on bit for bit.
    World straight = build_world(wall());
    ResponseMonitor straight_monitor(straight);
    const std::vector<std::uint32_t> bricks = dynamic_bodies(straight);
    ASSERT_GE(bricks.size(), 4u);
    advance(straight, straight_monitor, 300);
    set_external_load(straight, bricks[0], {0.0, -0.0}, -0.0);
    set_external_load(straight, bricks.back(), {40.0, -15.0}, 3.5);
    hold_body_velocity(straight, bricks[1], {0.02, 0.0}, 0.1);
    hold_body_velocity(straight, bricks[2], {-0.01, 0.01}, 0.0);
    advance(straight, straight_monitor, 300);
    release_body_velocity(straight, bricks[2]);
    advance(straight, straight_monitor, 300);
    ASSERT_NE(straight.external_loads.force_n[bricks[1]].x, 0.0) << "no holding force: the test would not test it";
    ASSERT_NE(straight.energy.external_work_j, 0.0);
    const fs::path file = temp_file("loads.h5");
    write_state_file(file, straight, {"save_state", "wall", "", "", 0}, {});

    World restored = build_world(wall());
    ResponseMonitor restored_monitor(restored);
    const StateFile state(file);
    expect_same_loads(state.world().external_loads, straight.external_loads);
    restore_state(restored, state.world());
    expect_same_loads(restored.external_loads, straight.external_loads);
    EXPECT_TRUE(same_bits(restored.energy.external_work_j, straight.energy.external_work_j));

    advance(straight, straight_monitor, 600);
    advance(restored, restored_monitor, 600);
    for (std::size_t i = 0; i < straight.bodies.size(); ++i) {
        EXPECT_TRUE(same_bits(straight.bodies.position_m[i], restored.bodies.position_m[i])) << straight.bodies.name[i];
        EXPECT_TRUE(same_bits(straight.bodies.velocity_m_s[i], restored.bodies.velocity_m_s[i])) << straight.bodies.name[i];
        EXPECT_TRUE(same_bits(straight.bodies.rotation_rad[i], restored.bodies.rotation_rad[i])) << straight.bodies.name[i];
    }
    expect_same_loads(restored.external_loads, straight.external_loads);
    EXPECT_TRUE(same_bits(straight.energy.external_work_j, restored.energy.external_work_j));
    EXPECT_TRUE(same_bits(straight.energy.residual_j(), restored.energy.residual_j()));
}

TEST_F(StateFileTest, AStateWithoutLoadsRestoresNone) {
    // A world without loads writes no /external_loads group, as every file before the group
    // existed; read back, it is no loads, also in a world that had some (going back to a
    // checkpoint).
    World plain = build_world(wall());
    const fs::path file = temp_file("plain.h5");
    write_state_file(file, plain, {"save_state", "wall", "", "", 0}, {});
    const StateFile state(file);
    EXPECT_FALSE(state.has_group("external_loads"));
    EXPECT_FALSE(state.world().external_loads.any());
    World loaded = build_world(wall());
    set_external_load(loaded, dynamic_bodies(loaded).front(), {1.0, 2.0}, 3.0);
    restore_state(loaded, state.world());
    EXPECT_FALSE(loaded.external_loads.any());
}

// A part that writes a hand-made /external_loads group beside a world without loads: a file
// whose loads were damaged or edited.
class LoadsGroupPart : public StatePart {
public:
    explicit LoadsGroupPart(std::function<void(StateGroup&)> write) : write_(std::move(write)) {}
    std::string state_group() const override { return "external_loads"; }
    void save_state(StateGroup& group) const override { write_(group); }
    void restore_state(const StateGroup&) override {}

private:
    std::function<void(StateGroup&)> write_;
};

TEST_F(StateFileTest, ABadLoadsGroupIsRefusedNamingTheFileAndTheDataset) {
    World w = build_world(wall());
    const std::uint32_t brick = dynamic_bodies(w).front();
    const auto bodies = static_cast<std::uint32_t>(w.bodies.size());
    // A group of one row, for brick, but for the dataset `name`, which `bad` writes instead
    // (or leaves out).
    auto write_with = [&](const std::string& name, const std::function<void(StateGroup&)>& bad) {
        return [=](StateGroup& g) {
            const std::pair<const char*, std::function<void()>> datasets[] = {
                {"body", [&] { g.write("body", std::vector<std::uint32_t>{brick}); }},
                {"force_n", [&] { g.write("force_n", std::vector<Vec2>{{1.0, 2.0}}); }},
                {"torque_n_m", [&] { g.write("torque_n_m", std::vector<double>{0.5}); }},
                {"held", [&] { g.write("held", std::vector<std::uint8_t>{0}); }},
                {"held_velocity_m_s", [&] { g.write("held_velocity_m_s", std::vector<Vec2>{{}}); }},
                {"held_angular_velocity_rad_s", [&] { g.write("held_angular_velocity_rad_s", std::vector<double>{0.0}); }},
            };
            for (const auto& [dataset, write] : datasets) {
                if (dataset == name) bad(g);
                else write();
            }
        };
    };
    const fs::path good = temp_file("good_loads.h5");
    LoadsGroupPart good_part(write_with("", [](StateGroup&) {}));
    write_state_file(good, w, {"save_state", "wall", "", "", 0}, {&good_part});
    EXPECT_TRUE(same_bits(StateFile(good).world().external_loads.torque_n_m[brick], 0.5));  // (the hand-made group reads)

    struct Case {
        const char* dataset;
        std::function<void(StateGroup&)> bad;
        const char* message;
    };
    const Case cases[] = {
        {"body", [&](StateGroup& g) { g.write("body", std::vector<std::uint32_t>{bodies}); },
         "/external_loads/body: row 1: body"},   // (out of range)
        {"body", [&](StateGroup& g) { g.write("body", std::vector<std::uint32_t>{brick, brick}); },
         "/external_loads/body: row 2: body"},   // (a body twice)
        {"force_n", [](StateGroup& g) { g.write("force_n", std::vector<Vec2>{{1.0, 2.0}, {3.0, 4.0}}); },
         "/external_loads/force_n: 2 rows, expected 1"},
        {"torque_n_m", [](StateGroup& g) { g.write("torque_n_m", std::vector<Vec2>{{1.0, 2.0}}); },
         "/external_loads/torque_n_m: expected an array of shape n"},
        {"held", [](StateGroup& g) { g.write("held", std::vector<std::uint8_t>{2}); }, "/external_loads/held: row 1"},
        {"held_velocity_m_s", [](StateGroup& g) { g.write("held_velocity_m_s", std::vector<Vec2>{{std::nan(""), 0.0}}); },
         "/external_loads/held_velocity_m_s: row 1 (body"},
        {"held_angular_velocity_rad_s", [](StateGroup&) {}, "/external_loads/held_angular_velocity_rad_s: missing dataset"},
    };
    int k = 0;
    for (const Case& c : cases) {
        const fs::path file = temp_file(fmt::format("bad_loads_{}.h5", k++));
        LoadsGroupPart part(write_with(c.dataset, c.bad));
        write_state_file(file, w, {"save_state", "wall", "", "", 0}, {&part});
        const std::string error = error_of(file);   // (names the file)
        EXPECT_NE(error.find(c.message), std::string::npos) << c.dataset << ": " << error;
    }
}

}  // namespace
}  // namespace blockdem
