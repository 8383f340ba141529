// The one-sine pulse outcome in 3-D reduced to the 2-D case (tests/validation/test_rocking.cpp,
// peers' scene S2): a 0.4 x 1.0 x 1.6 m box (the 2-D block's b = 0.2, h = 0.8, one metre deep) on
// the 3-D table, shaken by a one-sine pulse of period 1 s normal to its 0.4 m faces, rocks about
// the edge of its 1.0 m side as Housner's block (analysis/housner_rocking.hpp) does: at 0.3 g to
// Housner's peak within the 2-D test's 5% and back, at 0.5 g over. The 2-D test's contact (its kn
// per metre of depth shared by the edge's two corners, e = 0.2) and its dt.
//
// Shaken normal to a face, the box rocks in one plane whatever that plane is, so the outcome
// must not depend on the direction: the box is shaken along x, along y with its 0.4 m side along
// y, and along the azimuth 30 deg with the box turned by 30 deg about the vertical (its faces
// then off the grid's axes). Shaking along 30 deg a box whose faces stay on x and y would rock it
// about a corner, a different problem with no 2-D counterpart; it is left out.
//
// The amplitude at which the outcome changes: bisected between 0.30 and 0.35 g on Housner's
// integration and on the DEM (along x), compared within 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "analysis/housner_rocking.hpp"
#include "laws/restitution.hpp"
#include "support/table_run_3d.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;
constexpr double b = 0.2, h = 0.8, depth = 1.0;
constexpr double pulse_density_kg_m3 = 1536.0;   // [kg/m^3] as the 2-D test
constexpr double period_s = 1.0;     // [s] of the pulse
constexpr double end_s = 5.0;        // [s] as the 2-D test
constexpr double overturned_rad = 1.2;  // [rad] far past alpha = 0.245: the 2-D test's mark of overturning

HousnerBlock housner_block() {
    HousnerBlock hb;
    hb.half_width_m = b;
    hb.half_height_m = h;
    hb.gravity_m_s2 = g;
    return hb;
}

PulseMotion pulse(double amplitude_g) { return {PulseMotion::Shape::one_sine, amplitude_g * g, period_s, 0.0}; }

// The box standing on the table at zero overlap, its 0.4 m side along the horizontal unit vector
// at `azimuth_rad` from x, shaken along that vector.
struct PulseOutcome {
    double peak_tilt_rad = 0.0;  // [rad] largest angle between the box's axis and the vertical
    bool overturned = false;
    double out_of_plane_rad = 0.0;  // [rad] largest turn about the shaking direction or the vertical
};

PulseOutcome run_pulse(double amplitude_g, double azimuth_rad) {
    const Quaternion turn = from_rotation_vector({0.0, 0.0, azimuth_rad});
    const Vec3 direction{std::cos(azimuth_rad), std::sin(azimuth_rad), 0.0};
    RigidBody3d box = make_rigid_body_3d("block", box_vertices({2 * b, depth, 2 * h}, {0.0, 0.0, h}, turn), pulse_density_kg_m3);
    const ContactParameters contact{
        .kn_N_m = 0.5e9 * depth, .ks_N_m = 0.5e9 * depth, .mu = 2.0, .h_n = damping_ratio_paper(0.2), .h_s = 1.0};
    testing::TableRun3d run = testing::table_run(std::move(box), contact);
    run.horizontal = pulse(amplitude_g);
    run.direction = direction;
    run.dt_s = 2e-5;
    const Quaternion start = run.body.orientation;
    const Vec3 rocking_axis = cross(Vec3{0.0, 0.0, 1.0}, direction);
    PulseOutcome out;
    while (run.time_s < end_s) {
        run.step();
        const Quaternion since = run.body.orientation * conjugate(start);
        const Vec3 up = rotate(since, {0.0, 0.0, 1.0});
        out.peak_tilt_rad = std::max(out.peak_tilt_rad, std::acos(std::clamp(up.z, -1.0, 1.0)));
        const Vec3 turned = rotation_vector(since);
        const Vec3 off_axis = turned - dot(turned, rocking_axis) * rocking_axis;
        out.out_of_plane_rad = std::max(out.out_of_plane_rad, length(off_axis));
        if (out.peak_tilt_rad > overturned_rad) {
            out.overturned = true;
            break;
        }
    }
    return out;
}

