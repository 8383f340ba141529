// A block cut from a rock mass by one joint set, resting on the fixed rock below the joint,
// slides iff tan(beta) > mu (the incline's closed form: a rigid block on a plane dipping at beta
// accelerates down the dip at g (sin beta - mu cos beta), or stays). Built through the scenario
// keys (type = "rock_mass", io/assembly_3d_keys.hpp) and stepped by World3d: the dip direction's
// convention is checked too, the block must go east for a joint dipping toward 90 deg.
// And a symmetric wedge cut by two sets, against Hoek & Bray's wedge factor.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "geometry/joint_set_3d.hpp"
#include "io/scenario_3d.hpp"
#include "validation/validation_constants.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;
using validation::g;
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


// A symmetric wedge (Hoek & Bray, "Rock slope engineering", the wedge with friction only): two
// joints dipping 45 deg toward 40 and 140 deg meet along a line plunging east at psi,
// tan psi = tan 45 cos 50; the block above both is held by the two normal forces, each
// W cos psi / (2 cos(theta / 2)) with theta the angle between the joints' normals, so it slides
// along the line iff mu < tan psi cos(theta / 2) (the wedge factor 1 / cos(theta / 2)), then
// accelerates at g (sin psi - mu cos psi / cos(theta / 2)).
// The joints meet below the region (0.8 m below its bottom east edge), so nothing lies below both:
// the wedge bears on its two flanks only, as the closed form has it (with the line inside the
// region, the rock below both joints would touch the wedge's keel edge, a contact the closed form
// does not have). The flanks' blocks reach the region's south and north faces and are fixed; the
// wedge's bottom face, on the region's bottom, has nothing under it.
// What is compared is the acceleration once sliding (from 0.1 to 0.5 s): the wedge is placed
// touching with its springs unloaded, and while it sinks into the flanks (about 1e-4 m) the
// friction is not yet there to hold it, so it starts with a speed the closed form does not have
// (measured: the slide is 9 % longer at kn = 1e8 N/m, 2.8 % at 1e9, going as sqrt(1 / kn), the
// loading time; the acceleration after it matches to 7e-5 at both).
LoadedScenario3d wedge(double mu_wedge) {
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
region_min = [0.0, -3.0, 0.0]
region_max = [1.0, 3.0, 1.0]
density = 2600.0
fixed = ["south", "north"]
[[assemblies.joint_sets]]
dip_direction_deg = 40.0
dip_deg = 45.0
spacing = 10.0
origin = [1.0, 0.0, -0.8]
[[assemblies.joint_sets]]
dip_direction_deg = 140.0
dip_deg = 45.0
spacing = 10.0
origin = [1.0, 0.0, -0.8]
)",
                                         mu_wedge);
    return load_scenario_3d(toml::parse(text), "rock_mass_wedge.toml", {});
}

TEST(RockMass3d, SymmetricWedgeSlidesAsTheWedgeFactorSays) {
    const Vec3 n1 = joint_normal(40.0, 45.0), n2 = joint_normal(140.0, 45.0);
    Vec3 line = normalized(cross(n1, n2));  // along the intersection
    if (line.z > 0.0) line = -line;         // downward: it must then point east
    ASSERT_GT(line.x, 0.0);
    ASSERT_LT(line.z, 0.0);
    const double psi = std::asin(-line.z);
    const double half_cos = std::cos(0.5 * std::acos(dot(n1, n2)));  // cos(theta / 2)
    const double mu_limit = std::tan(psi) * half_cos;                  // 0.5405
    const double duration_s = 0.5;
    for (const double mu_wedge : {1.05 * mu_limit, 0.9 * mu_limit}) {
        LoadedScenario3d s = wedge(mu_wedge);
        ASSERT_EQ(s.world.bodies.size(), 3u);
        std::size_t free = 0, dynamic = 0;
        for (std::size_t i = 0; i < s.world.bodies.size(); ++i)
            if (s.world.kinds[i] == BodyKind3d::dynamic) free = i, ++dynamic;
        ASSERT_EQ(dynamic, 1u);
        World3d& w = s.world;
        const Vec3 start = w.bodies[free].position_m;
        while (w.time_s < 0.2 * duration_s - 0.5 * w.dt_s) step_3d(w);
        const double early_speed_m_s = dot(w.bodies[free].velocity_at_t_m_s, line);
        while (w.time_s < 0.5 * duration_s - 0.5 * w.dt_s) step_3d(w);
        const Vec3 halfway = w.bodies[free].position_m;
        while (w.time_s < duration_s - 0.5 * w.dt_s) step_3d(w);
        const double acceleration_m_s2 =
            (dot(w.bodies[free].velocity_at_t_m_s, line) - early_speed_m_s) / (0.8 * duration_s);
        const Vec3 d = w.bodies[free].position_m - start;
        const double along_m = dot(d, line);
        const double expected_m_s2 = std::max(0.0, g * (std::sin(psi) - mu_wedge * std::cos(psi) / half_cos));
        const double expected_m = 0.5 * expected_m_s2 * duration_s * duration_s;
        std::printf("wedge, mu %.4f (limit %.4f): slid %.6g m along the line (closed form from rest %.6g m), "
                    "acceleration %.6g m/s^2 (closed form %.6g), off the line %.2g m\n",
                    mu_wedge, mu_limit, along_m, expected_m, acceleration_m_s2, expected_m_s2, length(d - along_m * line));
        if (expected_m == 0.0) {
            // Stays: it settles into the flanks' springs as it is loaded (placed touching, the
            // springs unloaded), then does not move.
            std::printf("  moved %.3g m in the second half\n", length(w.bodies[free].position_m - halfway));
            EXPECT_LT(length(d), 1e-3);
            EXPECT_LT(length(w.bodies[free].position_m - halfway), 1e-6);
        } else {
            // 0.5 % of the acceleration: the friction term is 0.9 of the gravity term here, so this
            // is 5e-4 of the wedge factor's friction; the start adds speed, never takes it.
            EXPECT_NEAR(acceleration_m_s2 / expected_m_s2, 1.0, 0.005);
            EXPECT_GT(along_m, expected_m);
            // Along the line: off it only the sinking into the flanks' normal springs, W cos psi /
            // (2 cos(theta / 2)) per flank on about four points of 1e8 N/m each, ~1e-4 m.
            EXPECT_LT(length(d - along_m * line), 2e-4);
        }
    }
}

}  // namespace
}  // namespace blockdem
