// The verdict of `blockdem converge` on constructed summaries (docs/convergence.md): the
// relative change with its floor, the last refinement deciding, flags and words compared for
// equality, the ensemble telling a chaotic response from a too-long time step, the stiffness
// study; and the plan of runs (the overrides each run gets).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/input_error.hpp"
#include "study/convergence_plan.hpp"
#include "study/convergence_verdict.hpp"

namespace blockdem {
namespace {

// A summary.json as `blockdem run` writes it, reduced to what the study reads: one fixed table
// and one dynamic body "block".
struct Body {
    double rotation_rad = 0.0;
    double slip_m = 0.0;
    bool overturned = false;
    double overturning_time_s = 0.0;
    const char* outcome = nullptr;  // absent in today's summaries
};

nlohmann::json summary(const Body& b, double dt_s = 1e-4) {
    nlohmann::json body{{"name", "block"},
                        {"kind", "dynamic"},
                        {"peak_abs_rotation_rad", b.rotation_rad},
                        {"peak_abs_base_slip_m", b.slip_m},
                        {"final_base_slip_m", -b.slip_m},
                        {"overturned", b.overturned},
                        {"overturning_time_s", b.overturned ? nlohmann::json(b.overturning_time_s) : nlohmann::json(nullptr)}};
    if (b.outcome) body["outcome"] = b.outcome;
    return {{"status", "completed"}, {"dt_s", dt_s}, {"bodies", {{{"name", "table"}, {"kind", "fixed"}}, body}}};
}

std::vector<RunOutcome> runs(const std::vector<Body>& bodies, const std::string& prefix) {
    std::vector<RunOutcome> out;
    for (std::size_t i = 0; i < bodies.size(); ++i) out.push_back(outcome_of_summary(summary(bodies[i]), prefix + std::to_string(i)));
    return out;
}

ConvergenceResult judge(const std::vector<Body>& over_dt, const std::vector<Body>& ensemble = {},
                        const std::vector<Body>& stiffness = {}) {
    StudyRuns r{runs(over_dt, "dt"), runs(ensemble, "ensemble_"), runs(stiffness, "kn")};
    return judge_convergence(r, ConvergenceTolerance{});
}

const QuantityComparison& quantity(const ConvergenceResult& r, const std::string& name) {
    const auto& q = r.bodies.at(0).dt;
    const auto it = std::find_if(q.begin(), q.end(), [&](const QuantityComparison& c) { return c.quantity == name; });
    if (it == q.end()) throw std::runtime_error("no quantity " + name);
    return *it;
}

TEST(Convergence, RelativeChangeUsesTheLargerValueOrTheFloor) {
    EXPECT_DOUBLE_EQ(relative_change(0.1, 0.11, 0.01), 0.01 / 0.11);
    EXPECT_DOUBLE_EQ(relative_change(-0.2, 0.2, 0.01), 2.0);
    // A block at rest: 1e-6 rad against 3e-6 rad is not a 67% change but 2e-4 of the floor.
    EXPECT_DOUBLE_EQ(relative_change(1e-6, 3e-6, 0.01), 2e-4);
    EXPECT_DOUBLE_EQ(relative_change(0.0, 0.0, 0.0), 0.0);
}

TEST(Convergence, ShrinkingChangesAreConvergedWithTheirObservedOrder) {
    const auto r = judge({{0.100, 0.02}, {0.104, 0.02}, {0.105, 0.02}});
    EXPECT_EQ(r.verdict, Verdict::converged);
    EXPECT_EQ(r.converged_count, 1);
    const auto& q = quantity(r, "peak_rotation_rad");
    ASSERT_TRUE(q.change_ratio.has_value());
    EXPECT_NEAR(*q.change_ratio, 4.0, 1e-9);
    EXPECT_NEAR(*q.observed_order, 2.0, 1e-9);
    EXPECT_NEAR(*q.changes[1], 0.001 / 0.105, 1e-12);
    EXPECT_TRUE(r.bodies[0].base_within_tolerance);  // 0.100 against 0.105: 4.8%
}

TEST(Convergence, TheLastRefinementDecides) {
    // The issue's case: 0.0164 rad at dt, 0.09 at dt/2 and dt/4: the dt/4 answer is converged,
    // the base dt's is not, and the report says so.
    auto r = judge({{0.0164, 0.0}, {0.090, 0.0}, {0.091, 0.0}});
    EXPECT_EQ(r.verdict, Verdict::converged);
    EXPECT_FALSE(r.bodies[0].base_within_tolerance);
    // Changing by 20% at the last refinement is not converged, and the reason names it.
    r = judge({{0.10, 0.0}, {0.09, 0.0}, {0.072, 0.0}});
    EXPECT_EQ(r.verdict, Verdict::not_converged);
    EXPECT_FALSE(quantity(r, "peak_rotation_rad").converged);
    ASSERT_EQ(r.bodies[0].reasons.size(), 1u);
    EXPECT_NE(r.bodies[0].reasons[0].find("peak_rotation_rad changes by 20%"), std::string::npos) << r.bodies[0].reasons[0];
}

TEST(Convergence, FloorsKeepQuantitiesNearZeroFromFailing) {
    // Rotation 1e-6 -> 3e-6 -> 9e-6 rad and slip 1e-7 -> 4e-7 m: tripling, but far below the floors.
    const auto r = judge({{1e-6, 1e-7}, {3e-6, 2e-7}, {9e-6, 4e-7}});
    EXPECT_EQ(r.verdict, Verdict::converged);
    // Rotations of a rocking block tripling: not converged.
    EXPECT_EQ(judge({{1e-4, 1e-5}, {2e-4, 2e-5}, {4e-4, 4e-5}}).verdict, Verdict::converged);  // 2% of the floors
    EXPECT_EQ(judge({{1e-2, 1e-7}, {3e-2, 1e-7}, {9e-2, 1e-7}}).verdict, Verdict::not_converged);
}

TEST(Convergence, AChangedOverturnedFlagIsNotConverged) {
    // Standing at dt/2, overturned at dt/4 (with nearly the same peak so far): not converged.
    auto r = judge({{0.20, 0.0}, {0.20, 0.0}, {0.201, 0.0, true, 6.0}});
    EXPECT_EQ(r.verdict, Verdict::not_converged);
    EXPECT_FALSE(quantity(r, "overturned").converged);
    // Overturned at dt only: converged at dt/4, but the base run's answer is not.
    r = judge({{1.5, 0.0, true, 6.0}, {0.20, 0.0}, {0.201, 0.0}});
    EXPECT_EQ(r.verdict, Verdict::converged);
    EXPECT_FALSE(r.bodies[0].base_within_tolerance);
}

TEST(Convergence, OverturningTimesAreComparedAndTheFallIsNotJudged) {
    // Overturned in every run: the time decides (5.0 s against 5.5 s: 9%); the peak rotation
    // and slip after the fall are reported, not judged.
    auto r = judge({{1.6, 0.3, true, 5.0}, {1.6, 0.9, true, 5.0}, {1.6, 2.0, true, 5.5}});
    EXPECT_EQ(r.verdict, Verdict::not_converged);
    EXPECT_FALSE(quantity(r, "overturning_time_s").converged);
    EXPECT_FALSE(quantity(r, "peak_slip_m").judged);
    r = judge({{1.6, 0.3, true, 5.00}, {1.6, 0.9, true, 5.01}, {1.6, 2.0, true, 5.02}});
    EXPECT_EQ(r.verdict, Verdict::converged);
}

TEST(Convergence, OutcomeWordsAreComparedWhenEveryRunHasThem) {
    auto r = judge({{0.02, 0.0, false, 0, "rocked"}, {0.02, 0.0, false, 0, "rocked"}, {0.02, 0.0, false, 0, "slid"}});
    EXPECT_EQ(r.verdict, Verdict::not_converged);
    EXPECT_FALSE(quantity(r, "outcome").converged);
    // A summary without "outcome" (written before the key existed): not compared.
    r = judge({{0.02, 0.0, false, 0, "rocked"}, {0.02, 0.0}, {0.02, 0.0, false, 0, "slid"}});
    EXPECT_EQ(r.verdict, Verdict::converged);
    EXPECT_THROW(quantity(r, "outcome"), std::runtime_error);
}

TEST(Convergence, AnEnsembleAsWideAsTheTimeStepsIsChaotic) {
    // Not converged over dt (0.10, 0.30, 0.15), and tiny perturbations at dt give 0.08 .. 0.28:
    // the differences are those of a chaotic response.
    const std::vector<Body> over_dt = {{0.10, 0.0}, {0.30, 0.0}, {0.15, 0.0}};
    auto r = judge(over_dt, {{0.28, 0.0}, {0.08, 0.0}, {0.2, 0.0}});
    EXPECT_EQ(r.verdict, Verdict::chaotic);
    EXPECT_EQ(r.chaotic_count, 1);
    const auto& spread = r.bodies[0].ensemble.at(0);
    EXPECT_EQ(spread.quantity, "peak_rotation_rad");
    EXPECT_NEAR(*spread.mean, (0.10 + 0.28 + 0.08 + 0.2) / 4.0, 1e-12);  // the base run is a member
    EXPECT_DOUBLE_EQ(*spread.min, 0.08);
    EXPECT_DOUBLE_EQ(*spread.max, 0.28);
    EXPECT_NEAR(*spread.dt_spread_ratio, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(*r.bodies[0].fraction_overturned, 0.0);
    // Perturbations that move the answer by less than the tolerance: a too-long time step.
    r = judge(over_dt, {{0.101, 0.0}, {0.099, 0.0}});
    EXPECT_EQ(r.verdict, Verdict::not_converged);
    // Sensitive beyond the tolerance but far narrower than the dt spread: still the time step.
    r = judge(over_dt, {{0.12, 0.0}, {0.10, 0.0}});
    EXPECT_EQ(r.verdict, Verdict::not_converged);
    EXPECT_TRUE(r.bodies[0].ensemble.at(0).sensitive);
}

TEST(Convergence, MixedOverturningInTheEnsembleIsChaoticWithItsFraction) {
    // Converged over dt by chance, but two of four members overturn.
    const auto r = judge({{0.20, 0.0}, {0.21, 0.0}, {0.21, 0.0}}, {{1.6, 0.0, true, 7.0}, {0.2, 0.0}, {1.6, 0.0, true, 7.2}});
    EXPECT_EQ(r.verdict, Verdict::chaotic);
    EXPECT_DOUBLE_EQ(*r.bodies[0].fraction_overturned, 0.5);
    // The peak rotation of members that fell is no response: reported, not judged.
    EXPECT_EQ(r.bodies[0].ensemble.at(0).quantity, "peak_rotation_rad");
    EXPECT_FALSE(r.bodies[0].ensemble.at(0).judged);
    EXPECT_FALSE(r.bodies[0].ensemble.at(0).chaotic);
}

TEST(Convergence, StiffnessSensitivityIsReportedApart) {
    // The column of issue 17: stands at 0.5 x kn, collapses at 1 x and 2 x.
    const std::vector<Body> over_dt = {{1.6, 0.0, true, 6.9}, {1.6, 0.0, true, 6.9}, {1.6, 0.0, true, 6.9}};
    auto r = judge(over_dt, {}, {{0.17, 0.0}, {1.6, 0.0, true, 6.9}, {1.6, 0.0, true, 7.7}});
    EXPECT_EQ(r.verdict, Verdict::converged);
    ASSERT_TRUE(r.stiffness_sensitive.has_value());
    EXPECT_TRUE(*r.stiffness_sensitive);
    EXPECT_TRUE(r.bodies[0].stiffness_sensitive);
    r = judge(over_dt, {}, {{1.6, 0.0, true, 6.9}, {1.6, 0.0, true, 6.9}, {1.6, 0.0, true, 6.91}});
    EXPECT_FALSE(*r.stiffness_sensitive);
    EXPECT_FALSE(judge(over_dt).stiffness_sensitive.has_value());  // not studied
}

TEST(Convergence, AFailedRefinementRunIsNotConverged) {
    StudyRuns r{runs({{0.1, 0.0}, {0.1, 0.0}, {0.1, 0.0}}, "dt"), {}, {}};
    r.refinement[2].status = "failed";
    r.refinement[2].error = "unstable at t = 1 s";
    const auto result = judge_convergence(r, ConvergenceTolerance{});
    EXPECT_EQ(result.verdict, Verdict::not_converged);
    ASSERT_EQ(result.failed_runs.size(), 1u);
    EXPECT_EQ(result.failed_runs[0], "dt2: unstable at t = 1 s");
}

TEST(Convergence, ASummaryWithoutAQuantityIsRefusedByName) {
    nlohmann::json s = summary({0.1, 0.0});
    s["bodies"][1].erase("peak_abs_base_slip_m");
    try {
        outcome_of_summary(s, "dt_2");
        FAIL() << "accepted a summary without peak_abs_base_slip_m";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("run dt_2, body 'block': no number 'peak_abs_base_slip_m'"), std::string::npos) << e.what();
    }
}

// A 3-D summary (run/run_scenario_3d.cpp): the peak tilt about any horizontal axis stands for
// the peak rotation, the slip vector's length for the slip; no overturning time is given.
TEST(Convergence, A3dSummaryGivesItsTiltAndTheLengthOfItsSlipVector) {
    const nlohmann::json body{{"name", "drum_1"},      {"kind", "dynamic"},        {"peak_tilt_rad", 0.14},
                              {"peak_slip_m", 0.2},    {"slip_m", {0.03, -0.04}},  {"overturned", true},
                              {"rotation_vector_rad", {0.0, 0.1, 0.0}}};
    const nlohmann::json s{{"status", "completed"}, {"dimension", 3}, {"dt_s", 3.5e-5},
                           {"bodies", {{{"name", "table"}, {"kind", "driven"}}, body}}};
    const RunOutcome r = outcome_of_summary(s, "dt");
    ASSERT_EQ(r.bodies.size(), 1u);
    EXPECT_EQ(r.bodies[0].name, "drum_1");
    EXPECT_EQ(r.bodies[0].peak_rotation_rad, 0.14);
    EXPECT_EQ(r.bodies[0].peak_slip_m, 0.2);
    EXPECT_NEAR(r.bodies[0].final_slip_m, 0.05, 1e-15);
    EXPECT_TRUE(r.bodies[0].overturned);
    EXPECT_FALSE(r.bodies[0].overturning_time_s.has_value());
    nlohmann::json bad = s;
    bad["bodies"][1]["slip_m"] = {0.03};
    try {
        outcome_of_summary(bad, "dt_4");
        FAIL() << "accepted a slip vector of one component";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("run dt_4, body 'drum_1': no slip vector 'slip_m'"), std::string::npos) << e.what();
    }
}

// A 3-D scenario has no [output] report key (its reader refuses it): the runs do not set it.
TEST(ConvergencePlan, A3dScenarioGetsNoReportKey) {
    const toml::table scenario = toml::parse("dimension = 3\n[simulation]\ngravity = 9.81\n[contact]\nkn = 1e8\nks = 1e8\n");
    for (const PlannedRun& run : plan_follow_up_runs(scenario, 1e-4, ConvergenceOptions{true, 2, 1e-9})) {
        EXPECT_EQ(std::count(run.overrides.begin(), run.overrides.end(), "output.report=false"), 0) << run.label;
        EXPECT_EQ(std::count(run.overrides.begin(), run.overrides.end(), "output.vtk=false"), 1) << run.label;
    }
    const toml::table two_d = toml::parse("[simulation]\ngravity = 9.81\n");
    const auto plan = plan_follow_up_runs(two_d, 1e-4, ConvergenceOptions{});
    EXPECT_EQ(std::count(plan[0].overrides.begin(), plan[0].overrides.end(), "output.report=false"), 1);
}

TEST(ConvergencePlan, RunsCarryTheirTimeStepStiffnessAndPerturbation) {
    const toml::table scenario = toml::parse(R"(
[simulation]
gravity = 9.81
[contact]
kn = 1e9
ks = 5e8
[[contact.pairs]]
materials = ["a", "b"]
kn = 2e6
[[contact.pairs]]
materials = ["a", "c"]
mu = 0.1
)");
    const auto plan = plan_follow_up_runs(scenario, 1e-4, ConvergenceOptions{true, 2, 1e-9});
    ASSERT_EQ(plan.size(), 6u);
    EXPECT_EQ(plan[0].label, "dt_2");
    EXPECT_EQ(plan[1].label, "dt_4");
    EXPECT_EQ(plan[1].overrides[0], "simulation.dt=" + toml_float(2.5e-5));
    EXPECT_EQ(plan[2].label, "kn_x0.5");
    EXPECT_EQ(plan[3].label, "kn_x2");
    const auto& kn2 = plan[3].overrides;
    for (const std::string& want : {"simulation.dt=" + toml_float(5e-5), "contact.kn=" + toml_float(2e9),
                                    "contact.ks=" + toml_float(1e9), "contact.pairs.0.kn=" + toml_float(4e6)})
        EXPECT_NE(std::find(kn2.begin(), kn2.end(), want), kn2.end()) << want;
    // The second pair inherits kn and ks: nothing to scale there.
    EXPECT_EQ(std::count_if(kn2.begin(), kn2.end(), [](const std::string& s) { return s.rfind("contact.pairs.1", 0) == 0; }), 0);
    EXPECT_EQ(plan[4].label, "ensemble_1");
    EXPECT_EQ(plan[4].overrides.back(), "simulation.gravity=" + toml_float(9.81 * (1 + 1e-9)));
    EXPECT_EQ(plan[5].overrides.back(), "simulation.gravity=" + toml_float(9.81 * (1 - 1e-9)));
    EXPECT_NE(9.81 * (1 + 1e-9), 9.81);
}

TEST(ConvergencePlan, EnsemblePerturbationsAreDistinctAndNeverZero) {
    const auto d = ensemble_perturbations(5, 1e-9);
    ASSERT_EQ(d.size(), 5u);
    EXPECT_DOUBLE_EQ(d[0], 1e-9 / 3);
    EXPECT_DOUBLE_EQ(d[1], -1e-9 / 3);
    EXPECT_DOUBLE_EQ(d[4], 1e-9);
    for (std::size_t i = 0; i < d.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) EXPECT_NE(d[i], d[j]);
}

TEST(ConvergencePlan, NothingToPerturbOrScaleIsBadInput) {
    const toml::table no_gravity = toml::parse("[simulation]\ngravity = 0.0\n[contact]\nkn = 1e6\nks = 1e6\n");
    EXPECT_THROW(plan_follow_up_runs(no_gravity, 1e-4, ConvergenceOptions{false, 3, 1e-9}), InputError);
    EXPECT_NO_THROW(plan_follow_up_runs(no_gravity, 1e-4, ConvergenceOptions{true, 0, 1e-9}));
    EXPECT_THROW(plan_follow_up_runs(toml::table{}, 1e-4, ConvergenceOptions{false, 2, 0.1}), InputError);
    EXPECT_THROW(plan_follow_up_runs(toml::table{}, 1e-4, ConvergenceOptions{true, 0, 1e-9}), InputError);
}

TEST(ConvergencePlan, TomlFloatsReadBackAsTheSameDouble) {
    for (const double x : {2e9, 5e-05, 9.81 * (1 + 1e-9), 0.1, 1.0 / 3.0, 12345678.0}) {
        const std::string text = toml_float(x);
        const toml::table t = toml::parse("v = " + text);
        ASSERT_TRUE(t["v"].is_floating_point()) << text;
        EXPECT_EQ(*t["v"].value<double>(), x) << text;
    }
}

}  // namespace
}  // namespace blockdem
