// The model's extent in 3-D (world/model_domain_3d.hpp) against free fall: a box dropped beside
// a fixed slab falls as z(t) = z0 - g t^2 / 2 (the central-difference scheme is exact for a
// constant acceleration), so it leaves the derived extent at the first step whose posed box top
// is below the extent's floor, the slab's bottom less one body diagonal; its energy then moves to
// removed_j with the ledger closed, and it stays where it left.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "io/input_error.hpp"
#include "io/scenario_3d.hpp"
#include "validation/validation_constants.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

using validation::g;

LoadedScenario3d dropped_beside_a_slab(const std::string& simulation_more = "") {
    const std::string text = R"(dimension = 3
[simulation]
duration = 2.0
dt = 1e-4
)" + simulation_more + R"(
[contact]
kn = 1e6
ks = 1e6
mu = 0.5
[[bodies]]
name = "slab"
kind = "fixed"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "box"
shape = "box"
size = [0.2, 0.2, 0.1]
position = [1.5, 0.0, 0.05]
density = 2000.0
)";
    return load_scenario_3d(toml::parse(text), std::filesystem::path(BLOCKDEM_SOURCE_DIR) / "domain_3d.toml", {});
}

TEST(ModelDomain3d, AFreelyFallingBoxLeavesAtTheFreeFallTimeWithItsEnergyBooked) {
    LoadedScenario3d s = dropped_beside_a_slab();
    World3d& w = s.world;
    const double diagonal_m = std::sqrt(0.2 * 0.2 + 0.2 * 0.2 + 0.1 * 0.1);
    ASSERT_NEAR(w.domain.margin_m, diagonal_m, 1e-15);
    const double floor_m = -0.2 - diagonal_m;
    ASSERT_NEAR(w.domain.box_m.lo.z, floor_m, 1e-15);
    EXPECT_TRUE(std::isinf(w.domain.box_m.hi.z));
    // The box's top starts at z = 0.1 m: it leaves once 0.1 - g t^2 / 2 < floor.
    const double leave_s = std::sqrt(2.0 * (0.1 - floor_m) / g);
    while (w.domain.left.empty() && w.time_s < 1.0) step_3d(w);
    ASSERT_EQ(w.domain.left.size(), 1u);
    const BodyLeftModel3d left = w.domain.left.front();
    EXPECT_EQ(left.body, 1u);
    // Caught at the first step past the crossing (tolerance one step: the test runs per step).
    EXPECT_GE(left.time_s, leave_s - 1e-12);
    EXPECT_LE(left.time_s, leave_s + w.dt_s + 1e-12);
    // Where and how fast it left: free fall from rest, exact in the scheme to round-off.
    EXPECT_NEAR(left.position_m.z, 0.05 - 0.5 * g * left.time_s * left.time_s, 1e-9);
    EXPECT_NEAR(left.velocity_m_s.z, -g * left.time_s, 1e-9);
    const double m = w.bodies[1].mass_kg;
    const double removed_j = 0.5 * m * left.velocity_m_s.z * left.velocity_m_s.z + m * g * left.position_m.z;
    EXPECT_NEAR(w.ledger.removed_j, removed_j, 1e-9 * std::abs(removed_j));
    EXPECT_EQ(w.ledger.kinetic_j, 0.0);
    // It stays where it left, and the ledger keeps closing.
    for (int n = 0; n < 1000; ++n) step_3d(w);
    EXPECT_EQ(w.bodies[1].position_m.z, left.position_m.z);
    EXPECT_EQ(w.domain.left.size(), 1u);
    EXPECT_LT(w.ledger.balance_error(), 1e-9);
}

TEST(ModelDomain3d, AGivenExtentIsUsedAndMustContainEveryBody) {
    LoadedScenario3d s = dropped_beside_a_slab("domain = [[-2.0, -2.0, -0.5], [2.0, 2.0, 1.0]]\n");
    World3d& w = s.world;
    EXPECT_TRUE(w.domain.from_scenario);
    EXPECT_EQ(w.domain.margin_m, 0.0);
    // The box's top passes z = -0.5 m at sqrt(2 (0.1 + 0.5) / g).
    while (w.domain.left.empty() && w.time_s < 1.0) step_3d(w);
    ASSERT_EQ(w.domain.left.size(), 1u);
    EXPECT_NEAR(w.domain.left.front().time_s, std::sqrt(2.0 * 0.6 / g), w.dt_s + 1e-12);
    try {
        dropped_beside_a_slab("domain = [[-1.0, -1.0, -0.5], [1.0, 1.0, 1.0]]\n");
        FAIL() << "a domain that misses the box was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("simulation.domain"), std::string::npos) << what;
        EXPECT_NE(what.find("does not contain body 'box'"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace blockdem
