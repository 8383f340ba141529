// Bad input gets a clear error naming the file, the key or the body, and the line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "laws/restitution.hpp"
#include "support/scenario_text.hpp"

namespace blockdem {
namespace {

using testing::expect_contains;
using testing::replace_once;
using testing::write_scenario;
std::filesystem::path write(const std::string& name, const std::string& text) { return write_scenario("test", name, text); }

const char* valid = R"(
[simulation]
duration = 1.0
dt = 1.0e-4

[contact]
kn = 2.0e4
ks = 2.0e4
mu = 0.3
e = 0.4

[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]

[[bodies]]
name = "block"
shape = "rectangle"
width = 0.5
height = 0.2
center = [0.0, 0.1]
mass = 1.0

[table_motion.horizontal]
type = "sine"
amplitude = 350.0
unit = "gal"
period = 1.0
)";

// The error message for loading text with overrides ("" if it loads).
std::string error_of(const std::string& name, const std::string& text, const std::vector<std::string>& overrides = {}) {
    return testing::scenario_error("test", name, text, overrides);
}

TEST(ScenarioErrors, ValidScenarioLoads) {
    const LoadedScenario s = load_scenario(write("valid", valid), {});
    EXPECT_EQ(s.world.bodies.size(), 2u);
    EXPECT_NEAR(s.world.contact.at(0, 0).h_n, 0.28, 1e-4);
    EXPECT_DOUBLE_EQ(s.world.contact.at(0, 0).h_s, 1.0);
}

TEST(ScenarioErrors, MisspelledKeySuggestsTheNearest) {
    const std::string m = error_of("typo", replace_once(valid, "mu = 0.3", "muu = 0.3"));
    expect_contains(m, "blockdem-test-typo.toml:");
    expect_contains(m, "key 'contact.muu'");
    expect_contains(m, "did you mean 'mu'?");
}

TEST(ScenarioErrors, MisspelledBodyKeyNamesTheBodyAndLine) {
    const std::string m = error_of("bodytypo", replace_once(valid, "width = 0.5", "widht = 0.5"));
    expect_contains(m, "key 'bodies.block.widht'");
    expect_contains(m, "did you mean 'width'?");
    expect_contains(m, ".toml:23:");
}

TEST(ScenarioErrors, MissingRequiredKey) {
    expect_contains(error_of("missing", replace_once(valid, "duration = 1.0", "")), "missing required key 'simulation.duration'");
}

TEST(ScenarioErrors, WrongTypeAndUnits) {
    expect_contains(error_of("type", replace_once(valid, "kn = 2.0e4", "kn = \"stiff\"")),
                    "key 'contact.kn': must be a number, got the string \"stiff\"");
    expect_contains(error_of("unit", replace_once(valid, "unit = \"gal\"", "unit = \"gall\"")), "did you mean 'gal'?");
    expect_contains(error_of("negative", replace_once(valid, "mass = 1.0", "mass = -1.0")), "must be > 0");
}

TEST(ScenarioErrors, OverlapLimitIsAFractionOfAWidth) {
    expect_contains(error_of("overlap", valid, {"simulation.max_overlap=1.5"}),
                    "key 'simulation.max_overlap': is a fraction of the thinner body's least width and must be <= 1");
    expect_contains(error_of("overlap0", valid, {"simulation.max_overlap=0"}), "key 'simulation.max_overlap'");
    EXPECT_EQ(error_of("overlap_ok", valid, {"simulation.max_overlap=0.1"}), "");
}

TEST(ScenarioErrors, ConcaveAcceptedSelfIntersectingAndTouchingPolygonsRefused) {
    // A concave outline is a body (cut into convex parts, issue 13); one that crosses or
    // touches itself is not.
    const std::string arrow = R"(shape = "polygon"
vertices = [[0.0, 0.0], [0.5, 0.0], [0.5, 0.3], [0.25, 0.1], [0.0, 0.3]])";
    std::string text = replace_once(valid, "shape = \"rectangle\"\nwidth = 0.5\nheight = 0.2\ncenter = [0.0, 0.1]", arrow);
    EXPECT_EQ(error_of("concave", text), "");
    const std::string bowtie = R"(shape = "polygon"
vertices = [[0.0, 0.0], [0.5, 0.3], [0.5, 0.0], [0.0, 0.3]])";
    text = replace_once(valid, "shape = \"rectangle\"\nwidth = 0.5\nheight = 0.2\ncenter = [0.0, 0.1]", bowtie);
    expect_contains(error_of("bowtie", text), "key 'bodies.block.vertices': the edge from vertex");
    expect_contains(error_of("bowtie", text), "the outline crosses itself");
    const std::string touching = R"(shape = "polygon"
