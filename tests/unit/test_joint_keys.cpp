// The joint keys of [contact] and [[contact.pairs]] (stiffness = "per_length", cohesion,
// tensile_strength, residual_mu, friction_deg), bonded = true, and their bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scenario.hpp"
#include "support/scenario_text.hpp"

namespace blockdem {
namespace {

using testing::expect_contains;
using testing::replace_once;

// A block bonded to a fixed base, both 1 m wide, with a per-length joint.
const char* bonded_block = R"(
[simulation]
duration = 0.01

[contact]
stiffness = "per_length"
kn = 1.0e10
ks = 4.0e9
mu = 0.6
cohesion = 2.0e5
tensile_strength = 1.0e5
residual_mu = 0.5
e = 0.5

[[bodies]]
name = "base"
kind = "fixed"
shape = "rectangle"
width = 1.0
height = 0.2
center = [0.0, -0.1]
bonded = true

[[bodies]]
name = "block"
shape = "rectangle"
width = 1.0
height = 0.5
center = [0.0, 0.25]
density = 2000.0
thickness = 0.5
bonded = true
)";

std::string joint_key_error_of(const std::string& name, const std::string& text) {
    return testing::scenario_error("joint-keys", name, text);
}

TEST(JointKeys, PerLengthJointLoadsAndBondsTheTouchingBodies) {
    const LoadedScenario s = load_scenario(testing::write_scenario("joint-keys", "good", bonded_block), {});
    const ContactParameters& p = s.world.contact.at(0, 0);
    EXPECT_EQ(p.stiffness, StiffnessBasis::per_length);
    EXPECT_DOUBLE_EQ(p.kn_pa_m, 1e10);
    EXPECT_DOUBLE_EQ(p.ks_pa_m, 4e9);
    EXPECT_DOUBLE_EQ(p.cohesion_pa, 2e5);
    EXPECT_DOUBLE_EQ(p.tensile_strength_pa, 1e5);
    EXPECT_DOUBLE_EQ(residual_friction(p), 0.5);
    ASSERT_EQ(s.world.contacts.size(), 1u);
    const PairContact& pair = s.world.contacts[0];
    ASSERT_EQ(pair.count, 2u);
    for (std::uint32_t k = 0; k < 2; ++k) EXPECT_EQ(pair.points[k].bond, BondState::intact);
    // The stable step follows the points' stiffness, JKN x 0.5 m x 0.5 m: 2.5e9 N/m each on a
    // 500 kg block; without bonds (nothing touching) it would be the landing's.
    EXPECT_GT(s.world.critical_dt_s, 0.0);
    EXPECT_LT(s.world.critical_dt_s, 2.0 * std::sqrt(500.0 / 2.5e9));
}

TEST(JointKeys, FrictionAngleGivesMu) {
    const LoadedScenario s = load_scenario(
        testing::write_scenario("joint-keys", "angle", replace_once(bonded_block, "mu = 0.6\n", "friction_deg = 30.0\n")), {});
    EXPECT_NEAR(s.world.contact.at(0, 0).mu, std::tan(30.0 * 3.14159265358979 / 180.0), 1e-12);
}

TEST(JointKeys, JointPropertyWithPerPointStiffnessIsRefusedNamingTheKey) {
    const std::string text = replace_once(bonded_block, "stiffness = \"per_length\"\n", "");
    const std::string e = joint_key_error_of("per-point", replace_once(text, "bonded = true\n", ""));
    expect_contains(e, "contact.cohesion");
    expect_contains(e, "needs per-length stiffness, but per-point is set");
}

TEST(JointKeys, NegativeStrengthsAreRefused) {
    expect_contains(joint_key_error_of("neg-c", replace_once(bonded_block, "cohesion = 2.0e5", "cohesion = -1.0")),
                    "contact.cohesion");
    const std::string e = joint_key_error_of("neg-t", replace_once(bonded_block, "tensile_strength = 1.0e5", "tensile_strength = -1.0"));
    expect_contains(e, "contact.tensile_strength");
    expect_contains(e, "must be >= 0");
}

TEST(JointKeys, ResidualAbovePeakFrictionIsRefused) {
    const std::string e = joint_key_error_of("residual", replace_once(bonded_block, "residual_mu = 0.5", "residual_mu = 0.7"));
    expect_contains(e, "contact.residual_mu");
    expect_contains(e, "above the peak friction");
}

TEST(JointKeys, BondsNeedPerLengthStiffness) {
    std::string text = replace_once(bonded_block, "stiffness = \"per_length\"\n", "");
    for (const char* key : {"cohesion = 2.0e5\n", "tensile_strength = 1.0e5\n", "residual_mu = 0.5\n"})
        text = replace_once(text, key, "");
    const std::string e = joint_key_error_of("bonded-per-point", text);
    expect_contains(e, "contact.stiffness");
    expect_contains(e, "body 'base' is bonded");
}

TEST(JointKeys, PairChangingTheBasisMustGiveItsOwnStiffness) {
    const std::string pairs = std::string(bonded_block) + R"(
[[contact.pairs]]
materials = ["default", "default"]
stiffness = "per_point"
kn = 1.0e8
)";
    const std::string e = joint_key_error_of("pair-basis", replace_once(pairs, "bonded = true\n", ""));
    expect_contains(e, "contact.pairs[0].stiffness");
    expect_contains(e, "per-point stiffness given where per-length is set");
}

