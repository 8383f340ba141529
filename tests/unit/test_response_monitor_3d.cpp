// The 3-D response monitor's toppling limit (world/response_monitor_3d.hpp): the tilt from the
// start at which a body's centroid stands above an edge of the face it rests on, against the
// closed forms of a block on a level base (atan(d / h)) and on a face dipping at beta
// (atan(d / h) - beta over the lower edge), and a body whose centroid is already past an edge.
#include <gtest/gtest.h>

#include <cmath>

#include "world/response_monitor_3d.hpp"

namespace blockdem {
namespace {

// A box 2d x 2d x 2h [m] (d half the width along y) turned by `beta` about x, its centroid at
// z = 1 m, alone in a world (the table is not needed: the limit reads the body only).
ResponseMonitor3d monitor_of_box(double d_m, double h_m, double beta_rad, double extra_x_m = 0.0) {
    World3d w;
    const Quaternion turn = from_rotation_vector({beta_rad, 0.0, 0.0});
    add_body(w, make_rigid_body_3d("box", box_vertices({2.0 * d_m + extra_x_m, 2.0 * d_m, 2.0 * h_m}, {0.0, 0.0, 1.0}, turn), 2000.0),
             BodyKind3d::dynamic);
    return ResponseMonitor3d(w);
}

TEST(ResponseMonitor3d, LevelBlockToppleAtAtanOfHalfWidthOverHalfHeight) {
    const ResponseMonitor3d m = monitor_of_box(0.1, 0.5, 0.0);
    EXPECT_NEAR(m.bodies()[0].overturning_angle_rad, std::atan(0.1 / 0.5), 1e-12);
}

TEST(ResponseMonitor3d, BlockOnADippingFaceToppleOverItsLowerEdgeSooner) {
    // Turned by beta about x, the box rests on its bottom face dipping at beta: over the lower
    // edge the limit is atan(d / h) - beta (a rock block on a joint plane; the upper edge needs
    // atan(d / h) + beta, and the side edges, along the dip, atan(d' / h) with d' the half length
    // along x, made larger here so that the lower edge governs).
    for (double beta_deg : {5.0, 10.0, 20.0}) {
        const double beta = beta_deg * std::acos(-1.0) / 180.0;
        const ResponseMonitor3d m = monitor_of_box(0.2, 0.5, beta, 1.0);
        EXPECT_NEAR(m.bodies()[0].overturning_angle_rad, std::atan(0.2 / 0.5) - beta, 1e-12) << beta_deg;
    }
}

TEST(ResponseMonitor3d, CentroidAlreadyPastAnEdgeGivesZero) {
    // A slender box (d / h = 0.1) resting on a face dipping at 10 deg > atan(0.1) = 5.7 deg.
    const ResponseMonitor3d m = monitor_of_box(0.05, 0.5, 10.0 * std::acos(-1.0) / 180.0, 1.0);
    EXPECT_EQ(m.bodies()[0].overturning_angle_rad, 0.0);
}

}  // namespace
}  // namespace blockdem