vertices = [[0.0, 0.0], [0.5, 0.0], [0.5, 0.3], [0.25, 0.0], [0.0, 0.3]])";
    text = replace_once(valid, "shape = \"rectangle\"\nwidth = 0.5\nheight = 0.2\ncenter = [0.0, 0.1]", touching);
    expect_contains(error_of("touching", text), "vertex 3 (0.25, 0) m lies on the edge from vertex 0 to vertex 1");
}

TEST(ScenarioErrors, OverlapAtStartNamesBothBodies) {
    expect_contains(error_of("overlap", replace_once(valid, "center = [0.0, 0.1]", "center = [0.0, 0.09]")),
                    "bodies 'table' and 'block' overlap at the start by 0.01 m");
}

TEST(ScenarioErrors, TimeStepAboveStableLimitIsRefusedWithTheLimit) {
    const std::string m = error_of("dt", replace_once(valid, "dt = 1.0e-4", "dt = 0.01"));
    expect_contains(m, "time step dt = 0.01 s is above the stable limit 0.00243 s");
    expect_contains(m, "body 'block'");
}

// A motion starts at rest: one that started before t = 0 had the table moving at the start.
TEST(ScenarioErrors, MotionStartBeforeZeroIsRefused) {
    const std::string words = "key 'table_motion.horizontal.start': must be >= 0 [s], got -5: a motion starts at rest, "
                              "and one that started before t = 0 would have the table already moving when the run begins";
    const std::string m = error_of("start", replace_once(valid, "period = 1.0", "period = 1.0\nstart = -5"));
    expect_contains(m, words);
    expect_contains(m, ".toml:33:");
    const std::string pulse = replace_once(valid, "type = \"sine\"", "type = \"one_cosine\"");
    expect_contains(error_of("pulse_start", replace_once(pulse, "period = 1.0", "period = 1.0\nstart = -5")), words);
    EXPECT_EQ(error_of("late_start", replace_once(valid, "period = 1.0", "period = 1.0\nstart = 0.5")), "");
}

// The step samples the motion once per dt: a period under 4 steps is not the motion the scenario
// gives. dt may be derived after the motion is read: the check waits for it.
TEST(ScenarioErrors, MotionPeriodUnderFourTimeStepsIsRefused) {
    const std::string m = error_of("period", replace_once(valid, "period = 1.0", "period = 1e-12"));
    expect_contains(m, ".toml:32:");
    expect_contains(m, "key 'table_motion.horizontal.period': the period 1e-12 s spans 1e-08 time steps of dt = 0.0001 s; it "
                       "must span at least 4: the step samples the motion once per dt, and fewer than 4 samples a cycle "
                       "miss its peaks (at 2, the Nyquist limit, the shaking is lost altogether); give a longer period or "
                       "a smaller simulation.dt");
    expect_contains(error_of("frequency", replace_once(valid, "period = 1.0", "frequency = 3000.0")),
                    "key 'table_motion.horizontal.frequency': the frequency 3000 Hz (a period of 0.000333333 s) spans "
                    "3.33 time steps of dt = 0.0001 s");
    EXPECT_EQ(error_of("four_steps", replace_once(valid, "period = 1.0", "period = 4.0e-4")), "");
    const std::string pulse = replace_once(valid, "type = \"sine\"", "type = \"one_sine\"");
    expect_contains(error_of("pulse_period", replace_once(pulse, "period = 1.0", "period = 1e-6")),
                    "key 'table_motion.horizontal.period': the period 1e-06 s spans 0.01 time steps");
    const std::string ricker = replace_once(replace_once(valid, "type = \"sine\"", "type = \"ricker\""), "period = 1.0",
                                            "frequency = 1e6");
    expect_contains(error_of("ricker", ricker), "key 'table_motion.horizontal.frequency': the frequency 1e+06 Hz");
    const std::string derived = replace_once(valid, "dt = 1.0e-4\n", "");
    expect_contains(error_of("derived_dt", replace_once(derived, "period = 1.0", "period = 1e-12")),
                    "key 'table_motion.horizontal.period': the period 1e-12 s spans");
}

