// A rocking cylinder (issue 15): a 32-sided prism on the table.
//
// (a) Planar rocking. Stood on its base, tilted about one edge of its base polygon and released
// without spin, it rocks in that plane. The equivalent 2-D block is Housner's
// (analysis/housner_rocking.hpp) with the prism's own numbers: the pivot is the base edge, at the
// apothem a = r cos(pi/32) from the axis (not the circumradius r), so R = sqrt(a^2 + (H/2)^2)
// and alpha = atan(a / (H/2)); the moment about the pivot edge is I_0 = I_t + m R^2 with I_t the
// prism's transverse centroidal moment, taken from its mass properties (principal moments from
// the volume integrals) and checked against the n-gon prism's closed form
// I_t = m [r^2 (1 + 2 cos^2(pi/n)) / 12 + H^2 / 12] (a solid cylinder's m (r^2/4 + H^2/12) as n
// grows). Housner's impact rule keeps the angular momentum about the new pivot edge:
// I_0 w+ = (I_0 - 2 m R^2 sin^2 alpha) w-, so e = 1 - (m R^2 / I_0)(1 - cos 2 alpha). The 3-D
// adjustment: it holds about an edge because the prism is symmetric about the rocking plane (no
// product of inertia couples the rocking axis to the others) and the new pivot is an edge parallel
// to the old one (an even number of sides); but it assumes the whole impulse at that edge, which
// the square prism's base gives (its corners are on the two edges) and the 32-gon's does not (its
// corners share the landing round the rim): see the two tests below, and docs/3d.md.
//
// (b) Rolling on the rim. Tilted onto one base corner, spun about its own axis with that corner
// at rest, it rolls on its rim: the lowest corner travels round the base polygon while it
// wobbles. No closed form describes that wobble (the steady precession of a rolling disc needs a
// thin disc and a steady state, neither of which holds here); what must hold exactly is the
// energy balance, closed by the ledger through every corner landing. Without friction two more
// invariants hold (the table's forces are then vertical): the horizontal momentum and the
// angular momentum about the vertical through the centroid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <vector>

#include "analysis/housner_rocking.hpp"
#include "laws/restitution.hpp"
#include "support/table_run_3d.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

constexpr int sides = 32;
using std::numbers::pi;
using validation::g;
constexpr double density = 2500.0;     // [kg/m^3]

// The base polygon of n corners, circumradius r, its first corner at angle `first_corner_rad` from +x.
std::vector<Vec2> base_polygon(double radius_m, int n, double first_corner_rad) {
    std::vector<Vec2> polygon;
    for (int i = 0; i < n; ++i) {
        const double angle = first_corner_rad + 2.0 * pi * i / n;
        polygon.push_back({radius_m * std::cos(angle), radius_m * std::sin(angle)});
    }
    return polygon;
}

// The prism on z = 0, turned by `turn` about the point `pivot` on the table.
std::vector<Vec3> turned_prism(const std::vector<Vec2>& polygon, double height_m, Quaternion turn, Vec3 pivot_m) {
    std::vector<Vec3> vertices;
    for (Vec3 v : prism_vertices(polygon, height_m)) vertices.push_back(pivot_m + rotate(turn, v - pivot_m));
    return vertices;
}

struct PrismPeaks {
    std::vector<double> theta;    // [rad] the release angle, then the signed peaks between impacts
    std::vector<double> impacts;  // [s] times theta crosses zero
};

// Peaks before the first impact are left out: the prism is placed at zero overlap and settles
// onto its corner springs in the first steps, which the search would take for a peak.
PrismPeaks prism_peaks_of(const std::vector<double>& t, const std::vector<double>& theta) {
    PrismPeaks p;
    p.theta.push_back(theta[0]);
    for (std::size_t i = 1; i + 1 < theta.size(); ++i) {
        if (!p.impacts.empty() && std::abs(theta[i]) > 1e-4 && std::abs(theta[i]) >= std::abs(theta[i - 1]) &&
            std::abs(theta[i]) > std::abs(theta[i + 1]))
            p.theta.push_back(theta[i]);
        if ((theta[i] > 0.0) != (theta[i + 1] > 0.0)) p.impacts.push_back(t[i]);
    }
    return p;
}