TEST(JointKeys, DilationAngleIsReadAndBounded) {
    const std::string good = replace_once(bonded_block, "residual_mu = 0.5", "residual_mu = 0.5\ndilation_deg = 20.0");
    const LoadedScenario s = load_scenario(testing::write_scenario("joint-keys", "dilation", good), {});
    EXPECT_DOUBLE_EQ(s.world.contact.at(0, 0).tan_dilation, std::tan(20.0 * std::acos(-1.0) / 180.0));
    EXPECT_TRUE(s.world.contact.any_dilation);
    // Out of [0, 45), above the (residual) friction angle 26.6 deg, or on a per-point contact: refused.
    const std::string too_large = joint_key_error_of("dilation-45", replace_once(good, "dilation_deg = 20.0", "dilation_deg = 45.0"));
    expect_contains(too_large, "contact.dilation_deg");
    expect_contains(too_large, "[0, 45)");
    const std::string above = joint_key_error_of("dilation-phi", replace_once(good, "dilation_deg = 20.0", "dilation_deg = 30.0"));
    expect_contains(above, "contact.dilation_deg");
    expect_contains(above, "above the joint's friction angle");
    const std::string per_point = replace_once(replace_once(replace_once(good, "stiffness = \"per_length\"\n", ""),
                                                            "cohesion = 2.0e5\ntensile_strength = 1.0e5\nresidual_mu = 0.5\n", ""),
                                               "kn = 1.0e10", "kn = 1.0e8");
    const std::string on_points = joint_key_error_of("dilation-per-point", per_point);
    expect_contains(on_points, "contact.dilation_deg");
    expect_contains(on_points, "per_length");
}

TEST(JointKeys, ZeroDilationSlipIsReadAndBounded) {
    const std::string good =
        replace_once(bonded_block, "residual_mu = 0.5", "residual_mu = 0.5\ndilation_deg = 20.0\ndilation_zero_slip = 0.002");
    const LoadedScenario s = load_scenario(testing::write_scenario("joint-keys", "zero-slip", good), {});
    EXPECT_DOUBLE_EQ(s.world.contact.at(0, 0).dilation_zero_slip_m, 0.002);
    const std::string negative =
        joint_key_error_of("zero-slip-negative", replace_once(good, "dilation_zero_slip = 0.002", "dilation_zero_slip = -0.002"));
    expect_contains(negative, "contact.dilation_zero_slip");
    expect_contains(negative, ">= 0");
    const std::string per_point = replace_once(replace_once(replace_once(replace_once(good, "stiffness = \"per_length\"\n", ""),
                                                                         "cohesion = 2.0e5\ntensile_strength = 1.0e5\nresidual_mu = 0.5\n", ""),
                                                            "dilation_deg = 20.0\n", ""),
                                               "kn = 1.0e10", "kn = 1.0e8");
    const std::string on_points = joint_key_error_of("zero-slip-per-point", per_point);
    expect_contains(on_points, "contact.dilation_zero_slip");
    expect_contains(on_points, "per_length");
}

}  // namespace
}  // namespace blockdem