TEST(ScenarioErrors, OverridesReachAnyKey) {
    const LoadedScenario s = load_scenario(write("override", valid), {"contact.h_s=0.5", "bodies.block.width=0.3",
                                                                      "table_motion.horizontal.type=one_sine"});
    EXPECT_DOUBLE_EQ(s.world.contact.at(0, 0).h_s, 0.5);
    EXPECT_NEAR(s.world.bodies.bounding_radius_m[1], std::hypot(0.15, 0.1), 1e-12);
    EXPECT_TRUE(std::holds_alternative<PulseMotion>(s.world.table_motion.horizontal));
    expect_contains(error_of("badset", valid, {"contact.hs=0.5"}), "did you mean 'h_s'?");
    expect_contains(error_of("badbody", valid, {"bodies.blok.width=1"}), "no element named or numbered 'blok'");
}

TEST(ScenarioErrors, MissingFileAndSyntaxError) {
    try {
        load_scenario("/nonexistent/scenario.toml", {});
        FAIL();
    } catch (const InputError& e) {
        expect_contains(e.what(), "/nonexistent/scenario.toml: cannot open the file");
    }
    expect_contains(error_of("syntax", replace_once(valid, "mu = 0.3", "mu = = 0.3")), "TOML syntax error");
}

TEST(ScenarioErrors, DuplicateNamesAndBadMaterialPairs) {
    expect_contains(error_of("dup", replace_once(valid, "name = \"block\"", "name = \"table\"")), "two bodies are named 'table'");
    const std::string pairs = std::string(valid) + "\n[[contact.pairs]]\nmaterials = [\"default\", \"stone\"]\nmu = 0.5\n";
    expect_contains(error_of("pairs", pairs), "no body uses material 'stone'");
}

}  // namespace
}  // namespace blockdem

namespace blockdem {
namespace {

TEST(ScenarioErrors, PairsInheritTheRestitutionMeaning) {
    std::string text = replace_once(valid, "e = 0.4", "e = 0.4\ne_meaning = \"rebound\"");
    text = replace_once(text, "name = \"block\"", "name = \"block\"\nmaterial = \"stone\"");
    text += "\n[[contact.pairs]]\nmaterials = [\"default\", \"stone\"]\ne = 0.4\n";
    const LoadedScenario s = load_scenario(write("inherit", text), {});
    const double rebound_h = damping_ratio_rebound(0.4);
    EXPECT_NEAR(s.world.contact.at(0, 1).h_n, rebound_h, 1e-12);
    EXPECT_NEAR(s.world.contact.at(0, 0).h_n, rebound_h, 1e-12);
}

TEST(ScenarioErrors, BodyNamesAndGravity) {
    expect_contains(error_of("name", replace_once(valid, "name = \"block\"", "name = \"block, left\"")), "is not a valid body name");
    expect_contains(error_of("emptyname", replace_once(valid, "name = \"block\"", "name = \"\"")), "is not a valid body name");
    expect_contains(error_of("gravity", replace_once(valid, "dt = 1.0e-4", "dt = 1.0e-4\ngravity = -9.81")), "must be >= 0");
}

TEST(ScenarioErrors, OverriddenValuesAreReportedByKeyWithoutAFakeLine) {
    const std::string m = error_of("setloc", valid, {"contact.kn=\"stiff\""});
    expect_contains(m, "key 'contact.kn': must be a number");
    EXPECT_EQ(m.find(".toml:1:"), std::string::npos) << m;
}

}  // namespace
}  // namespace blockdem