// One free-rocking run of an n-sided prism (circumradius 0.3 m, height 1.6 m, 2500 kg/m^3)
// released from half its alpha about the base edge at x = -a, and its equivalent 2-D block.
struct PlanarRocking {
    HousnerBlock block;      // the equivalent block, with the prism's own I_0 / (m R^2)
    double theta0_rad = 0.0;
    PrismPeaks dem;
    double out_of_plane_rad = 0.0;
    double balance_error = 0.0;
};

PlanarRocking rock(int n) {
    const double radius = 0.3, height = 1.6;
    const double apothem = radius * std::cos(pi / n);
    PlanarRocking out;
    out.block.half_width_m = apothem;
    out.block.half_height_m = 0.5 * height;
    out.block.gravity_m_s2 = g;
    out.theta0_rad = 0.5 * out.block.alpha_rad();
    // theta counter-clockwise seen from -y, as in 2-D and test_rocking_3d: a turn about -y, the
    // edge at x = -a staying on the table. Corners at odd multiples of pi/n: an edge faces +x
    // and one faces -x, both at the apothem.
    const Quaternion tilt = from_rotation_vector({0.0, -out.theta0_rad, 0.0});
    testing::TableRun3d run = testing::table_run(
        make_rigid_body_3d("prism", turned_prism(base_polygon(radius, n, pi / n), height, tilt, {-apothem, 0.0, 0.0}), density),
        // test_rocking_3d's contact: the 2-D kn per corner shared by the two corners of an edge;
        // friction high enough that it never slides.
        ContactParameters{.kn_N_m = 0.5e9, .ks_N_m = 0.5e9, .mu = 2.0, .h_n = damping_ratio_paper(0.2), .h_s = 1.0});
    run.dt_s = 2e-5;
    // I_0 from the prism's mass properties: the transverse principal moment (the two largest are
    // equal for a regular polygon) plus m R^2.
    const double m = run.body.mass_kg;
    const double radius_to_pivot_sq = apothem * apothem + 0.25 * height * height;
    out.block.corner_inertia_ratio = (run.body.principal_moments_kg_m2.z + m * radius_to_pivot_sq) / (m * radius_to_pivot_sq);

    const Quaternion start = run.body.orientation;
    std::vector<double> t, theta;
    while (run.time_s < 4.0) {
        // The pose at run.time_s, before the step moves the body.
        const Vec3 turned = rotation_vector(run.body.orientation * conjugate(start));
        t.push_back(run.time_s);
        theta.push_back(out.theta0_rad - turned.y);
        out.out_of_plane_rad = std::max({out.out_of_plane_rad, std::abs(turned.x), std::abs(turned.z)});
        run.step();
    }
    out.dem = prism_peaks_of(t, theta);
    out.balance_error = run.ledger.balance_error();
    return out;
}

// The coefficient of restitution between successive peaks, from the energy at each.
double prism_impact_ratio(double alpha, double before, double after) {
    return std::sqrt((std::cos(alpha - std::abs(after)) - std::cos(alpha)) / (std::cos(alpha - std::abs(before)) - std::cos(alpha)));
}

// Housner's signed peaks after theta0 over 4 s, with the block's restitution.
std::vector<double> housner_peaks(const HousnerBlock& block, double theta0) {
    const RockingResult ref = housner_rocking(block, RestMotion{}, theta0, 0.0, 4.0, 1e-5);
    std::vector<double> t, theta;
    for (const auto& p : ref.history) {
        t.push_back(p.time_s);
        theta.push_back(p.theta_rad);
    }
    return prism_peaks_of(t, theta).theta;
}

// Housner's time from rest at theta to the impact: a quarter of that amplitude's cycle.
double quarter_cycle_s(const HousnerBlock& block, double theta) {
    return housner_rocking(block, RestMotion{}, std::abs(theta), 0.0, 2.0, 1e-5).impact_times_s.at(0);
}