TEST(Pulse3d, OneSinePulseOutcomeAgainstHousnerAlongXYAndThirtyDegrees) {
    const double azimuths_deg[] = {0.0, 90.0, 30.0};
    for (double amplitude_g : {0.3, 0.5}) {
        const RockingResult ref = housner_rocking(housner_block(), pulse(amplitude_g), 0.0, 0.0, end_s, 1e-5);
        for (double azimuth_deg : azimuths_deg) {
            const PulseOutcome dem = run_pulse(amplitude_g, azimuth_deg * std::numbers::pi / 180.0);
            std::printf("3-D one-sine %.1f g along %.0f deg: DEM peak %.4f rad%s, Housner %.4f rad%s; out of plane "
                        "%.1e rad\n",
                        amplitude_g, azimuth_deg, dem.peak_tilt_rad, dem.overturned ? " (overturned)" : "",
                        ref.peak_abs_theta_rad, ref.overturned ? " (overturned)" : "", dem.out_of_plane_rad);
            EXPECT_EQ(dem.overturned, ref.overturned) << amplitude_g << " g along " << azimuth_deg << " deg";
            // The 2-D test's 5%: the corner springs delay uplift a little.
            if (!ref.overturned)
                EXPECT_NEAR(dem.peak_tilt_rad, ref.peak_abs_theta_rad, 0.05 * ref.peak_abs_theta_rad)
                    << amplitude_g << " g along " << azimuth_deg << " deg";
            // Symmetric about its rocking plane, the box never turns out of it (round-off: turned
            // by 30 deg its corners' coordinates are no longer exact, 2e-13 rad measured).
            EXPECT_LT(dem.out_of_plane_rad, 1e-9) << amplitude_g << " g along " << azimuth_deg << " deg";
        }
    }
}

// Housner's threshold amplitude [g] of overturning by the one-sine pulse, bisected between an
// amplitude that does not overturn and one that does, to 1e-4 g.
double housner_threshold_g(double low_g, double high_g) {
    while (high_g - low_g > 1e-4) {
        const double mid = 0.5 * (low_g + high_g);
        (housner_rocking(housner_block(), pulse(mid), 0.0, 0.0, end_s, 1e-5).overturned ? high_g : low_g) = mid;
    }
    return 0.5 * (low_g + high_g);
}

// The DEM's threshold [g], bisected likewise to 0.001 g (about 6 runs of at most 5 s).
double dem_threshold_g(double low_g, double high_g) {
    while (high_g - low_g > 1e-3) {
        const double mid = 0.5 * (low_g + high_g);
        (run_pulse(mid, 0.0).overturned ? high_g : low_g) = mid;
    }
    return 0.5 * (low_g + high_g);
}

TEST(Pulse3d, OverturningThresholdAgainstHousner) {
    // Between 0.30 g (rocks back, above) and 0.35 g: both outcomes checked first, so that the
    // bisections start from a bracket.
    ASSERT_FALSE(housner_rocking(housner_block(), pulse(0.30), 0.0, 0.0, end_s, 1e-5).overturned);
    ASSERT_TRUE(housner_rocking(housner_block(), pulse(0.35), 0.0, 0.0, end_s, 1e-5).overturned);
    ASSERT_FALSE(run_pulse(0.30, 0.0).overturned);
    ASSERT_TRUE(run_pulse(0.35, 0.0).overturned);
    const double housner_g = housner_threshold_g(0.30, 0.35);
    const double dem_g = dem_threshold_g(0.30, 0.35);
    std::printf("3-D one-sine overturning threshold: DEM %.4f g, Housner %.4f g (%+.2f%%)\n", dem_g, housner_g,
                100.0 * (dem_g - housner_g) / housner_g);
    // 1%: the DEM's impacts lose Housner's share only to 0.5% per impact (test_rocking.cpp) and
    // its springs delay uplift a little; both move the threshold by less than that.
    EXPECT_NEAR(dem_g, housner_g, 0.01 * housner_g);
}

}  // namespace
}  // namespace blockdem
