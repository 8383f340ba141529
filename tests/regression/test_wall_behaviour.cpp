// A generated wall under gravity alone settles and then stays at rest; the same kind of wall on
// a table shaken well past its capacity collapses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "laws/restitution.hpp"
#include "scenes/assemblies.hpp"
#include "world/settling.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// A running-bond wall (40 kg bricks 0.2 x 0.1 m) on a table; kn = 1e7 N/m lets dt = 2e-4 s.
Model small_wall(double length_m, int courses, bool stepped_ends) {
    Model m;
    m.settings.dt_s = 2e-4;
    m.settings.duration_s = 1e9;
    m.contact = MaterialPairs::uniform(
        {.kn_N_m = 1e7, .ks_N_m = 1e7, .mu = 0.6, .h_n = damping_ratio_rebound(0.5), .h_s = 0.2});
    BodyDef table;
    table.name = "table";
    table.kind = BodyKind::driven;
    table.vertices_m = {{-1.0, -0.2}, {length_m + 1.0, -0.2}, {length_m + 1.0, 0.0}, {-1.0, 0.0}};
    table.density_kg_m3 = 1000.0;
    m.bodies.push_back(table);
    scenes::WallSpec spec;
    spec.length_m = length_m;
    spec.courses = courses;
    spec.stepped_ends = stepped_ends;
    scenes::BlockStyle style;
    style.density_kg_m3 = 2000.0;
    for (BodyDef& b : scenes::as_bodies(scenes::masonry_wall(spec), style)) m.bodies.push_back(std::move(b));
    return m;
}

// Stated bound: after settling, over 10 s of simulated time with no shaking, no brick moves by
// more than 2 um or turns by more than 1e-5 rad, and the kinetic energy stays below the settling
// criterion, 1e-8 of the potential energy (a creeping contact would show as a steady drift well
// above these).
TEST(WallBehaviour, SettlesAndStaysAtRestForTenSeconds) {
    World w = build_world(small_wall(1.0, 6, false));
    const SettlingReport settled = settle(w, SettlingSettings{1e-8, 0.05, 3.0});
    ASSERT_TRUE(settled.settled) << "kinetic / potential " << settled.kinetic_ratio;
    EXPECT_EQ(w.time_s, 0.0);
    const std::vector<Vec2> start = w.bodies.position_m;
    const std::vector<double> start_rotation = w.bodies.rotation_rad;
    double drift = 0.0;
    double turn = 0.0;
    double kinetic = 0.0;
    while (w.time_s < 10.0) {
        step(w);
        kinetic = std::max(kinetic, w.energy.kinetic_j);
    }
    for (std::size_t i = 1; i < w.bodies.size(); ++i) {
        drift = std::max(drift, length(w.bodies.position_m[i] - start[i]));
        turn = std::max(turn, std::abs(w.bodies.rotation_rad[i] - start_rotation[i]));
    }
    EXPECT_LT(drift, 2e-6);
    EXPECT_LT(turn, 1e-5);
    EXPECT_LT(kinetic, 1e-8 * w.energy.gravitational_j);  // the table top is y = 0: E_p = m g y
    std::printf("settled in %.3f s; over 10 s: drift %.3g m, turn %.3g rad, kinetic / potential %.3g\n",
                settled.time_s, drift, turn, kinetic / w.energy.gravitational_j);
}

// Stated measure: the fraction of bricks whose centroid ends more than one brick height (0.1 m)
// below where it started. A wall 0.6 m long and 1.2 m high (in-plane overturning needs about
// 0.5 g) shaken at 1.5 g, 2 Hz, for 2 s collapses (more than a third of its bricks fall);
// the same wall at 0.1 g loses none.
double fallen_fraction(double amplitude_g) {
    Model m = small_wall(0.6, 12, true);
    m.table_motion.horizontal = SineMotion{amplitude_g * 9.81, 0.5, 0.0, 0.0, 0.0};
    World w = build_world(m);
    while (w.time_s < 2.0) step(w);
    int fallen = 0;
    for (std::size_t i = 1; i < w.bodies.size(); ++i)
        if (w.bodies.position_m[i].y < w.bodies.initial_position_m[i].y - 0.1) ++fallen;
    return static_cast<double>(fallen) / static_cast<double>(w.bodies.size() - 1);
}

TEST(WallBehaviour, SmallWallShakenPastItsCapacityCollapses) {
    const double strong = fallen_fraction(1.5);
    const double weak = fallen_fraction(0.1);
    std::printf("fallen fraction: %.2f at 1.5 g, %.2f at 0.1 g\n", strong, weak);
    EXPECT_GT(strong, 1.0 / 3.0);
    EXPECT_EQ(weak, 0.0);
}

}  // namespace
}  // namespace blockdem