// The control: a square prism (n = 4) is the 2-D block itself (I_0 = 4/3 m R^2), and its edge
// takes the whole impact, as Housner assumes: his r, peaks and impact times, with
// test_rocking_3d's tolerances (r 0.005: the springs make each impact last a few ms; peaks 2%;
// impact times 1%).
TEST(Cylinder3d, SquarePrismRocksAsHousnersBlock) {
    const PlanarRocking r = rock(4);
    EXPECT_NEAR(r.block.corner_inertia_ratio, 4.0 / 3.0, 1e-12);
    // The general formulas at the rectangle's 4/3 are the rectangle's.
    HousnerBlock rectangle = r.block;
    rectangle.corner_inertia_ratio = 0.0;
    EXPECT_NEAR(r.block.p_rad_s(), rectangle.p_rad_s(), 1e-12 * rectangle.p_rad_s());
    EXPECT_NEAR(r.block.housner_restitution(), rectangle.housner_restitution(), 1e-12);
    const double alpha = r.block.alpha_rad();
    const std::vector<double> ref = housner_peaks(r.block, r.theta0_rad);
    ASSERT_GE(r.dem.theta.size(), 6u);
    ASSERT_GE(ref.size(), 6u);
    for (std::size_t k = 0; k + 1 < 6; ++k)
        EXPECT_NEAR(prism_impact_ratio(alpha, r.dem.theta[k], r.dem.theta[k + 1]), r.block.housner_restitution(), 0.005);
    for (std::size_t k = 1; k < 6; ++k) EXPECT_NEAR(r.dem.theta[k], ref[k], 0.02 * std::abs(ref[k])) << "peak " << k;
    std::printf("square prism: r %.4f (Housner %.4f), peak 5 %.5f rad (Housner %.5f)\n",
                prism_impact_ratio(alpha, r.dem.theta[0], r.dem.theta[1]), r.block.housner_restitution(), r.dem.theta[5], ref[5]);
}

// The 32-sided prism. Between impacts it follows Housner's equation with its own I_0: the first
// quarter cycle within 0.1% (the 2-D rectangle's 4/3 m R^2 would be 0.4% off), each later
// half-cycle within 1% of Housner's from the peak it reached. At an impact it keeps more than
// Housner's e: e assumes the whole impulse at the new pivot edge, the least favourable place
// (kept angular momentum about an impulse at x_J from the axis, with rotation about the far edge
// after: r = (I_G + m (h^2 - a x_J)) / (I_G + m (h^2 + a x_J)), smallest at x_J = a). The 32
// corners round the rim share the landing, most of it nearer the axis than the far edge, so r is
// higher (measured 0.878 against e = 0.815; 0.875 to 0.88 with 8 and 64 sides, with kn from 5e7
// to 5e9 N/m and the contact e from 0.01 to 0.2: a property of the base's shape, not of the
// springs). What Housner's model still predicts is a ratio the same at every impact: the
// measured ones within 0.005 of the first, and the peaks within 2% of Housner's equation run
// with their mean (the calibrated 2-D block of practice).
TEST(Cylinder3d, PlanarRockingFollowsHousnersEquationWithItsOwnInertia) {
    const PlanarRocking r = rock(sides);
    // The transverse moment of the volume integrals against the n-gon prism's closed form.
    const double radius = 0.3, height = 1.6, cos_n = std::cos(pi / sides);
    const double transverse_per_kg = radius * radius * (1.0 + 2.0 * cos_n * cos_n) / 12.0 + height * height / 12.0;
    const double r_sq = std::pow(r.block.half_width_m, 2) + std::pow(r.block.half_height_m, 2);
    EXPECT_NEAR(r.block.corner_inertia_ratio, (transverse_per_kg + r_sq) / r_sq, 1e-12);
    const double alpha = r.block.alpha_rad();
    const double e_housner = 1.0 - (1.0 / r.block.corner_inertia_ratio) * (1.0 - std::cos(2.0 * alpha));
    EXPECT_NEAR(r.block.housner_restitution(), e_housner, 1e-14);
    ASSERT_GE(r.dem.theta.size(), 6u);
    ASSERT_GE(r.dem.impacts.size(), 5u);

    HousnerBlock rectangle = r.block;
    rectangle.corner_inertia_ratio = 0.0;
    const double first = quarter_cycle_s(r.block, r.theta0_rad);
    EXPECT_NEAR(r.dem.impacts[0], first, 1e-3 * first);
    std::printf("cylinder first impact: DEM %.4f s, Housner %.4f s with I_0 (%+.3f%%), %.4f s with the rectangle's 4/3 m R^2\n",
                r.dem.impacts[0], first, 100.0 * (r.dem.impacts[0] - first) / first, quarter_cycle_s(rectangle, r.theta0_rad));
    for (std::size_t k = 1; k < 5; ++k) {
        const double half = r.dem.impacts[k] - r.dem.impacts[k - 1];
        const double ref = 2.0 * quarter_cycle_s(r.block, r.dem.theta[k]);
        EXPECT_NEAR(half, ref, 0.01 * ref) << "half-cycle " << k;
        std::printf("cylinder half-cycle %zu: DEM %.4f s, Housner from its peak %.4f s (%+.2f%%)\n", k, half, ref,
                    100.0 * (half - ref) / ref);
    }
    const double r0 = prism_impact_ratio(alpha, r.dem.theta[0], r.dem.theta[1]);
    double r_mean = 0.0;
    for (std::size_t k = 0; k + 1 < 6; ++k) {
        const double rk = prism_impact_ratio(alpha, r.dem.theta[k], r.dem.theta[k + 1]);
        EXPECT_GT(rk, e_housner) << "impact " << k;
        EXPECT_NEAR(rk, r0, 0.005) << "impact " << k;
        r_mean += rk / 5.0;
        std::printf("cylinder impact %zu: r = %.4f (Housner's e %.4f)\n", k, rk, e_housner);
    }
    HousnerBlock calibrated = r.block;
    calibrated.restitution = r_mean;
    const std::vector<double> ref = housner_peaks(calibrated, r.theta0_rad);
    const std::vector<double> uncalibrated = housner_peaks(r.block, r.theta0_rad);
    ASSERT_GE(ref.size(), 6u);
    for (std::size_t k = 1; k < 6; ++k) {
        EXPECT_NEAR(r.dem.theta[k], ref[k], 0.02 * std::abs(ref[k])) << "peak " << k;
        std::printf("cylinder peak %zu: DEM %.5f rad, Housner with the mean r %.5f rad (%+.2f%%), with e %.5f rad\n", k, r.dem.theta[k],
                    ref[k], 100.0 * (r.dem.theta[k] - ref[k]) / ref[k], uncalibrated[k]);
    }
    // Symmetric about its rocking plane, it stays in it: round-off, grown through the impacts
    // of 64 corners (measured 6.5e-9 rad; the box's 8 give 3e-19).
    EXPECT_LT(r.out_of_plane_rad, 1e-7);
    EXPECT_LT(r.balance_error, 1e-3);
    std::printf("cylinder: I_0 / (m R^2) = %.5f (rectangle 4/3), e = %.4f, out of plane %.1e rad, balance error %.2e\n",
                r.block.corner_inertia_ratio, e_housner, r.out_of_plane_rad, r.balance_error);
}

