// A block cut from a rock mass by one joint set, resting on the fixed rock below the joint,
// slides iff tan(beta) > mu (the incline's closed form: a rigid block on a plane dipping at beta
// accelerates down the dip at g (sin beta - mu cos beta), or stays). Built through the scenario
// keys (type = "rock_mass", io/assembly_3d_keys.hpp) and stepped by World3d: the dip direction's
// convention is checked too, the block must go east for a joint dipping toward 90 deg.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "io/scenario_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double g = 9.81;
constexpr double mu = 0.5;

// A 1 m cube of rock cut by one joint dipping at beta_deg toward east, through its bottom east
// edge (x = 1, z = 0): the wedge below it has the cube's bottom face and is fixed, the block
// above touches the bottom only along that edge and is free.
LoadedScenario3d cube_on_a_joint(double beta_deg) {
    const std::string text = fmt::format(R"(dimension = 3
[simulation]
duration = 0.5
[contact]
kn = 1e8
ks = 1e8
mu = {}
e = 0.2
[[assemblies]]
name = "rock"
type = "rock_mass"
region_min = [0.0, 0.0, 0.0]
region_max = [1.0, 1.0, 1.0]
density = 2600.0
fixed = ["bottom"]
[[assemblies.joint_sets]]
dip_direction_deg = 90.0
dip_deg = {}
spacing = 10.0
origin = [1.0, 0.0, 0.0]
)",
                                         mu, beta_deg);
    return load_scenario_3d(toml::parse(text), "rock_mass_incline.toml", {});
}

// The free block's displacement [m] after `duration_s`.
Vec3 slide_m(LoadedScenario3d& s, double duration_s) {
    World3d& w = s.world;
    EXPECT_EQ(w.bodies.size(), 2u);
    const std::size_t free = w.kinds[0] == BodyKind3d::dynamic ? 0 : 1;
    EXPECT_EQ(w.kinds[free], BodyKind3d::dynamic);
    EXPECT_EQ(w.kinds[1 - free], BodyKind3d::fixed);
    const Vec3 start = w.bodies[free].position_m;
    while (w.time_s < duration_s - 0.5 * w.dt_s) step_3d(w);
    return w.bodies[free].position_m - start;
}

TEST(RockMass3d, BlockOnAJointSlidesIffTanBetaAboveMu) {
    const double friction_deg = std::atan(mu) * 180.0 / pi;  // 26.57 deg
    const double duration_s = 0.5;
    for (const double beta_deg : {friction_deg - 1.0, friction_deg + 1.0}) {
        LoadedScenario3d s = cube_on_a_joint(beta_deg);
        const double beta = beta_deg * pi / 180.0;
        const Vec3 down_dip{std::cos(beta), 0.0, -std::sin(beta)};  // toward east (dip direction 90)
        const Vec3 d = slide_m(s, duration_s);
        const double along_m = dot(d, down_dip);
        const double expected_m = std::max(0.0, 0.5 * g * (std::sin(beta) - mu * std::cos(beta))) * duration_s * duration_s;
        SCOPED_TRACE(fmt::format("beta {:.2f} deg: slid {:.6g} m, closed form {:.6g} m", beta_deg, along_m, expected_m));
        std::printf("beta %.2f deg: slid %.6g m down the dip (closed form %.6g m), across %.2g m, dt %.3g s\n", beta_deg,
                    along_m, expected_m, d.y, s.world.dt_s);
        EXPECT_NEAR(d.y, 0.0, 1e-9);  // nothing drives it across the dip
        if (expected_m == 0.0) {
            // Stays: only the springs' elastic give, mu N / (4 ks) ~ 2e-5 m, and the settling
            // onto the normal springs, m g / (4 kn) ~ 5e-5 m.
            EXPECT_LT(std::abs(along_m), 1e-4);
        } else {
            // Slides east and down. 0.5 %: the shear springs' lag before slip, mu N / (4 ks) ~ 2e-5 m,
            // is 1e-3 of the slide at 1 deg above the friction angle (measured 8.5e-4).
            EXPECT_GT(d.x, 0.0);
            EXPECT_NEAR(along_m / expected_m, 1.0, 0.005);
        }
    }
}

}  // namespace
}  // namespace blockdem
