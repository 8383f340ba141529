// The settling stage measures each body's kinetic energy against m g L (its weight times its own
// size), a scale that cannot vanish, and names the body that did not settle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <toml++/toml.h>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "support/world_helpers.hpp"
#include "world/settling.hpp"

namespace blockdem {
namespace {

using testing::contact;
using testing::model_with;
using testing::rectangle_body;

// A 0.3 x 1.0 m block (720 kg) standing on its right bottom corner at the origin, turned 25 deg
// clockwise: past its toppling angle, atan(0.3) = 16.7 deg, so it falls to the right.
BodyDef tilted_block() {
    const double a = 25.0 * std::numbers::pi / 180.0;
    BodyDef b;
    b.name = "block";
    for (const Vec2 corner : {Vec2{0.0, 0.0}, Vec2{0.0, 1.0}, Vec2{-0.3, 1.0}, Vec2{-0.3, 0.0}})
        b.vertices_m.push_back({corner.x * std::cos(a) + corner.y * std::sin(a),
                                -corner.x * std::sin(a) + corner.y * std::cos(a) + 1e-6});
    b.mass_kg = 720.0;
    return b;
}

// The block on a fixed table whose top is y = 0 and whose right edge is at table_right_m.
Model tilted_block_on_table(double table_right_m) {
    Model m = model_with({rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {table_right_m - 2.0, -0.1}), tilted_block()},
                         contact(1e7, 0.6, 0.28, 1.0), 0.0, 9.81);
    m.settings.dt_s.reset();  // 0.2 x the stable limit
    return m;
}

// Off the table's edge the block falls for ever: it must not settle, and the report names it
// with a finite ratio. (The old criterion divided by the potential energy above the lowest
// starting corner, which a falling body makes negative: it reported 1.97e+305.)
TEST(Settling, BlockFallingOffTheTableIsNamed) {
    // A model extent far larger than the fall, so that the block stays in the step.
    Model m = tilted_block_on_table(0.1);
    m.settings.domain = DomainBox{{-1e4, -1e4}, {1e4, 1e4}};
    World w = build_world(m);
    const SettlingSettings settings{1e-8, 0.05, 1.5};
    const SettlingReport r = settle(w, settings);
    EXPECT_FALSE(r.settled);
    EXPECT_EQ(r.body, "block");
    // After about 1 s of falling its speed is several m/s: E_k / (m g L) is of order 1 to 100.
    EXPECT_GT(r.kinetic_ratio, 0.1);
    EXPECT_LT(r.kinetic_ratio, 1e3);
    EXPECT_GT(r.body_kinetic_j, 1e3);
    EXPECT_NEAR(r.body_size_m, std::hypot(0.15, 0.5), 1e-9);
    EXPECT_GT(r.body_moved_m, 1.0);
    const std::string message = settling_failure(r, settings);
    EXPECT_NE(message.find("body 'block' still moves"), std::string::npos) << message;
    EXPECT_NE(message.find("it moved"), std::string::npos) << message;
}

// With the model's default extent the block falls out of it while settling: the set-up has
// lost a body before any shaking, which is a failed settling naming the body, not a settled
// (frozen) model.
TEST(Settling, BlockLeavingTheModelWhileSettlingFails) {
    World w = build_world(tilted_block_on_table(0.1));
    const SettlingSettings settings{1e-8, 0.05, 5.0};
    const SettlingReport r = settle(w, settings);
    EXPECT_FALSE(r.settled);
    EXPECT_TRUE(r.left_model);
    EXPECT_EQ(r.body, "block");
    ASSERT_EQ(r.left_position_m.size(), 2u);
    EXPECT_LT(r.left_position_m[1], -0.2);
    const std::string message = settling_failure(r, settings);
    EXPECT_NE(message.find("body 'block' left the model"), std::string::npos) << message;
}

// On a wide table the same block topples onto its side and comes to rest: settled, lying flat
// (turned by 90 - 25 = 65 deg), and still by the criterion when the clock restarts.
TEST(Settling, ToppledBlockSettlesOnItsSide) {
    World w = build_world(tilted_block_on_table(2.0));
    const SettlingReport r = settle(w, SettlingSettings{1e-8, 0.05, 5.0});
    ASSERT_TRUE(r.settled) << settling_failure(r, SettlingSettings{1e-8, 0.05, 5.0});
    EXPECT_LT(r.kinetic_ratio, 1e-8);
    const std::uint32_t block = w.body_id("block");
    // Lying on its long side: the centroid 0.15 m above the table.
    EXPECT_NEAR(w.bodies.position_m[block].y, 0.15, 1e-3);
    EXPECT_EQ(w.time_s, 0.0);
}

// A block already at rest settles in the first window, whatever its height above any datum.
TEST(Settling, BlockAtRestSettlesInOneWindow) {
    Model m = model_with({rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0.0, 1.9}),
                          rectangle_body("block", BodyKind::dynamic, 0.4, 0.2, {0.0, 2.1}, 0.0, 100.0)},
                         contact(1e7, 0.6, 0.28, 1.0), 0.0, 9.81);
    m.settings.dt_s.reset();
    World w = build_world(m);
    const SettlingReport r = settle(w, SettlingSettings{1e-3, 0.05, 2.0});
    EXPECT_TRUE(r.settled) << r.kinetic_ratio;
    EXPECT_LT(r.time_s, 0.5);
}

