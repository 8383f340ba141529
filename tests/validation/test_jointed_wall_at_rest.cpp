// A running-bond wall with per-length joints at rest on a level table (issue 13: a per-length
// wall that never settled). The wall of the limit-analysis suite (38 bricks, a window, 0.2 x 0.1 m
// bricks) stands under gravity alone, as built, with per-length joints (JKN = 1e10 Pa/m,
// JKS = 5e9 Pa/m, no dilation) and, for comparison, per-point contacts (kn = 1e9 N/m). Recorded
// over time: the energy balance error, the largest brick movement, and how many contact pairs
// change their point count (one-point corner contact against two-point edge contact) per step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scenes/assemblies.hpp"
#include "world/settling.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;

Model wall_at_rest(bool per_length) {
    scenes::WallSpec spec;
    spec.origin_m = {-0.6, 0.0};
    spec.length_m = 0.8;
    spec.courses = 10;
    spec.openings.push_back({.x_m = 0.2, .y_m = 0.4, .width_m = 0.4, .height_m = 0.3, .lintel_bearing_m = 0.1});
    std::vector<BodyDef> bodies{testing::rectangle_body("base", BodyKind::fixed, 2.0, 0.2, {0.0, -0.1})};
    for (BodyDef& b : scenes::as_bodies(scenes::masonry_wall(spec), {.name_prefix = "brick", .density_kg_m3 = 2500.0}))
        bodies.push_back(std::move(b));
    ContactParameters p = testing::contact(1e9, 0.8, 0.3, 1.0);
    if (per_length) {
        p.stiffness = StiffnessBasis::per_length;
        p.kn_pa_m = 1e10;
        p.ks_pa_m = 5e9;
    }
    Model m = testing::model_with(std::move(bodies), p, 0.0, g);
    m.settings.dt_s.reset();  // (derived, as blockdem does)
    m.settings.max_energy_error = 1e9;  // (measured here, not guarded)
    return m;
}

struct RestRun {
    double largest_move_m = 0.0;     ///< [m] from the start
    double energy_error = 0.0;       ///< [-] at the end
    long flips = 0;                  ///< pair point-count changes between 1 and 2
};

RestRun run_at_rest(bool per_length, double duration_s, bool print) {
    World w = build_world(wall_at_rest(per_length));
    const std::vector<Vec2> p0 = w.bodies.position_m;
    RestRun out;
    std::vector<std::uint32_t> counts(w.contacts.size(), 0);
    double next_print_s = 0.0;
    while (w.time_s < duration_s) {
        step_begin(w);
        step_end(w);
        if (counts.size() != w.contacts.size()) counts.assign(w.contacts.size(), 0);
        long flips = 0;
        for (std::size_t k = 0; k < w.contacts.size(); ++k) {
            const std::uint32_t c = w.contacts[k].count;
            flips += (c == 1 && counts[k] == 2) || (c == 2 && counts[k] == 1);
            counts[k] = c;
        }
        out.flips += flips;
        if (print && w.time_s >= next_print_s) {
            double largest = 0.0;
            for (std::size_t i = 0; i < w.bodies.size(); ++i) largest = std::max(largest, length(w.bodies.position_m[i] - p0[i]));
            std::printf("  %s t = %.3f s: error %.3e, residual %.3e J, elastic %.3e J, kinetic %.3e J, moved %.3e m, flips %ld\n",
                        per_length ? "per_length" : "per_point", w.time_s, w.energy.balance_error(), w.energy.residual_j(),
                        w.energy.elastic_j, w.energy.kinetic_j, largest, out.flips);
            next_print_s += 0.1;
        }
    }
    double largest = 0.0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) largest = std::max(largest, length(w.bodies.position_m[i] - p0[i]));
    out.largest_move_m = largest;
    out.energy_error = w.energy.balance_error();
    return out;
}

// Measured (1 s, derived dt): per-point error 5.7e-6, bricks moved 9.9e-6 m, 149 flips; per-length
// before the fix (head joints flickering between one and two points) 122364 flips, error 0.107 and
// growing by 0.1 a second, kinetic energy never below 1e-7 J; after it 20 flips, all in the first
// 0.1 s, error 5.3e-5, kinetic energy 1e-14 J at 0.4 s. Bounds: flips below 100 (the first
// instants' real openings and closings), error below 1e-3 (20 times the measured, 100 times below
// the flickering wall's after 1 s), bricks moved below 5e-5 m (the joints' elastic closure under
// ten courses, sigma / JKN ~ 2e-5 m, with margin; the creep was unbounded).
TEST(JointedWallAtRest, PerLengthJointsComeToRestWithAClosedLedger) {
    const RestRun point = run_at_rest(false, 1.0, false);
    const RestRun joint = run_at_rest(true, 1.0, false);
    std::printf("per_point: error %.3e, moved %.3e m, flips %ld; per_length: error %.3e, moved %.3e m, flips %ld\n",
                point.energy_error, point.largest_move_m, point.flips, joint.energy_error, joint.largest_move_m, joint.flips);
    EXPECT_LT(joint.flips, 100);
    EXPECT_LT(joint.energy_error, 1e-3);
    EXPECT_LT(joint.largest_move_m, 5e-5);
}

// The settling stage's default criterion (kinetic energy below 1e-8 m g L over 0.05 s) is met
// by the per-length wall (it never was: 0.27 mm of creep in 5 s, docs/limit_analysis.md), and
// the settling moves no brick by more than the bound above.
TEST(JointedWallAtRest, PerLengthWallSettles) {
    World w = build_world(wall_at_rest(true));
    const SettlingReport r = settle(w, SettlingSettings{});
    std::printf("per_length wall settled: %d after %.3f s, kinetic ratio %.2e, largest move %.3e m (%s)\n", r.settled, r.time_s,
                r.kinetic_ratio, r.largest_move_m, r.largest_move_body.c_str());
    EXPECT_TRUE(r.settled);
    EXPECT_LT(r.largest_move_m, 5e-5);
}

}  // namespace
}  // namespace blockdem
