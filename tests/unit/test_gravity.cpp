// Gravity as a vector or as a magnitude turned by the table's tilt ([simulation] gravity,
// tilt_deg, tilt_rate_deg_s): the keys, the convention (positive tilt raises the table's +x
// end, so gravity points down and towards -x), and the force the step applies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <toml++/toml.h>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "support/world_helpers.hpp"

namespace blockdem {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

Model model_from(const std::string& simulation_keys) {
    const toml::table root = toml::parse("[simulation]\nduration = 2.0\n" + simulation_keys + R"(
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
e = 0.3
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.4
height = 0.2
center = [0.0, 0.1]
density = 2500.0
)");
    return read_model(root, "test.toml", ".");
}

std::string error_of(const std::string& simulation_keys) {
    try {
        model_from(simulation_keys);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(Gravity, TiltTurnsGravityTowardsMinusX) {
    SimulationSettings s;
    s.gravity_m_s2 = 10.0;
    s.tilt_rad = 30.0 * deg;
    s.tilt_rate_rad_s = 1.0 * deg;
    EXPECT_NEAR(gravity_at(s, 0.0).x, -5.0, 1e-12);
    EXPECT_NEAR(gravity_at(s, 0.0).y, -10.0 * std::cos(30.0 * deg), 1e-12);
    EXPECT_NEAR(tilt_at_rad(s, 15.0), 45.0 * deg, 1e-12);
    EXPECT_NEAR(gravity_at(s, 15.0).x, -10.0 * std::sin(45.0 * deg), 1e-12);
}

TEST(Gravity, VectorKeyGivesMagnitudeAndTilt) {
    const Model m = model_from("gravity = [3.0, -4.0]\n");
    EXPECT_DOUBLE_EQ(m.settings.gravity_m_s2, 5.0);
    EXPECT_NEAR(gravity_at(m.settings, 0.0).x, 3.0, 1e-12);
    EXPECT_NEAR(gravity_at(m.settings, 0.0).y, -4.0, 1e-12);
    // tilt_deg turns the vector further, as a table tilted by that much more.
    const Model t = model_from("gravity = [0.0, -9.81]\ntilt_deg = 20.0\ntilt_rate_deg_s = 2.0\n");
    EXPECT_NEAR(t.settings.tilt_rad, 20.0 * deg, 1e-12);
    EXPECT_NEAR(t.settings.tilt_rate_rad_s, 2.0 * deg, 1e-12);
    EXPECT_NEAR(gravity_at(t.settings, 0.0).x, -9.81 * std::sin(20.0 * deg), 1e-12);
    const Model zero = model_from("gravity = [0.0, 0.0]\n");
    EXPECT_EQ(zero.settings.gravity_m_s2, 0.0);
    EXPECT_EQ(zero.settings.tilt_rad, 0.0);
}

TEST(Gravity, BadKeysAreNamed) {
    EXPECT_NE(error_of("tilt_deg = 95.0\n").find("simulation.tilt_deg"), std::string::npos);
    const std::string ramp = error_of("tilt_deg = 80.0\ntilt_rate_deg_s = 10.0\n");
    EXPECT_NE(ramp.find("simulation.tilt_rate_deg_s"), std::string::npos) << ramp;
    EXPECT_NE(ramp.find("100"), std::string::npos) << ramp;
    EXPECT_NE(error_of("gravity = -9.81\n").find("simulation.gravity"), std::string::npos);
    EXPECT_NE(error_of("gravity = [1.0, 2.0, 3.0]\n").find("simulation.gravity"), std::string::npos);
}

// A body in free flight accelerates with the gravity vector, and its energy balance holds with
// -m g . x as its potential.
TEST(Gravity, FreeBodyFallsAlongTheGravityVector) {
    Model m = testing::model_with({testing::rectangle_body("block", BodyKind::dynamic, 0.4, 0.2, {0.0, 0.0}, 0.0, 2.0)},
                                  testing::contact(1e6, 0.5, 0.3, 1.0), 1e-4, 9.81, 1.0);
    m.settings.tilt_rad = 30.0 * deg;
    m.settings.domain = DomainBox{{-100, -100}, {100, 100}};
    World w = build_world(m);
    while (w.time_s < 0.5 - 1e-9) step(w);
    ASSERT_NEAR(w.time_s, 0.5, 1e-9);
    const Vec2 moved = w.bodies.position_m[0] - w.bodies.initial_position_m[0];
    const Vec2 g = gravity_at(m.settings, 0.0);
    EXPECT_NEAR(moved.x, 0.5 * g.x * 0.25, 1e-3);
    EXPECT_NEAR(moved.y, 0.5 * g.y * 0.25, 1e-3);
    EXPECT_LT(w.energy.balance_error(), 1e-6);
}

}  // namespace
}  // namespace blockdem
