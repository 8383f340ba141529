// [contact] young_modulus: kn and ks derived from the material and the block size
// (docs/scenario.md, docs/physics.md "Choosing the contact stiffness"), and its bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "support/scenario_text.hpp"

namespace blockdem {
namespace {

using testing::expect_contains;
using testing::replace_once;

// Two 0.6 x 0.9 m drums on a 0.2 m high driven table, all of stone.
const char* column = R"(
[simulation]
duration = 0.01

[contact]
young_modulus = 30.0e9
poisson_ratio = 0.2
mu = 0.7
e = 0.4

[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]
material = "plate"

[[bodies]]
name = "drum0"
shape = "rectangle"
width = 0.6
height = 0.9
center = [0.0, 0.45]
density = 2600.0
material = "stone"

[[bodies]]
name = "drum1"
shape = "rectangle"
width = 0.6
height = 0.9
center = [0.0, 1.35]
density = 2600.0
material = "stone"
)";

LoadedScenario load(const std::string& name, const std::string& text, const std::vector<std::string>& sets = {}) {
    return load_scenario(testing::write_scenario("material", name, text), sets);
}

std::string material_error_of(const std::string& name, const std::string& text, const std::vector<std::string>& sets = {}) {
    return testing::scenario_error("material", name, text, sets);
}

// stone / stone: two equal drums, kn = E t w / (2 h) = 30e9 x 0.6 / 1.8 = 1e10 N/m.
// stone / plate: the drum's half height and the table's half height (0.1 m) in series, over the
// drum's 0.6 m face: kn = 1 / (0.45 / 30e9 + 0.1 / 30e9) x 0.3 = 1.636e10 N/m.
TEST(ScenarioMaterial, StiffnessDerivedPerMaterialPair) {
    const LoadedScenario s = load("derived", column);
    const MaterialPairs& c = s.world.contact;
    const auto stone = c.id("stone");
    const auto plate = c.id("plate");
    EXPECT_NEAR(c.at(stone, stone).kn_N_m, 1e10, 1.0);
    EXPECT_NEAR(c.at(stone, stone).ks_N_m, 1e10 / 2.4, 1.0);
    EXPECT_NEAR(c.at(stone, plate).kn_N_m, 0.3 / (0.45 / 30e9 + 0.1 / 30e9), 1.0);
    EXPECT_DOUBLE_EQ(c.at(plate, stone).kn_N_m, c.at(stone, plate).kn_N_m);
    ASSERT_FALSE(c.origins.empty());
    EXPECT_TRUE(c.origins[stone * c.materials.size() + plate].derived);
    EXPECT_DOUBLE_EQ(c.origins[stone * c.materials.size() + plate].b.block.height_m, 0.2);
    EXPECT_DOUBLE_EQ(c.at(stone, stone).mu, 0.7);
    // The stable step follows the derived stiffness: four times E, half the limit.
    const LoadedScenario stiffer = load("derived4", column, {"contact.young_modulus=120e9"});
    EXPECT_NEAR(stiffer.world.critical_dt_s / s.world.critical_dt_s, 0.5, 1e-9);
}

// "default" is used by no body here: its pairs copy the used material's side, so they never make
// the stable step smaller than the real pairs do.
TEST(ScenarioMaterial, UnusedMaterialPairsCopyTheUsedSide) {
    const std::string text = std::string(column) + R"(
[contact.materials.stone]
young_modulus = 3.0e9
)";
    const LoadedScenario s = load("unused", text);
    const MaterialPairs& c = s.world.contact;
    const auto stone = c.id("stone");
    const auto unused = c.id("default");
    EXPECT_NEAR(c.at(stone, stone).kn_N_m, 1e9, 1e-3);
    EXPECT_DOUBLE_EQ(c.at(unused, stone).kn_N_m, c.at(stone, stone).kn_N_m);
    EXPECT_DOUBLE_EQ(c.at(stone, unused).ks_N_m, c.at(stone, stone).ks_N_m);
}

// A material of its own, and a pair's explicit kn overriding the rule (ks stays derived).
TEST(ScenarioMaterial, PerMaterialModulusAndPairOverride) {
    const std::string text = std::string(column) + R"(
[contact.materials.plate]
young_modulus = 200.0e9
poisson_ratio = 0.3

[[contact.pairs]]
materials = ["stone", "stone"]
kn = 5.0e8
)";
    const LoadedScenario s = load("override", text);
    const MaterialPairs& c = s.world.contact;
    const auto stone = c.id("stone");
    const auto plate = c.id("plate");
    EXPECT_DOUBLE_EQ(c.at(stone, stone).kn_N_m, 5e8);
    EXPECT_NEAR(c.at(stone, stone).ks_N_m, 1e10 / 2.4, 1.0);
    EXPECT_TRUE(c.origins[stone * c.materials.size() + stone].kn_given);
    EXPECT_FALSE(c.origins[stone * c.materials.size() + stone].ks_given);
    EXPECT_NEAR(c.at(stone, plate).kn_N_m, 0.3 / (0.45 / 30e9 + 0.1 / 200e9), 1.0);
    const double g_plate = 200e9 / 2.6;
    EXPECT_NEAR(c.at(stone, plate).ks_N_m, 0.3 / (0.45 / 12.5e9 + 0.1 / g_plate), 1.0);
}