// A prism of circumradius 0.3 m and height 0.8 m, tilted 0.15 rad about x onto its base corner at
// -y (number 24 of the polygon whose first corner is on +x), lifted to touch the table there.
struct RimStart {
    double radius_m = 0.3, height_m = 0.8, tilt_rad = 0.15;
    std::size_t contact_corner = 24;
    Quaternion turn() const { return from_rotation_vector({tilt_rad, 0.0, 0.0}); }
    std::vector<Vec3> vertices() const {
        std::vector<Vec3> out;
        for (Vec3 v : prism_vertices(base_polygon(radius_m, sides, 0.0), height_m))
            out.push_back(rotate(turn(), v) + Vec3{0.0, 0.0, radius_m * std::sin(tilt_rad)});
        return out;
    }
};

// The base corner lowest now, and the angle [rad] of that corner round the base polygon.
std::size_t lowest_base_corner(const RigidBody3d& body) {
    std::size_t lowest = 0;
    for (std::size_t i = 1; i < sides; ++i)
        if (world_vertex(body, i).z < world_vertex(body, lowest).z) lowest = i;
    return lowest;
}

// The turn [rad] of the lowest corner round the polygon since the last call, by whole corners
// (the shorter way round).
double corner_step_rad(std::size_t from, std::size_t to) {
    int d = static_cast<int>(to) - static_cast<int>(from);
    if (d > sides / 2) d -= sides;
    if (d < -sides / 2) d += sides;
    return 2.0 * pi * d / sides;
}

