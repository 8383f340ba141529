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
#include "support/world_helpers.hpp"

namespace blockdem {
namespace {

constexpr double g = 9.81;

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

TEST(JointedWallAtRest, DiagnosisPrintsTheBalance) {
    const RestRun point = run_at_rest(false, 1.0, true);
    const RestRun joint = run_at_rest(true, 1.0, true);
    std::printf("per_point: error %.3e, moved %.3e m, flips %ld; per_length: error %.3e, moved %.3e m, flips %ld\n",
                point.energy_error, point.largest_move_m, point.flips, joint.energy_error, joint.largest_move_m, joint.flips);
}

}  // namespace
}  // namespace blockdem
