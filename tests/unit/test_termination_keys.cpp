// The scenario key [contact] termination (and per [[contact.pairs]]): read, inherited, and how
// it changes what e means (docs/scenario.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "laws/restitution.hpp"

namespace blockdem {
namespace {

std::string termination_scenario(const std::string& contact_extra, const std::string& pairs = "") {
    return R"(
[simulation]
duration = 0.1
dt = 1.0e-4
[contact]
kn = 2.0e4
ks = 2.0e4
mu = 0.3
e = 0.4
)" + contact_extra + R"(
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]
material = "steel"
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.5
height = 0.2
center = [0.0, 0.1]
mass = 1.0
)" + pairs;
}

LoadedScenario load(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("blockdem-termination-" + name + ".toml");
    std::ofstream(path) << text;
    return load_scenario(path, {});
}

TEST(TerminationKeys, DefaultIsNoTension) {
    const LoadedScenario s = load("default", termination_scenario(""));
    EXPECT_EQ(s.world.contact.at(0, 1).termination, ContactTermination::no_tension);
    EXPECT_NEAR(s.world.contact.at(0, 1).h_n, damping_ratio_paper(0.4), 1e-15);
}

TEST(TerminationKeys, ZeroOverlapMakesBothMeaningsThePapers) {
    // With the paper's termination the contact really rebounds with the paper's e, so asking
    // for a rebound of 0.4 gives the paper's h_n, not the no-tension one.
    const LoadedScenario s = load("zero", termination_scenario("termination = \"zero_overlap\"\ne_meaning = \"rebound\""));
    const ContactParameters& p = s.world.contact.at(0, 1);
    EXPECT_EQ(p.termination, ContactTermination::zero_overlap);
    EXPECT_NEAR(p.h_n, damping_ratio_paper(0.4), 1e-15);
    EXPECT_GT(damping_ratio_rebound(0.4) - p.h_n, 0.05);
}

TEST(TerminationKeys, PairsInheritAndOverride) {
    const std::string pair = "\n[[contact.pairs]]\nmaterials = [\"default\", \"steel\"]\ntermination = \"no_tension\"\n";
    const LoadedScenario s = load("pairs", termination_scenario("termination = \"zero_overlap\"", pair));
    const std::uint32_t steel = s.world.contact.id("steel");
    const std::uint32_t other = s.world.contact.id("default");
    EXPECT_EQ(s.world.contact.at(other, steel).termination, ContactTermination::no_tension);
    EXPECT_EQ(s.world.contact.at(steel, other).termination, ContactTermination::no_tension);
    EXPECT_EQ(s.world.contact.at(steel, steel).termination, ContactTermination::zero_overlap);
    const std::string inherit = "\n[[contact.pairs]]\nmaterials = [\"default\", \"steel\"]\nmu = 0.5\n";
    EXPECT_EQ(load("inherit", termination_scenario("termination = \"zero_overlap\"", inherit)).world.contact.at(other, steel).termination,
              ContactTermination::zero_overlap);
}

TEST(TerminationKeys, UnknownRuleNamesTheKey) {
    try {
        load("bad", termination_scenario("termination = \"sticky\""));
        FAIL() << "a bad termination loaded";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("contact.termination"), std::string::npos) << message;
        EXPECT_NE(message.find("zero_overlap"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace blockdem
