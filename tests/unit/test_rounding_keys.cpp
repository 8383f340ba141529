// The scenario key [contact] rounding: read, 0 by default, refused when negative, for one pair
// of materials (it is global), or when too large for a body (naming the body and the key).
#include <gtest/gtest.h>

#include <string>

#include "support/scenario_text.hpp"

namespace blockdem {
namespace {

std::string scenario(const std::string& contact_extra, const std::string& pairs = "") {
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
[[bodies]]
name = "slab"
shape = "rectangle"
width = 0.5
height = 0.04
center = [0.0, 0.02]
mass = 1.0
)" + pairs;
}

TEST(RoundingKeys, SharpByDefaultAndReadInMetres) {
    const auto sharp = load_scenario(testing::write_scenario("rounding", "default", scenario("")), {});
    EXPECT_EQ(sharp.world.contact.rounding_m, 0.0);
    const auto round = load_scenario(testing::write_scenario("rounding", "set", scenario("rounding = 0.002")), {});
    EXPECT_EQ(round.world.contact.rounding_m, 0.002);
}

TEST(RoundingKeys, NegativeRefusedNamingTheKey) {
    const std::string message = testing::scenario_error("rounding", "negative", scenario("rounding = -0.001"));
    testing::expect_contains(message, "contact.rounding");
    testing::expect_contains(message, ">= 0");
}

TEST(RoundingKeys, TooLargeForABodyNamesTheBodyAndTheKey) {
    // The slab is 0.04 m thick: a quarter of that is the limit.
    EXPECT_EQ(testing::scenario_error("rounding", "fits", scenario("rounding = 0.0099")), "");
    const std::string message = testing::scenario_error("rounding", "large", scenario("rounding = 0.01"));
    testing::expect_contains(message, "body 'slab'");
    testing::expect_contains(message, "[contact] rounding = 0.01 m");
    testing::expect_contains(message, "least width (0.04 m)");
}

TEST(RoundingKeys, NotAPropertyOfAPair) {
    const std::string pair = "\n[[contact.pairs]]\nmaterials = [\"default\", \"default\"]\nrounding = 0.001\n";
    testing::expect_contains(testing::scenario_error("rounding", "pair", scenario("", pair)), "rounding");
}

}  // namespace
}  // namespace blockdem