TEST(ScenarioMaterial, ModulusAndExplicitStiffnessTogetherRefused) {
    const std::string m = material_error_of("both", replace_once(column, "mu = 0.7", "mu = 0.7\nkn = 1.0e9"));
    expect_contains(m, "contact.kn");
    expect_contains(m, "give either young_modulus");
    expect_contains(m, "not both");
    expect_contains(material_error_of("both_ks", replace_once(column, "mu = 0.7", "mu = 0.7\nks = 1.0e9")), "contact.ks");
    // The same through --set: an override cannot silently win either.
    expect_contains(material_error_of("both_set", column, {"contact.kn=1e9"}), "contact.kn");
}

TEST(ScenarioMaterial, BadModulusAndPoissonRatioRefused) {
    for (const char* bad : {"0.0", "-30.0e9"})
        expect_contains(material_error_of("bad_e", replace_once(column, "young_modulus = 30.0e9", std::string("young_modulus = ") + bad)),
                        "contact.young_modulus': must be > 0");
    for (const char* bad : {"0.5", "-1.0", "0.7", "-2.0"})
        expect_contains(material_error_of("bad_nu", replace_once(column, "poisson_ratio = 0.2", std::string("poisson_ratio = ") + bad)),
                        "contact.poisson_ratio': must be in (-1, 0.5)");
    EXPECT_EQ(material_error_of("good_nu", replace_once(column, "poisson_ratio = 0.2", "poisson_ratio = -0.5")), "");
}

TEST(ScenarioMaterial, UnknownRuleRefused) {
    const std::string m = material_error_of("rule", replace_once(column, "mu = 0.7", "mu = 0.7\nstiffness_rule = \"block_deformabilty\""));
    expect_contains(m, "contact.stiffness_rule");
    expect_contains(m, "did you mean 'block_deformability'");
    EXPECT_EQ(material_error_of("rule_ok", replace_once(column, "mu = 0.7", "mu = 0.7\nstiffness_rule = \"block_deformability\"")), "");
}

TEST(ScenarioMaterial, MisplacedMaterialKeysRefused) {
    // Neither a modulus nor kn and ks.
    expect_contains(material_error_of("none", replace_once(column, "young_modulus = 30.0e9\npoisson_ratio = 0.2\n", "")),
                    "missing the contact stiffness");
    // poisson_ratio or a rule without a modulus.
    const std::string explicit_k = replace_once(column, "young_modulus = 30.0e9\npoisson_ratio = 0.2\n", "kn = 1e9\nks = 1e9\n");
    EXPECT_EQ(material_error_of("explicit", explicit_k), "");
    expect_contains(material_error_of("nu_alone", replace_once(explicit_k, "mu = 0.7", "mu = 0.7\npoisson_ratio = 0.2")),
                    "contact.poisson_ratio': needs young_modulus");
    expect_contains(material_error_of("rule_alone", replace_once(explicit_k, "mu = 0.7", "mu = 0.7\nstiffness_rule = \"block_deformability\"")),
                    "contact.stiffness_rule': needs young_modulus");
    // A material's modulus without the rule, or for a material no body uses.
    expect_contains(material_error_of("mat_explicit", explicit_k + "\n[contact.materials.plate]\nyoung_modulus = 2e11\n"),
                    "contact.materials");
    expect_contains(material_error_of("mat_unknown", std::string(column) + "\n[contact.materials.plat]\nyoung_modulus = 2e11\n"),
                    "did you mean 'plate'");
    expect_contains(material_error_of("mat_bad", std::string(column) + "\n[contact.materials.plate]\nyoung_modulus = -1.0\n"),
                    "contact.materials.plate.young_modulus': must be > 0");
    expect_contains(material_error_of("mat_typo", std::string(column) + "\n[contact.materials.plate]\nyoungs_modulus = 2e11\n"),
                    "did you mean 'young_modulus'");
    // A modulus is a material's, not a pair's.
    expect_contains(material_error_of("pair_e", std::string(column) +
                                                    "\n[[contact.pairs]]\nmaterials = [\"stone\", \"plate\"]\nyoung_modulus = 2e11\n"),
                    "is a property of one material");
}

}  // namespace
}  // namespace blockdem
