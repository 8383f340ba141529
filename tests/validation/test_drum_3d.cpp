// A column drum (a 32-sided prism, R = 0.3 m, H = 0.8 m) standing on the table, tilted onto its
// rim and set turning about the vertical with its contact corner at rest: it rolls on its rim
// (the contact goes round the base's corners, the wobble of a spun coin) while it rocks. That
// motion has no closed form; what it must do is close the energy balance: each corner landing on
// the table is a small impact, and the ledger must account for every one (hundreds in 2 s). The
// balance's error is the scheme's: measured 8.0e-5 at dt = 2e-5 s, 2.9e-5 at 1e-5 s; the
// tolerance 5e-4 is that with room, far below the 445 J dissipated (0.7 of the energy at start).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <vector>

#include "laws/restitution.hpp"
#include "support/table_run_3d.hpp"

namespace blockdem {
namespace {

TEST(Drum3d, RollsOnItsRimWithTheEnergyBalanceClosed) {
    constexpr int sides = 32;
    const double radius = 0.3, height = 0.8, tilt = 0.12;
    std::vector<Vec2> polygon;
    for (int i = 0; i < sides; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / sides;
        polygon.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    // Tilted about x: the base corner at -y (number 24) goes lowest, and sits at z = 0.
    const Quaternion turn = from_rotation_vector({tilt, 0.0, 0.0});
    std::vector<Vec3> vertices;
    for (Vec3 v : prism_vertices(polygon, height))
        vertices.push_back(rotate(turn, v) + Vec3{0.0, 0.0, radius * std::sin(tilt)});
    const ContactParameters contact{
        .kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.8, .h_n = damping_ratio_paper(0.5), .h_s = 1.0};
    testing::TableRun3d run = testing::table_run(make_rigid_body_3d("drum", vertices, 2500.0), contact);
    run.dt_s = 2e-5;
    // Turning about the vertical through the centroid at 4 rad/s, the contact corner at rest.
    const Vec3 omega{0.0, 0.0, 4.0};
    const Vec3 contact_point = world_vertex(run.body, 24);
    set_initial_velocity(run.body, -1.0 * cross(omega, contact_point - run.body.position_m), omega);

    std::set<std::size_t> touched;
    double lowest_centroid_m = run.body.position_m.z;
    while (run.time_s < 2.0) {
        run.step();
        for (std::size_t i = 0; i < run.vertices.size(); ++i)
            if (run.vertices[i].active) touched.insert(i);
        lowest_centroid_m = std::min(lowest_centroid_m, run.body.position_m.z);
    }
    // It rolls round: most of the base's corners have carried it.
    EXPECT_GE(touched.size(), static_cast<std::size_t>(sides / 2));
    // It stays up: its centroid never fell below that of the drum lying on its side.
    EXPECT_GT(lowest_centroid_m, radius);
    // The ledger closes over 1e5 steps and hundreds of corner impacts.
    EXPECT_LT(run.ledger.balance_error(), 5e-4);
    std::printf(
        "drum rolling on its rim: %zu corners touched in 2 s, lowest centroid %.3f m, kinetic %.3f J, "
        "dissipated %.3f J (dashpots %.3f, friction %.3f), balance error %.2e\n",
        touched.size(), lowest_centroid_m, run.ledger.kinetic_j, run.ledger.dissipated_j(),
        run.ledger.normal_dashpot_j + run.ledger.shear_dashpot_j, run.ledger.friction_j, run.ledger.balance_error());
}

}  // namespace
}  // namespace blockdem
