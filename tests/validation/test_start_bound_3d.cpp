// The stable bound at the start of a tall stack placed touching (world/world_3d_start.hpp) against
// the bound of the same model settled (dynamics/critical_time_step_3d.hpp, over the live contact
// table). The start's probe grows its bodies by a touch tolerance, so that every face placed
// touching carries its points at once; before, its three steps loaded only the lowest courses of
// examples/3d/brick_wall.toml (504 points, a bound 12 % above the settled one, docs/3d.md): a
// given dt just below the printed bound went unstable once the wall had settled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "dynamics/critical_time_step_3d.hpp"
#include "io/scenario_3d.hpp"
#include "world/step_3d.hpp"
#include "world/world_3d_start.hpp"

namespace blockdem {
namespace {

TEST(StartBound3d, TallWallPlacedTouchingGetsTheSettledBoundAtOnce) {
    LoadedScenario3d s = load_scenario_3d(std::filesystem::path(BLOCKDEM_SOURCE_DIR) / "examples/3d/brick_wall.toml", {});
    World3d& w = s.world;
    const CriticalTimeStep3d start = start_time_step_3d(w).proven;
    const std::size_t start_points = start_contacts_3d(w).size();
    // Settle with the table still, at half the proven bound (the step the proven bound alone would
    // give), for 0.05 s (about 10 periods of a brick's vertical mode on its bed joints), and take
    // the least live bound: every step while the courses load one after the other (the first 2
    // ms), then every 32 steps as the run's watch.
    w.table = {};
    w.dt_s = 0.5 * start.dt_s;
    double settled_s = live_time_step_3d(w).dt_s;
    std::size_t points_min = SIZE_MAX, points_max = 0;
    const auto steps = static_cast<long>(0.05 / w.dt_s);
    for (long k = 0; k < steps; ++k) {
        step_3d(w);
        if (w.time_s < 2e-3 || k % 32 == 31) {
            settled_s = std::min(settled_s, live_time_step_3d(w).dt_s);
            points_min = std::min(points_min, w.contacts.size());
            points_max = std::max(points_max, w.contacts.size());
        }
    }
    std::printf("start bound %.5e s (%zu points), settled %.5e s (%zu to %zu points), dt %.4e s\n", start.dt_s,
                start_points, settled_s, points_min, points_max, w.dt_s);
    // Never above the live bound (a run at the start's bound times the safety factor must stay
    // stable as the wall loads), and within 15 % below it. Not the 2 % hoped for: the probe sees
    // every face placed touching closed at once (3110 points), head and collar joints and the
    // line contacts between the wythes included, while the live wall has some of them open at any
    // moment (up to 1979 points). Measured: 0.897 of the least live bound of this still settle,
    // 0.948 of the shaken run's (docs/3d.md); it was 1.12 (unsafe) before the probe counted
    // touching faces.
    EXPECT_LE(start.dt_s, settled_s * (1.0 + 1e-12));
    EXPECT_GT(start.dt_s, 0.85 * settled_s);
}

}  // namespace
}  // namespace blockdem
