// The scenario key [contact] sub_contacts (contact/sub_contacts.hpp): 2 by default, read as a
// whole number from 2 to 16, refused out of range, with per-point stiffness (naming the key and
// the pair), or for one pair of materials (it is global).
#include <gtest/gtest.h>

#include <string>

#include "support/scenario_text.hpp"

namespace blockdem {
namespace {

std::string scenario(const std::string& contact_extra, const std::string& pairs = "") {
    return R"(
[simulation]
duration = 0.1
dt = 1.0e-5
[contact]
stiffness = "per_length"
kn = 1.0e9
ks = 4.0e8
mu = 0.6
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

TEST(SubContactKeys, TwoByDefaultAndReadAsAWholeNumber) {
    const auto two = load_scenario(testing::write_scenario("sub_contacts", "default", scenario("")), {});
    EXPECT_EQ(two.world.contact.sub_contacts, 2u);
    const auto eight = load_scenario(testing::write_scenario("sub_contacts", "set", scenario("sub_contacts = 8")), {});
    EXPECT_EQ(eight.world.contact.sub_contacts, 8u);
}

TEST(SubContactKeys, OutOfRangeRefusedNamingTheKey) {
    testing::expect_contains(testing::scenario_error("sub_contacts", "one", scenario("sub_contacts = 1")),
                             "contact.sub_contacts");
    testing::expect_contains(testing::scenario_error("sub_contacts", "many", scenario("sub_contacts = 17")),
                             "contact.sub_contacts");
    testing::expect_contains(testing::scenario_error("sub_contacts", "half", scenario("sub_contacts = 4.5")),
                             "contact.sub_contacts");
}

TEST(SubContactKeys, PerPointStiffnessRefusedNamingTheKeyAndThePair) {
    const std::string pair = "\n[[contact.pairs]]\nmaterials = [\"default\", \"default\"]\nstiffness = \"per_point\"\n"
                             "kn = 1.0e6\nks = 1.0e6\n";
    const std::string message = testing::scenario_error("sub_contacts", "per_point", scenario("sub_contacts = 4", pair));
    testing::expect_contains(message, "contact.sub_contacts");
    testing::expect_contains(message, "per_length");
    testing::expect_contains(message, "default / default");
}

TEST(SubContactKeys, NotAPropertyOfAPair) {
    const std::string pair = "\n[[contact.pairs]]\nmaterials = [\"default\", \"default\"]\nsub_contacts = 4\n";
    testing::expect_contains(testing::scenario_error("sub_contacts", "pair", scenario("", pair)), "sub_contacts");
}

}  // namespace
}  // namespace blockdem
