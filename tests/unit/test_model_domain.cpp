// Outcomes end to end (docs/outputs.md, "Outcomes"): a cube knocked off a stack falls (and is
// said to); past the table's edge it leaves the model and is taken out of the step, the run
// going on for the rest with a closed energy balance; onto a floor inside the model it is not
// taken out. And the model's extent and the outcome thresholds as scenario keys.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "run/run_scenario.hpp"

namespace blockdem {
namespace {

const std::filesystem::path scenes = BLOCKDEM_SOURCE_DIR "/tests/data/outcomes";

nlohmann::json run(const std::string& scene, std::vector<std::string> overrides = {}) {
    // (One folder per test: ctest runs the tests of this file in parallel processes.)
    const auto out = std::filesystem::temp_directory_path() /
                     ("blockdem_test_outcomes_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(out);
    RunRequest request;
    request.scenario = scenes / (scene + ".toml");
    request.overrides = std::move(overrides);
    request.out_dir = out;
    return run_scenario(request);
}

const nlohmann::json& body(const nlohmann::json& summary, const std::string& name) {
    for (const auto& b : summary["bodies"])
        if (b["name"] == name) return b;
    throw std::runtime_error("no body " + name);
}

TEST(Outcomes, CubeKnockedOffTheStackFellThoughItDidNotOverturn) {
    const nlohmann::json s = run("knocked_off");
    const auto& upper = body(s, "upper");
    EXPECT_FALSE(upper["overturned"].get<bool>());   // today's field, kept: it lands upright
    EXPECT_EQ(upper["outcome"], "fell");
    EXPECT_TRUE(upper["failed"].get<bool>());
    EXPECT_EQ(upper["supporters"], nlohmann::json::array({"lower"}));
    EXPECT_TRUE(upper["fell"]["came_to_rest"].get<bool>());
    EXPECT_GT(upper["fell"]["position_m"][0].get<double>(), 1.0);                // on the table, beyond the stack
    EXPECT_NEAR(upper["fell"]["position_m"][1].get<double>(), 0.2, 0.01);
    EXPECT_GT(upper["outcome_time_s"].get<double>(), 0.05);                      // when it let go of the lower cube
    EXPECT_LT(upper["outcome_time_s"].get<double>(), 0.3);
    EXPECT_EQ(body(s, "lower")["outcome"], "stable");
    const auto& all = s["collapse"].back();
    EXPECT_EQ(all["group"], "all");
    EXPECT_EQ(all["fell"], 1);
    EXPECT_EQ(all["first_to_go"], "upper");
    EXPECT_NEAR(all["displaced_mass_fraction"].get<double>(), 0.5, 1e-12);
    EXPECT_TRUE(s["domain"]["left"].empty());
}

TEST(Outcomes, CubePastTheTableEdgeLeavesTheModelAndTheRunGoesOn) {
    const nlohmann::json s = run("knocked_off", {"bodies.table.width=1.2"});
    EXPECT_EQ(s["status"], "completed");
    const auto& upper = body(s, "upper");
    EXPECT_EQ(upper["outcome"], "left_model");
    const double left_at_s = upper["left_model"]["time_s"].get<double>();
    EXPECT_GT(left_at_s, 0.2);
    EXPECT_LT(left_at_s, 1.0);
    // Taken out as soon as its box was wholly outside the derived extent (the table and the
    // stack, grown by the margin, the cube's diagonal 0.566 m): past x = 0.6 + 0.566 m while
    // falling beside the table, and frozen there, not ~30 m away after free fall (old code).
    const double margin_m = s["domain"]["margin_m"].get<double>();
    EXPECT_NEAR(margin_m, 0.4 * std::sqrt(2.0), 1e-9);
    const double extent_right_m = s["domain"]["hi_m"][0].get<double>();
    EXPECT_NEAR(extent_right_m, 0.6 + margin_m, 1e-9);
    EXPECT_TRUE(s["domain"]["hi_m"][1].is_null());   // no top
    const double x_m = upper["final_position_m"][0].get<double>();
    // The left edge of the turned 0.4 m cube's box (0.5 margin_m is its half-extent at 45 deg only).
    const double turn_rad = upper["final_rotation_rad"].get<double>();
    const double left_edge_m = x_m - 0.2 * (std::abs(std::cos(turn_rad)) + std::abs(std::sin(turn_rad)));
    EXPECT_GT(left_edge_m, extent_right_m);          // its box is outside...
    EXPECT_LT(left_edge_m, extent_right_m + 0.05);   // ...by no more than a few steps of motion
    EXPECT_EQ(upper["final_position_m"], upper["left_model"]["position_m"]);
    EXPECT_LT(upper["peak_abs_relative_displacement_m"].get<double>(), 3.0);
    ASSERT_EQ(s["domain"]["left"].size(), 1u);
    EXPECT_EQ(s["domain"]["left"][0]["body"], "upper");
    // The run went on for the lower cube, and the ledger closes with the removed account.
    EXPECT_EQ(body(s, "lower")["outcome"], "stable");
    EXPECT_NEAR(s["time_s"].get<double>(), 2.5, 1e-3);
    const auto& e = s["energy_j"];
    EXPECT_GT(e["removed_with_bodies_leaving"].get<double>(), 0.0);
    EXPECT_LT(e["balance_error_relative"].get<double>(), 0.01);
    EXPECT_NEAR(e["kinetic"].get<double>(), 0.0, 1e-6);   // the frozen cube keeps no kinetic energy
}

TEST(Outcomes, CubeFallingOntoAFloorInsideTheModelIsNotTakenOut) {
    const nlohmann::json s = run("knocked_off_floor");
    const auto& upper = body(s, "upper");
    EXPECT_EQ(upper["outcome"], "fell");
    EXPECT_TRUE(s["domain"]["left"].empty());
    EXPECT_NEAR(upper["fell"]["position_m"][1].get<double>(), -1.0 + 0.2, 0.01);  // resting on the floor
    EXPECT_TRUE(upper["fell"]["came_to_rest"].get<bool>());
}

TEST(Outcomes, GivenDomainIsTheExtent) {
    // On the narrow table, a domain that ends at x = 1 m and has a top at 0.9 m: the cube is out
    // as soon as its box is right of x = 1 m (its centre beyond 1 + half its diagonal).
    const nlohmann::json s = run("knocked_off", {"bodies.table.width=1.2", "simulation.domain=[[-1, -1], [1, 0.9]]"});
    const auto& upper = body(s, "upper");
    EXPECT_EQ(upper["outcome"], "left_model");
    EXPECT_EQ(s["domain"]["from"], "scenario");
    EXPECT_DOUBLE_EQ(s["domain"]["hi_m"][1].get<double>(), 0.9);
    const double x_m = upper["left_model"]["position_m"][0].get<double>();
    EXPECT_GT(x_m, 1.0 + 0.2);                    // (rotated, its half width is between 0.2 and 0.283 m)
    EXPECT_LT(x_m, 1.0 + 0.2 * std::sqrt(2.0) + 0.05);
}

void expect_input_error(const std::vector<std::string>& overrides, const std::string& key, const std::string& text) {
    try {
        load_scenario(scenes / "knocked_off.toml", overrides);
        ADD_FAILURE() << "no error for " << overrides.front();
    } catch (const InputError& e) {
        EXPECT_EQ(e.where().key, key) << e.what();
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

TEST(Outcomes, BadKeysAreNamedErrors) {
    expect_input_error({"outcomes.fall_drop_ratio=-0.5"}, "outcomes.fall_drop_ratio", "must be >= 0");
    expect_input_error({"outcomes.rest_speed=\"slow\""}, "outcomes.rest_speed", "must be a number");
    expect_input_error({"outcomes.slip_ratio=nan"}, "outcomes.slip_ratio", "finite");
    expect_input_error({"simulation.domain=[[-1, 0], [1, 5]]"}, "simulation.domain", "does not contain body 'table'");
    expect_input_error({"simulation.domain=[[1, 0], [-1, 5]]"}, "simulation.domain", "below and left");
    expect_input_error({"simulation.domain=[[-1, 0]]"}, "simulation.domain", "two corners");
}

TEST(Outcomes, ThresholdsAreRead) {
    const LoadedScenario s = load_scenario(scenes / "knocked_off.toml", {"outcomes.fall_drop_ratio=2.0", "outcomes.support_window=0.02"});
    EXPECT_DOUBLE_EQ(s.world.settings.outcomes.fall_drop_ratio, 2.0);
    EXPECT_DOUBLE_EQ(s.world.settings.outcomes.support_window_s, 0.02);
    EXPECT_DOUBLE_EQ(s.world.settings.outcomes.slip_ratio, 1e-3);   // default kept
}

TEST(Outcomes, FallDropRatioDecidesTheFall) {
    // The cube drops 0.4 m (its height): with a threshold of 1.5 heights it did not fall.
    const nlohmann::json s = run("knocked_off", {"outcomes.fall_drop_ratio=1.5"});
    EXPECT_EQ(body(s, "upper")["outcome"], "rocked_and_slid");
}

}  // namespace
}  // namespace blockdem