// The toppled block's settling is reported as the summary and check give it: the body that
// moved and turned most, and by how much.
TEST(Settling, RecordNamesTheBodyThatMovedAndTurnedMost) {
    World w = build_world(tilted_block_on_table(2.0));
    const SettlingSettings settings{1e-8, 0.05, 5.0};
    const SettlingRecord record = settling_record(settle(w, settings), settings);
    EXPECT_EQ(record.largest_turn_body, "block");
    EXPECT_EQ(record.largest_move_body, "block");
    EXPECT_NEAR(record.largest_turn_rad, 65.0 * std::numbers::pi / 180.0, 0.02);
    EXPECT_GT(record.largest_move_m, 0.1);
    EXPECT_GT(record.steps, 0);
    EXPECT_TRUE(record.friction_held);
}

// A block on a table tilted by 35 deg with mu = 0.5 (friction angle 26.6 deg): with friction
// held it settles in place, its shear springs loaded; with the actual friction it slides off
// the table and cannot settle.
TEST(Settling, HeldFrictionLoadsASteepContactInPlace) {
    for (const SettlingFriction friction : {SettlingFriction::held, SettlingFriction::actual}) {
        Model m = model_with({rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0.0, -0.1}),
                              rectangle_body("block", BodyKind::dynamic, 0.4, 0.2, {0.0, 0.1}, 0.0, 100.0)},
                             contact(1e7, 0.5, 0.28, 1.0), 0.0, 9.81);
        m.settings.dt_s.reset();
        m.settings.tilt_rad = 35.0 * std::numbers::pi / 180.0;
        m.settings.domain = DomainBox{{-1e3, -1e3}, {1e3, 1e3}};
        World w = build_world(m);
        const SettlingReport r = settle(w, SettlingSettings{1e-8, 0.05, 1.0, friction});
        if (friction == SettlingFriction::held) {
            EXPECT_TRUE(r.settled) << r.kinetic_ratio;
            EXPECT_LT(r.largest_move_m, 1e-3);
            // The real friction is back for t = 0.
            EXPECT_DOUBLE_EQ(w.contact.parameters[0].mu, 0.5);
        } else {
            EXPECT_FALSE(r.settled);
            EXPECT_GT(r.largest_move_m, 0.5);
        }
    }
}

const char* hand_written_scenario = R"(
[simulation]
duration = 0.1
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
e = 0.3
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 2.0
height = 0.2
center = [0.0, -0.1]
density = 1000.0
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.4
height = 0.2
center = [0.0, 0.1]
density = 2500.0
)";

// [settling] applies to hand-written [[bodies]] as to assemblies: the world is settled at t = 0
// and the record says how long it took and how far the block moved (it sinks into its contacts
// by about m g / (2 kn) = 5e-5 m).
TEST(Settling, HandWrittenBodiesSettleFromTheScenario) {
    const toml::table root = toml::parse(std::string(hand_written_scenario) + "[settling]\nfriction = \"actual\"\nmax_time = 2.0\n");
    const Model m = read_model(root, "test.toml", ".");
    ASSERT_TRUE(m.settling);
    EXPECT_EQ(m.settling->friction, SettlingFriction::actual);
    const World w = build_world(m);
    ASSERT_TRUE(w.settling);
    EXPECT_FALSE(w.settling->friction_held);
    EXPECT_GT(w.settling->time_s, 0.0);
    EXPECT_EQ(w.settling->largest_move_body, "block");
    EXPECT_GT(w.settling->largest_move_m, 1e-5);
    EXPECT_LT(w.settling->largest_move_m, 2e-4);
    EXPECT_EQ(w.time_s, 0.0);
}

TEST(Settling, UnknownFrictionIsRejectedAtItsKey) {
    const toml::table root = toml::parse(std::string(hand_written_scenario) + "[settling]\nfriction = \"sticky\"\n");
    try {
        read_model(root, "test.toml", ".");
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("settling.friction"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace blockdem
