// Sensor kinematics (world/sensor.hpp) against closed forms: a body in uniform rotation (the
// centripetal acceleration omega^2 r), and the sensor bank's channels and relative sensors.
#include <gtest/gtest.h>

#include <cmath>

#include "support/world_helpers.hpp"
#include "world/sensor.hpp"

namespace blockdem {
namespace {

using testing::contact;
using testing::model_with;
using testing::rectangle_body;

// A free body spinning at omega in zero gravity, touching nothing.
World spinning_world(double omega_rad_s, Vec2 velocity_m_s) {
    BodyDef b = rectangle_body("disc", BodyKind::dynamic, 0.4, 0.4, {1.0, 2.0});
    b.angular_velocity_rad_s = omega_rad_s;
    b.velocity_m_s = velocity_m_s;
    return build_world(model_with({b}, contact(1e6, 0.5, 0.1, 0.1), 1e-4, 0.0));
}

TEST(SensorKinematics, UniformRotationGivesTheCentripetalAcceleration) {
    const double omega = 3.0;   // [rad/s]
    const Vec2 drift{0.5, -0.2};
    World w = spinning_world(omega, drift);
    const Vec2 r0{0.2, 0.1};   // a corner region point, from the centroid
    const double r = length(r0);
    for (int n = 0; n < 5000; ++n) {
        step_begin(w);
        if (n % 500 == 0) {
            const PointKinematics p = point_kinematics(w.bodies, 0, r0);
            const double angle = omega * w.time_s;
            const Vec2 arm = Rotation::from_angle(angle).apply(r0);
            const Vec2 centre = Vec2{1.0, 2.0} + w.time_s * drift;
            EXPECT_NEAR(p.position_m.x, centre.x + arm.x, 1e-9);
            EXPECT_NEAR(p.position_m.y, centre.y + arm.y, 1e-9);
            EXPECT_NEAR(p.velocity_m_s.x, drift.x - omega * arm.y, 1e-9);
            EXPECT_NEAR(p.velocity_m_s.y, drift.y + omega * arm.x, 1e-9);
            // omega^2 r, pointing at the centroid.
            EXPECT_NEAR(length(p.acceleration_m_s2), omega * omega * r, 1e-9);
            EXPECT_NEAR(p.acceleration_m_s2.x, -omega * omega * arm.x, 1e-9);
            EXPECT_NEAR(p.acceleration_m_s2.y, -omega * omega * arm.y, 1e-9);
        }
        step_end(w);
    }
}

TEST(SensorKinematics, BankChannelsAndRelativeSensorFromTheStart) {
    const double omega = 2.0;
    World w = spinning_world(omega, {0.3, 0.0});
    SensorDef at_centre{"c", SensorKind::point, 0, {0.0, 0.0}, 0, {}, 0.0, 4};
    SensorDef spin{"s", SensorKind::relative, 0, {0.2, 0.0}, 0, {0.0, 0.0}, 0.0, 4};
    SensorBank bank({at_centre, spin}, w.dt_s);
    ASSERT_EQ(bank.values().size(), 8u);
    while (w.time_s < 0.5) {
        step_begin(w);
        bank.observe(w);
        step_end(w);
    }
    step_begin(w);
    bank.observe(w);
    const double t = w.time_s;
    const std::vector<double>& v = bank.values();
    EXPECT_NEAR(v[0], 0.0, 1e-12);              // ax of the centroid of a drifting body
    EXPECT_NEAR(v[2], 0.3, 1e-12);              // vx
    EXPECT_NEAR(v[4], 1.0 + 0.3 * t, 1e-9);     // x
    EXPECT_NEAR(v[5], 2.0, 1e-12);              // y
    // The point 0.2 m out on the arm relative to the centroid: turned by omega t from the start.
    EXPECT_NEAR(v[6], 0.2 * std::cos(omega * t) - 0.2, 1e-9);
    EXPECT_NEAR(v[7], 0.2 * std::sin(omega * t), 1e-9);
}

}  // namespace
}  // namespace blockdem
