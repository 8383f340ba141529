// The run cut into pieces (world/simulation.hpp RunLoop, run/scenario_run.hpp): however a caller
// cuts it, the records and the final state are those of the run to the end, bit for bit; the
// state between two calls is complete at its time; a run without a folder keeps its rows in
// memory; and a finished run refuses to go on.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <vector>

#include "io/scenario.hpp"
#include "run/scenario_run.hpp"
#include "support/world_helpers.hpp"
#include "world/simulation.hpp"

namespace blockdem {
namespace {

// A block dropped onto a shaken table: contacts open and close, so the history matters.
World dropped_block() {
    BodyDef table = testing::rectangle_body("table", BodyKind::driven, 2.0, 0.2, {0.0, -0.1});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.3, 0.2, {0.0, 0.12}, 0.1, 5.0);
    Model m = testing::model_with({table, block}, testing::contact(1e6, 0.5, 0.1, 0.2), 1e-4, 9.81, 0.3);
    m.settings.output_interval_s = 7e-4;
    SineMotion shaking;
    shaking.amplitude_m_s2 = 4.0;
    shaking.period_s = 0.2;
    m.table_motion.horizontal = shaking;
    return build_world(m);
}

struct Rows : Recorder {
    std::vector<double> values;
    void record(const World& w) override {
        values.push_back(w.time_s);
        values.push_back(w.bodies.position_m[1].x);
        values.push_back(w.bodies.rotation_rad[1]);
        values.push_back(w.bodies.velocity_at_t_m_s[1].y);
    }
};

TEST(RunLoop, CutIntoPiecesItRecordsWhatTheRunToTheEndRecords) {
    World whole = dropped_block();
    Rows whole_rows;
    RunOptions options;
    options.recorders = {&whole_rows};
    ASSERT_EQ(run_simulation(whole, options), RunEnd::completed);

    World cut = dropped_block();
    Rows cut_rows;
    options.recorders = {&cut_rows};
    RunLoop loop(cut, options);
    EXPECT_EQ(loop.advance(0), 0);
    EXPECT_EQ(cut.step_index, 0);
    for (std::int64_t n : {1, 7, 300, 1}) {
        const std::int64_t before = cut.step_index;
        EXPECT_EQ(loop.advance(n), n);
        EXPECT_EQ(cut.step_index, before + n);
        // (Time is a running sum of dt: equal to n dt within rounding.)
        EXPECT_NEAR(cut.time_s, static_cast<double>(cut.step_index) * cut.dt_s, 1e-12);
    }
    EXPECT_EQ(loop.advance(std::numeric_limits<std::int64_t>::max()), total_steps(cut) - 309);
    EXPECT_TRUE(loop.ended());
    EXPECT_EQ(loop.advance(5), 0);
    loop.finish();
    EXPECT_EQ(cut_rows.values, whole_rows.values);  // bit for bit
    EXPECT_EQ(cut.bodies.position_m[1], whole.bodies.position_m[1]);
    EXPECT_EQ(cut.energy.residual_j(), whole.energy.residual_j());
}

TEST(RunLoop, StopEndsAtTheTimeReachedWithALastRecord) {
    World w = dropped_block();
    Rows rows;
    RunOptions options;
    options.recorders = {&rows};
    RunLoop loop(w, options);
    loop.advance(5);  // between two output times (every 7 steps)
    loop.stop();
    EXPECT_TRUE(loop.ended());
    EXPECT_EQ(loop.end(), RunEnd::stopped);
    ASSERT_EQ(rows.values.size(), 8u);  // t = 0 and t = 5 dt
    EXPECT_EQ(rows.values[4], w.time_s);
}

TEST(ScenarioRun, WithoutAFolderWritesNothingAndRefusesToGoOnOnceFinished) {
    const auto scenario = std::filesystem::path(BLOCKDEM_SOURCE_DIR) / "examples/paper/sliding.toml";
    RunRequest request;
    request.scenario = scenario;
    ScenarioRun run(load_scenario(scenario, {"simulation.duration=0.01"}), request, true);
    EXPECT_EQ(run.step(40), 40);
    EXPECT_EQ(run.world().step_index, 40);
    EXPECT_EQ(run.step(1000), 60);  // to the end
    EXPECT_TRUE(run.ended());
    const nlohmann::json summary = run.finish();
    EXPECT_EQ(summary["status"], "completed");
    EXPECT_EQ(summary["run_folder"], "");
    ASSERT_NE(run.trace(), nullptr);
    EXPECT_EQ(run.trace()->rows(), 11u);  // output_interval = 1e-3 s over 0.01 s, both ends
    EXPECT_THROW(run.step(1), std::logic_error);
    EXPECT_THROW(run.finish(), std::logic_error);
    EXPECT_TRUE(summary["outputs"].is_object());
}

TEST(ScenarioRun, FinishedBeforeTheEndIsInterrupted) {
    const auto scenario = std::filesystem::path(BLOCKDEM_SOURCE_DIR) / "examples/paper/sliding.toml";
    RunRequest request;
    ScenarioRun run(load_scenario(scenario, {}), request);
    run.step(123);
    const nlohmann::json summary = run.finish();
    EXPECT_EQ(summary["status"], "interrupted");
    EXPECT_NEAR(summary["time_s"].get<double>(), 123 * 1e-4, 1e-12);
}

}  // namespace
}  // namespace blockdem
