// Free rocking of a box in 3-D reduced to the 2-D case (tests/validation/test_rocking.cpp):
// a 0.4 x 1.0 x 1.6 m box (the 2-D block's b = 0.2, h = 0.8, one metre deep) tilted about the
// y axis onto its edge and released rocks in the x-z plane as Housner's block
// (analysis/housner_rocking.hpp), with the 2-D test's contact (its kn per metre of depth shared by
// the edge's two corners) and the 2-D tolerances: the impact ratio within 0.005 of
// 1 - 1.5 sin^2 alpha, the peaks within 3%, the impact times within 1%. It stays in its plane.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/housner_rocking.hpp"
#include "contact/table_contact_3d.hpp"
#include "dynamics/rigid_rotation_3d.hpp"
#include "laws/restitution.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;
constexpr double box_b_m = 0.2, box_h_m = 0.8, box_depth_m = 1.0;  // [m] half sizes b and h, depth

struct Rocking3dPeaks {
    std::vector<double> theta;    // signed peak angles [rad]
    std::vector<double> impacts;  // [s] times theta crosses zero
};

// The release angle, then the peaks between impacts. (Peaks before the first impact are left
// out: the box is placed at zero overlap and settles onto its corner springs in the first steps,
// which the peak search would take for a peak.)
Rocking3dPeaks rocking_3d_peaks_of(const std::vector<double>& t, const std::vector<double>& theta) {
    Rocking3dPeaks p;
    p.theta.push_back(theta[0]);
    for (std::size_t i = 1; i + 1 < theta.size(); ++i) {
        if (!p.impacts.empty() && std::abs(theta[i]) > 1e-4 && std::abs(theta[i]) >= std::abs(theta[i - 1]) &&
            std::abs(theta[i]) > std::abs(theta[i + 1]))
            p.theta.push_back(theta[i]);
        if ((theta[i] > 0.0) != (theta[i + 1] > 0.0)) p.impacts.push_back(t[i]);
    }
    return p;
}

TEST(Rocking3d, FreeRockingOnAnEdgeMatchesHousner) {
    HousnerBlock block;
    block.half_width_m = box_b_m;
    block.half_height_m = box_h_m;
    block.gravity_m_s2 = g;
    const double alpha = block.alpha_rad();
    const double theta0 = 0.5 * alpha;
    // theta counter-clockwise seen from -y (x right, z up), as in 2-D: a turn about -y. Tilted
    // about its left edge (x = -b), which stays on the table.
    const Quaternion tilt = from_rotation_vector({0.0, -theta0, 0.0});
    const Vec3 center = Vec3{-box_b_m, 0.0, 0.0} + rotate(tilt, {box_b_m, 0.0, box_h_m});
    RigidBody3d body =
        make_rigid_body_3d("block", box_vertices({2 * box_b_m, box_depth_m, 2 * box_h_m}, center, tilt), 1536.0);
    const Quaternion start = body.orientation;
    // The 2-D contact: kn = 1e9 N/m per corner of a unit-thick block; here two corners per edge.
    const ContactParameters contact{.kn_N_m = 0.5e9 * box_depth_m, .ks_N_m = 0.5e9 * box_depth_m, .mu = 2.0,
                                    .h_n = damping_ratio_paper(0.2), .h_s = 1.0};
    std::vector<VertexContact3d> vertices(body.shape.vertices_m.size());
    const double dt = 2e-5, end = 4.0;
    std::vector<double> t, theta;
    double out_of_plane = 0.0;
    for (int n = 0; n * dt < end; ++n) {
        const TableContactResult3d r = table_contact_3d(body, {}, contact, dt, vertices);
        body.force_n = r.force_n + Vec3{0.0, 0.0, -g * body.mass_kg};
        body.torque_n_m = r.torque_n_m;
        update_velocity_3d(body, dt, n == 0);
        const Vec3 turned = rotation_vector(body.orientation * conjugate(start));
        t.push_back(n * dt);
        theta.push_back(theta0 - turned.y);
        out_of_plane = std::max({out_of_plane, std::abs(turned.x), std::abs(turned.z)});
        update_position_3d(body, dt);
    }
    const Rocking3dPeaks dem = rocking_3d_peaks_of(t, theta);
    const RockingResult ref = housner_rocking(block, RestMotion{}, theta0, 0.0, end, 1e-5);
    std::vector<double> rt, rtheta;
    for (const auto& p : ref.history) {
        rt.push_back(p.time_s);
        rtheta.push_back(p.theta_rad);
    }
    Rocking3dPeaks housner = rocking_3d_peaks_of(rt, rtheta);
    housner.impacts = ref.impact_times_s;
    ASSERT_GE(dem.theta.size(), 6u);
    ASSERT_GE(housner.theta.size(), 6u);
    ASSERT_GE(dem.impacts.size(), 5u);
    ASSERT_GE(housner.impacts.size(), 5u);
    const auto impact_ratio = [&](double before, double after) {
        return std::sqrt((std::cos(alpha - std::abs(after)) - std::cos(alpha)) /
                         (std::cos(alpha - std::abs(before)) - std::cos(alpha)));
    };
    for (std::size_t k = 0; k + 1 < 6; ++k)
        EXPECT_NEAR(impact_ratio(dem.theta[k], dem.theta[k + 1]), block.housner_restitution(), 0.005) << "impact " << k;
    for (std::size_t k = 1; k < 6; ++k) {
        EXPECT_NEAR(dem.theta[k], housner.theta[k], 0.03 * std::abs(housner.theta[k])) << "peak " << k;
        std::printf("3-D peak %zu: DEM %.5f rad, Housner %.5f rad (%.2f%%); impact %zu: DEM %.4f s, Housner %.4f s\n",
                    k, dem.theta[k], housner.theta[k], 100.0 * (dem.theta[k] - housner.theta[k]) / housner.theta[k],
                    k - 1, dem.impacts[k - 1], housner.impacts[k - 1]);
    }
    for (std::size_t k = 0; k < 5; ++k) EXPECT_NEAR(dem.impacts[k], housner.impacts[k], 0.01 * housner.impacts[k]);
    // Symmetric about its rocking plane, the box never turns out of it (round-off only).
    EXPECT_LT(out_of_plane, 1e-9);
    std::printf("3-D impact ratio r = %.4f (first impact), Housner %.4f; out of plane %.1e rad\n",
                impact_ratio(dem.theta[0], dem.theta[1]), block.housner_restitution(), out_of_plane);
}

}  // namespace
}  // namespace blockdem
