// The tilting-table test: a block on a table whose tilt rises slowly ([simulation] tilt_deg and
// tilt_rate_deg_s, gravity turned, geometry level) slides when tan(tilt) = mu if mu < b/h, and
// topples when tan(tilt) = b/h if b/h < mu (b, h: the block's width and height). The run reports
// the table's tilt at each body's first slip and first tipping (summary.json, table_tilt_deg_at).
//
// Tolerances, and why: the tilt keeps rising while the event grows to the size at which it is
// detected. A slide is detected once the base has slipped by 0.1% of its length: with the
// acceleration g (cos a + mu sin a) dtheta growing linearly in time at a ramp rate r, that takes
// (6 u / (g (cos a + mu sin a) r))^(1/3) = 0.4 s at r = 0.5 deg/s, 0.2 deg of tilt. A topple is
// detected once the block has turned by 1% of its critical angle (the rocking threshold): from
// the unstable equilibrium the rotation grows as (r/p) sinh(p t) - r t, p = sqrt(3 g / 4 R),
// which takes about 0.35 s here, 0.2 deg of tilt. The elastic contacts lean the block by
// m g sin a h / (2 b^2 kn), 2e-4 rad here. So each event is asserted 0 to 0.4 deg after the
// closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "io/summary_writer.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"
#include "world/response_monitor.hpp"

namespace blockdem {
namespace {

using validation::g;
using validation::deg;
constexpr double ramp_deg_s = 0.5;

struct TiltRun {
    double slip_tilt_deg = NAN;      ///< the table's tilt at the first slip, from summary.json (NaN: none)
    double rocking_tilt_deg = NAN;   ///< at the first tipping
    double overturning_tilt_deg = NAN;///< when its tilt from level last passed its critical angle
    double worst_balance_error = 0.0;///< [-] over the run
    double tilt_work_j = 0.0;        ///< [J] work of the turning gravity at the end
    double scale_j = 0.0;            ///< [J] the ledger's largest term
};

double number_or_nan(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : NAN; }

// A width x height block of 2500 kg/m^3 on a level fixed table, settled at start_deg, then
// the tilt raised at ramp_deg_s for duration_s.
TiltRun tilt_until_it_goes(double width_m, double height_m, double mu, double start_deg, double duration_s) {
    Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 2.0, 0.2, {0, -0.1}),
                                   testing::rectangle_body("block", BodyKind::dynamic, width_m, height_m, {0, 0.5 * height_m},
                                                           0.0, 2500.0 * width_m * height_m)},
                                  testing::contact(1e8, mu, 0.3, 1.0), 0.0, g, duration_s);
    m.settings.dt_s.reset();
    m.settings.tilt_rad = start_deg * deg;
    m.settings.tilt_rate_rad_s = ramp_deg_s * deg;
    m.settling = SettlingSettings{};
    World w = build_world(m);
    ResponseMonitor monitor(w);
    TiltRun run;
    while (true) {
        step_begin(w);
        monitor.observe(w);
        run.worst_balance_error = std::max(run.worst_balance_error, w.energy.balance_error());
        if (w.time_s >= duration_s) break;
        step_end(w);
    }
    const nlohmann::json summary = make_summary(w, monitor, RunInfo{"tilting", "completed", ""});
    const nlohmann::json& at = summary["bodies"][1]["table_tilt_deg_at"];
    run.slip_tilt_deg = number_or_nan(at["slip_onset"]);
    run.rocking_tilt_deg = number_or_nan(at["rocking_onset"]);
    run.overturning_tilt_deg = number_or_nan(at["overturning"]);
    run.tilt_work_j = w.energy.tilt_work_j;
    run.scale_j = w.energy.scale_j();
    return run;
}

// 0.2 m wide, 0.8 m tall (b/h = 0.25, topples at 14.04 deg), mu = 0.6 (would slide at 30.96 deg).
TEST(TiltingTable, SlenderBlockToppleAtAtanWidthOverHeight) {
    const TiltRun r = tilt_until_it_goes(0.2, 0.8, 0.6, 12.0, 6.0);
    const double expected = std::atan(0.2 / 0.8) / deg;
    std::printf("slender block: tipped at a table tilt of %.4f deg, atan(b/h) = %.4f deg (%+.3f deg); overturned (tilt from "
                "level past atan(b/h)) at %.4f deg; first slip at %.4g deg; balance error <= %.3g, tilt work %.4g J of %.4g J\n",
                r.rocking_tilt_deg, expected, r.rocking_tilt_deg - expected, r.overturning_tilt_deg, r.slip_tilt_deg,
                r.worst_balance_error, r.tilt_work_j, r.scale_j);
    ASSERT_FALSE(std::isnan(r.rocking_tilt_deg)) << "the block never tipped";
    EXPECT_GE(r.rocking_tilt_deg, expected);
    EXPECT_LT(r.rocking_tilt_deg, expected + 0.4);
    // Its tilt from level (the table's tilt plus its own lean) passes atan(b/h) when the table's
    // tilt is atan(b/h) less its elastic lean on its contacts (m g sin a h / (2 b^2 kn) = 2e-4
    // rad = 0.01 deg, measured 0.02 deg): within 0.05 deg.
    EXPECT_NEAR(r.overturning_tilt_deg, expected, 0.05);
    // It tipped before it slid (if it slid at all: it slips as it lands).
    EXPECT_TRUE(std::isnan(r.slip_tilt_deg) || r.slip_tilt_deg > r.rocking_tilt_deg);
}

// 0.4 m wide, 0.4 m tall (b/h = 1, would topple at 45 deg), mu = 0.6: slides at 30.96 deg.
TEST(TiltingTable, SquatBlockSlidesAtAtanMu) {
    const TiltRun r = tilt_until_it_goes(0.4, 0.4, 0.6, 29.0, 5.0);
    const double expected = std::atan(0.6) / deg;
    std::printf("squat block: slid at a table tilt of %.4f deg, atan(mu) = %.4f deg (%+.3f deg); tipped at %.4g deg; "
                "balance error <= %.3g, tilt work %.4g J of %.4g J\n",
                r.slip_tilt_deg, expected, r.slip_tilt_deg - expected, r.rocking_tilt_deg, r.worst_balance_error,
                r.tilt_work_j, r.scale_j);
    ASSERT_FALSE(std::isnan(r.slip_tilt_deg)) << "the block never slid";
    EXPECT_GE(r.slip_tilt_deg, expected);
    EXPECT_LT(r.slip_tilt_deg, expected + 0.4);
    EXPECT_TRUE(std::isnan(r.rocking_tilt_deg));
}

// The turning gravity does work on the bodies (-dg/dt . sum m x): the ledger counts it, and the
// balance stays closed while the table tilts. Bound: 1e-3 of the largest term; without the tilt
// work the residual would be the whole of it, which is asserted to be far larger.
TEST(TiltingTable, EnergyBalanceClosedWhileGravityTurns) {
    const TiltRun r = tilt_until_it_goes(0.2, 0.8, 0.6, 2.0, 4.0);  // no event: 2 to 4 deg
    std::printf("tilting 2 to 4 deg: balance error <= %.3g; tilt work %.4g J, largest term %.4g J\n", r.worst_balance_error,
                r.tilt_work_j, r.scale_j);
    EXPECT_LT(r.worst_balance_error, 1e-3);
    EXPECT_GT(std::abs(r.tilt_work_j), 0.1 * r.scale_j);
}

}  // namespace
}  // namespace blockdem