TEST(Cylinder3d, RollsOnItsRimWithTheEnergyBalanceClosed) {
    const RimStart start;
    const ContactParameters contact{.kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.8, .h_n = damping_ratio_paper(0.5), .h_s = 1.0};
    testing::TableRun3d run = testing::table_run(make_rigid_body_3d("cylinder", start.vertices(), density), contact);
    run.dt_s = 2e-5;
    ASSERT_EQ(lowest_base_corner(run.body), start.contact_corner);
    // Spun at 6 rad/s about its own (tilted) axis, the contact corner at rest: rolling.
    const Vec3 omega = 6.0 * rotate(start.turn(), Vec3{0.0, 0.0, 1.0});
    const Vec3 contact_point = world_vertex(run.body, start.contact_corner);
    set_initial_velocity(run.body, -1.0 * cross(omega, contact_point - run.body.position_m), omega);

    std::size_t corner = start.contact_corner;
    double travelled_rad = 0.0;
    std::set<std::size_t> touched;
    double lowest_centroid_m = run.body.position_m.z;
    while (run.time_s < 2.0) {
        run.step();
        const std::size_t now = lowest_base_corner(run.body);
        travelled_rad += corner_step_rad(corner, now);
        corner = now;
        for (std::size_t i = 0; i < run.vertices.size(); ++i)
            if (run.vertices[i].active) touched.insert(i);
        lowest_centroid_m = std::min(lowest_centroid_m, run.body.position_m.z);
    }
    // The contact goes round the rim: more than a full turn of the base polygon.
    EXPECT_GT(std::abs(travelled_rad), 2.0 * pi);
    EXPECT_GE(touched.size(), static_cast<std::size_t>(sides));
    // It stays up on its rim (its centroid above that of the prism lying on its side).
    EXPECT_GT(lowest_centroid_m, start.radius_m);
    // The ledger closes through every corner landing (the other 3-D tests' bound, 1e-3).
    EXPECT_LT(run.ledger.balance_error(), 1e-3);
    std::printf("cylinder rolling: contact travelled %.2f turns round the rim, %zu corners touched, lowest centroid %.3f m, "
                "dissipated %.2f J of %.2f J, balance error %.2e\n",
                travelled_rad / (2.0 * pi), touched.size(), lowest_centroid_m, run.ledger.dissipated_j(),
                run.ledger.initial_j, run.ledger.balance_error());
}

TEST(Cylinder3d, OnAFrictionlessTableKeepsHorizontalMomentumAndVerticalSpin) {
    const RimStart start;
    // mu = 0: the table pushes only vertically.
    const ContactParameters contact{.kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.0, .h_n = damping_ratio_paper(0.5), .h_s = 1.0};
    testing::TableRun3d run = testing::table_run(make_rigid_body_3d("cylinder", start.vertices(), density), contact);
    run.dt_s = 2e-5;
    // Turning at 4 rad/s about the vertical through its centroid, which is at rest.
    set_initial_velocity(run.body, {}, {0.0, 0.0, 4.0});
    const Vec3 centroid0 = run.body.position_m;
    const double spin0 = angular_momentum_of(run.body, {0.0, 0.0, 4.0}).z;
    std::size_t corner = start.contact_corner;
    double travelled_rad = 0.0, spin_error = 0.0, drift_m = 0.0;
    while (run.time_s < 2.0) {
        run.step();
        const std::size_t now = lowest_base_corner(run.body);
        travelled_rad += corner_step_rad(corner, now);
        corner = now;
        spin_error = std::max(spin_error, std::abs(run.body.angular_momentum_kg_m2_s.z - spin0));
        drift_m = std::max(drift_m, std::hypot(run.body.position_m.x - centroid0.x, run.body.position_m.y - centroid0.y));
    }
    // Both to round-off: relative 1e-12 of the spin, and 1e-12 m.
    EXPECT_LT(spin_error, 1e-12 * std::abs(spin0));
    EXPECT_LT(drift_m, 1e-12);
    EXPECT_GT(std::abs(travelled_rad), 2.0 * pi);
    EXPECT_LT(run.ledger.balance_error(), 1e-3);
    EXPECT_EQ(run.ledger.friction_j, 0.0);
    std::printf("cylinder on a frictionless table: contact travelled %.2f turns, spin error %.1e kg m^2/s of %.3f, "
                "centroid drift %.1e m, balance error %.2e\n",
                travelled_rad / (2.0 * pi), spin_error, spin0, drift_m, run.ledger.balance_error());
}

}  // namespace
}  // namespace blockdem
