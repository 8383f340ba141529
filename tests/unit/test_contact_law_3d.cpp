// The 3-D law's two forms held against each other (laws/contact_law_3d.hpp): two_point_law, the
// straight line of a sticking point taken at two points at once, one a lane, must give each point
// exactly what point_law (the straight line, or coulomb_slider_3d off it) gives it, wherever it
// takes the two points; and it must leave to point_law every point that slides or reaches its
// cap. The forces and the history carried to the next step are compared to the bit (each lane
// rounds as the scalar expression written the same way); the energy sums to 1e-12 (the lanes add a
// pair's terms lane by lane, point_law one point after the other: the same terms in another order).
// four_point_law (AVX2), four points at once, is held against two_point_law at its two halves: the
// points and the sums to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <utility>

#include "laws/contact_law_3d.hpp"

namespace blockdem {
namespace {

// Named one by one, not by a using-directive: in a unit build this namespace is the other files'
// of the unit too (tests/CMakeLists.txt). The four-point law's names only where it is compiled
// (GCC on x86-64: laws/quad_lanes.hpp), as its tests below.
using law_3d::law_constants;
using law_3d::LawConstants;
using law_3d::pair_lanes;
using law_3d::pair_sums;
using law_3d::PairDashpots;
using law_3d::PairEnergySums;
using law_3d::PairLaneSums;
using law_3d::PairLanes;
using law_3d::PairLaw;
using law_3d::PairMotion;
using law_3d::PairSums;
using law_3d::two_point_law;
#if BLOCKDEM_QUAD_LANES
using law_3d::add_halves;
using law_3d::four_point_law;
using law_3d::law_quads;
using law_3d::pair_quads;
using law_3d::PairQuadTerms;
#endif

Vec3 unit(Vec3 v) { return (1.0 / length(v)) * v; }

struct Case {
    LawConstants constants;
    PairMotion motion;
    PairDashpots dashpots;
    ContactPoint3d points[2];
};

// Two points of one pair, drawn in ten families: the plain case; no shear spring (ks = 0); no
// friction (mu = 0); no shear dashpot; zero_overlap termination; normals turned up to 1.5 rad
// since the history was laid into its plane; an overlap of a denormal; shares of 0 and 1e-12;
// springs right at their caps; histories of zero.
Case draw(std::mt19937_64& r, int family) {
    std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
    const double kn = 1e6 * (1 + u01(r)), ks = family == 1 ? 0.0 : 1e6 * u01(r), dt = 1e-5;
    const double mu = family == 2 ? 0.0 : u01(r), hn = 0.3 * u01(r), hs = family == 3 ? 0.0 : 0.3 * u01(r);
    ContactParameters p{.kn_N_m = kn, .ks_N_m = ks, .mu = mu, .h_n = hn, .h_s = hs};
    p.termination = family == 4 ? ContactTermination::zero_overlap : ContactTermination::no_tension;
    Case c;
    c.constants = law_constants(p, dt);
    const double root_mass = std::sqrt(1 + 10 * u01(r));  // sqrt(M / S) [kg^0.5]
    c.dashpots = {c.constants.cn_per_root_mass * root_mass, c.constants.cs_per_root_mass * root_mass};
    c.motion = {{1e-3 * u(r), 1e-3 * u(r), 1e-3 * u(r)}, {1e-2 * u(r), 1e-2 * u(r), 1e-2 * u(r)}, {u(r), u(r), u(r)}};
    const Vec3 plane_normal = unit({u(r), u(r), u(r)});
    for (ContactPoint3d& pt : c.points) {
        pt.point_m = c.motion.centroid_a_m + Vec3{0.1 * u(r), 0.1 * u(r), 0.1 * u(r)};
        const double turn = family == 5 ? 1.5 * u01(r) : 1e-6 * u01(r);
        pt.normal = unit(plane_normal + Vec3{turn * u(r), turn * u(r), turn * u(r)});
        pt.overlap_m = family == 6 ? 1e-320 : 1e-5 * u01(r);
        pt.stiffness_share = family == 7 ? (u01(r) < 0.5 ? 0.0 : 1e-12) : u01(r);
        pt.normal_dashpot_n = u(r);
        Vec3 s{u(r), u(r), u(r)};
        s = s - dot(s, plane_normal) * plane_normal;  // last step's plane
        const double cap_n = mu * kn * pt.stiffness_share * pt.overlap_m;
        s = (cap_n * (family == 8 ? 1.0 : u01(r)) / (length(s) + 1e-300)) * s;
        if (family == 9 && u01(r) < 0.3) s = {};
        pt.shear = {s, {1e-3 * u(r), 1e-3 * u(r), 1e-3 * u(r)}};
    }
    return c;
}

void expect_same_vector(Vec3 a, Vec3 b, const char* what) {
    EXPECT_EQ(a.x, b.x) << what;
    EXPECT_EQ(a.y, b.y) << what;
    EXPECT_EQ(a.z, b.z) << what;
}

void expect_close(double lanes_sum, double scalar_sum, const char* what) {
    EXPECT_NEAR(lanes_sum, scalar_sum, 1e-12 * std::abs(scalar_sum) + 1e-300) << what;
}

// Runs both forms on the case; returns whether the lanes took the two points.
bool compare(const Case& c) {
    ContactPoint3d lane_points[2] = {c.points[0], c.points[1]};
    ContactPoint3d scalar_points[2] = {c.points[0], c.points[1]};
    const PairLanes pair_lanes_now = pair_lanes(c.motion, c.dashpots);
    PairLaneSums sums{};
    if (!two_point_law(c.constants, pair_lanes_now, lane_points[0], lane_points[1], sums)) {
        // Nothing written where the lanes leave the points to point_law.
        for (int i = 0; i < 2; ++i) {
            expect_same_vector(lane_points[i].shear.spring_n, c.points[i].shear.spring_n, "untouched spring");
            EXPECT_EQ(lane_points[i].normal_dashpot_n, c.points[i].normal_dashpot_n);
        }
        return false;
    }
    PairLaw law = c.constants.law;
    law.cn_per_share_N_s_m = c.dashpots.cn_per_share_N_s_m;
    law.cs_per_share_N_s_m = c.dashpots.cs_per_share_N_s_m;
    PairEnergySums e;
    Vec3 force_n, torque_n_m;
    for (ContactPoint3d& pt : scalar_points) {
        const Vec3 r = pt.point_m - c.motion.centroid_a_m;
        const Vec3 f = point_law(c.motion, law, pt, r, e);
        force_n += f;
        torque_n_m += cross(r, f);
    }
    for (int i = 0; i < 2; ++i) {
        const ContactPoint3d& a = lane_points[i];
        const ContactPoint3d& b = scalar_points[i];
        EXPECT_FALSE(b.sliding) << "the lanes took a point the slider slides";
        EXPECT_FALSE(a.sliding);
        expect_same_vector(a.force_n, b.force_n, "force");
        expect_same_vector(a.shear.spring_n, b.shear.spring_n, "shear spring");
        expect_same_vector(a.shear.dashpot_n, b.shear.dashpot_n, "shear dashpot");
        EXPECT_EQ(a.normal_dashpot_n, b.normal_dashpot_n);
    }
    EXPECT_EQ(e.friction_j, 0.0);
    const Vec3 lane_force_n = lane_sum(sums.force_n);
    const Vec3 lane_torque_n_m = lane_sum(sums.torque_n_m);
    for (auto [a, b] : {std::pair{lane_force_n.x, force_n.x}, std::pair{lane_force_n.y, force_n.y},
                        std::pair{lane_force_n.z, force_n.z}, std::pair{lane_torque_n_m.x, torque_n_m.x},
                        std::pair{lane_torque_n_m.y, torque_n_m.y}, std::pair{lane_torque_n_m.z, torque_n_m.z}})
        expect_close(a, b, "pair force and moment");
    expect_close(lane_sum(sums.share_overlap_squared_m2), e.share_overlap_squared_m2, "w o^2");
    expect_close(lane_sum(sums.spring_squared_per_share_n2), e.spring_squared_per_share_n2, "|F_s|^2 / w");
    expect_close(lane_sum(sums.normal_dashpot_power_w), e.normal_dashpot_power_w, "normal dashpot power");
    expect_close(lane_sum(sums.shear_dashpot_power_w), e.shear_dashpot_power_w, "shear dashpot power");
    return true;
}

TEST(ContactLaw3d, TwoPointsInLanesAreEachPointsOwnLaw) {
    std::mt19937_64 r(11);
    int taken[10] = {};
    constexpr int draws = 100000;
    for (int k = 0; k < draws; ++k) {
        const int family = k % 10;
        if (compare(draw(r, family))) ++taken[family];
        if (::testing::Test::HasFailure()) break;  // one case's report, not thousands
    }
    // Not a vacuous test: the lanes take a good part of the plain and the turned cases.
    EXPECT_GT(taken[0], draws / 10 / 4);
    EXPECT_GT(taken[5], draws / 10 / 10);
    std::printf("lanes took %d of %d plain pairs, %d of %d with normals turned up to 1.5 rad\n", taken[0], draws / 10,
                taken[5], draws / 10);
}

// The cap sweep's case: a history laid into a plane 43 degrees from this step's normal, a slip
// that shrinks the carried spring by 1e-4 of its length in the step, and the overlap at which the
// spring's length is the cap mu kn o (the sweep goes up from there, ulp by ulp).
struct CapSweep {
    Case law;
    Vec3 last_spring_n;      ///< [N] last step's spring
    Vec3 normal;             ///< this step's
    double first_overlap_m;  ///< [m]
};

CapSweep cap_sweep() {
    const ContactParameters p{.kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.5, .h_n = 0.0, .h_s = 0.0};
    CapSweep sweep;
    sweep.law.constants = law_constants(p, 1e-6);
    sweep.law.dashpots = {0.0, 2000.0};
    sweep.last_spring_n = {-0.37700325163525505, -0.11769282325733366, -0.048260505954373922};
    sweep.normal = {-0.75951379784397355, 0.3539625117994063, -0.54575574309875963};
    sweep.law.motion = {(1e-4 / (p.ks_N_m * 1e-6)) * carried_into_plane(sweep.last_spring_n, sweep.normal), {}, {}};
    sweep.first_overlap_m = length(sweep.last_spring_n) / p.mu / p.kn_N_m;
    return sweep;
}

TEST(ContactLaw3d, ASpringAtItsCapAfterATurnIsLeftToTheSlider) {
    // A history laid into a plane 43 degrees from this step's normal, its spring's length swept
    // ulp by ulp through the cap mu kn o: the carry into the new plane rounds the length up by up
    // to 14 ulps, so the lanes' cap test must be the carried spring's own square (last step's
    // square let a spring at the cap stick in the lanes and slide in the slider, keeping a
    // shear dashpot force the slider drops).
    const CapSweep sweep = cap_sweep();
    Case c = sweep.law;
    double overlap_m = sweep.first_overlap_m;
    int taken = 0;
    for (int i = 0; i < 4000; ++i, overlap_m = std::nextafter(overlap_m, 1.0)) {
        for (ContactPoint3d& pt : c.points) {
            pt = ContactPoint3d{};
            pt.normal = sweep.normal;
            pt.overlap_m = overlap_m;
            pt.stiffness_share = 1.0;
            pt.shear = {sweep.last_spring_n, {}};
        }
        if (compare(c)) ++taken;
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "at overlap " << overlap_m << " m (step " << i << " of the sweep)";
            break;
        }
    }
    EXPECT_GT(taken, 0);  // the sweep reaches caps the lanes take
}

#if BLOCKDEM_QUAD_LANES
void expect_same_lanes(DoubleLanes a, DoubleLanes b, const char* what) {
    EXPECT_EQ(a[0], b[0]) << what;
    EXPECT_EQ(a[1], b[1]) << what;
}

void expect_same_lanes(const Vec3Lanes& a, const Vec3Lanes& b, const char* what) {
    expect_same_lanes(a.x, b.x, what);
    expect_same_lanes(a.y, b.y, what);
    expect_same_lanes(a.z, b.z, what);
}

void expect_same_point(const ContactPoint3d& a, const ContactPoint3d& b) {
    expect_same_vector(a.force_n, b.force_n, "force");
    expect_same_vector(a.shear.spring_n, b.shear.spring_n, "shear spring");
    expect_same_vector(a.shear.dashpot_n, b.shear.dashpot_n, "shear dashpot");
    EXPECT_EQ(a.normal_dashpot_n, b.normal_dashpot_n);
    EXPECT_EQ(a.sliding, b.sliding);
}

// four_point_law in an AVX2 function, as world/step_3d.cpp's pair_law_avx takes it.
// Its terms are added to l at its two halves (add_halves), and summed across the lanes as a pair
// of four points sums them (pair_sums) into sums.
[[gnu::target("avx2"), gnu::flatten]] bool four_point_law_in_avx(const Case& c, ContactPoint3d* p, PairLaneSums& l,
                                                                 PairSums& sums) {
    PairQuadTerms t;
    if (!four_point_law(law_quads(c.constants), pair_quads(c.motion, c.dashpots), p, t))
        return false;
    add_halves(l, t);
    sums = pair_sums(t);
    return true;
}

void expect_same_sums(const PairSums& a, const PairSums& b) {
    expect_same_vector(a.force_n, b.force_n, "force");
    expect_same_vector(a.torque_n_m, b.torque_n_m, "moment");
    EXPECT_EQ(a.e.share_overlap_squared_m2, b.e.share_overlap_squared_m2);
    EXPECT_EQ(a.e.spring_squared_per_share_n2, b.e.spring_squared_per_share_n2);
    EXPECT_EQ(a.e.normal_dashpot_power_w, b.e.normal_dashpot_power_w);
    EXPECT_EQ(a.e.shear_dashpot_power_w, b.e.shear_dashpot_power_w);
    EXPECT_EQ(a.e.friction_j, b.e.friction_j);
}

// Runs four_point_law at four points and two_point_law at their two halves; returns whether the
// four lanes took them.
// start: the sums of the pair's points before these four (the order of the additions shows only
// on top of such sums).
bool compare_four(const Case& c, const ContactPoint3d (&points)[4], const PairLaneSums& start) {
    ContactPoint3d four[4], two[4];
    for (int i = 0; i < 4; ++i) four[i] = two[i] = points[i];
    PairLaneSums four_sums = start, two_sums = start;
    PairSums four_pair_sums;
    const bool four_took = four_point_law_in_avx(c, four, four_sums, four_pair_sums);
    const PairLanes pair_lanes_now = pair_lanes(c.motion, c.dashpots);
    const bool first_took = two_point_law(c.constants, pair_lanes_now, two[0], two[1], two_sums);
    const bool second_took = two_point_law(c.constants, pair_lanes_now, two[2], two[3], two_sums);
    EXPECT_EQ(four_took, first_took && second_took)
        << "four lanes take the four points where two lanes take both halves";
    if (!four_took) {
        for (int i = 0; i < 4; ++i) expect_same_point(four[i], points[i]);  // nothing written
        expect_same_lanes(four_sums.force_n, start.force_n, "untouched sums");
        return false;
    }
    for (int i = 0; i < 4; ++i) expect_same_point(four[i], two[i]);
    // The sums to the bit: four_point_law adds its halves in two_point_law's order.
    expect_same_lanes(four_sums.force_n, two_sums.force_n, "force");
    expect_same_lanes(four_sums.torque_n_m, two_sums.torque_n_m, "moment");
    expect_same_lanes(four_sums.share_overlap_squared_m2, two_sums.share_overlap_squared_m2, "w o^2");
    expect_same_lanes(four_sums.spring_squared_per_share_n2, two_sums.spring_squared_per_share_n2, "|F_s|^2 / w");
    expect_same_lanes(four_sums.normal_dashpot_power_w, two_sums.normal_dashpot_power_w, "normal dashpot power");
    expect_same_lanes(four_sums.shear_dashpot_power_w, two_sums.shear_dashpot_power_w, "shear dashpot power");
    // A pair of these four points alone: its sums across the four lanes are those of the two-lane
    // sums from zero added across their lanes, to the bit (step_3d.cpp's two paths).
    ContactPoint3d alone[4] = {points[0], points[1], points[2], points[3]};
    PairLaneSums halves_from_zero{};
    two_point_law(c.constants, pair_lanes_now, alone[0], alone[1], halves_from_zero);
    two_point_law(c.constants, pair_lanes_now, alone[2], alone[3], halves_from_zero);
    expect_same_sums(four_pair_sums, pair_sums(halves_from_zero, PairEnergySums{}, Vec3{}, Vec3{}));
    return true;
}

TEST(ContactLaw3d, FourPointsInLanesAreTwoPointsTwice) {
    // four_point_law (AVX2) against two_point_law at each half, which the test above holds against
    // point_law: the four points of one pair drawn as two draws of the ten families (the second's
    // points under the first's law and motion, so that some stick and some reach their caps).
    if (!quad_lanes_usable()) GTEST_SKIP() << "no AVX2 on this processor: the four lanes are not run";
    std::mt19937_64 r(17);
    int taken = 0, left = 0;
    constexpr int draws = 50000;
    for (int k = 0; k < draws; ++k) {
        const Case c = draw(r, k % 10);
        const Case d = draw(r, (k + k / 10) % 10);
        const ContactPoint3d points[4] = {c.points[0], c.points[1], d.points[0], d.points[1]};
        // Sums of earlier points of the pair, of the size of these points' terms.
        std::uniform_real_distribution<double> u(-1, 1);
        const auto some = [&](double scale) { return lanes(scale * u(r), scale * u(r)); };
        const auto some3 = [&](double scale) { return Vec3Lanes{some(scale), some(scale), some(scale)}; };
        const PairLaneSums start{some3(10.0), some3(1.0), some(1e-10), some(1e-5), some(1e-3), some(1e-3)};
        if (compare_four(c, points, start)) ++taken; else ++left;
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(taken, draws / 20);  // not vacuous: both outcomes are met
    EXPECT_GT(left, draws / 20);
    std::printf("four lanes took %d of %d groups of four points\n", taken, draws);
}

TEST(ContactLaw3d, FourPointsAtTheirCapsAfterATurnGoAsTwo) {
    // The sweep of ASpringAtItsCapAfterATurnIsLeftToTheSlider through the four lanes.
    if (!quad_lanes_usable()) GTEST_SKIP() << "no AVX2 on this processor: the four lanes are not run";
    const CapSweep sweep = cap_sweep();
    const Case& c = sweep.law;
    double overlap_m = sweep.first_overlap_m;
    int taken = 0, left = 0;
    for (int i = 0; i < 4000; ++i, overlap_m = std::nextafter(overlap_m, 1.0)) {
        ContactPoint3d points[4];
        for (int j = 0; j < 4; ++j) {
            points[j].normal = sweep.normal;
            points[j].overlap_m = j == 3 ? overlap_m : 2.0 * overlap_m;  // the last at the cap
            points[j].stiffness_share = 1.0;
            points[j].shear = {sweep.last_spring_n, {}};
        }
        if (compare_four(c, points, PairLaneSums{})) ++taken; else ++left;
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "at overlap " << overlap_m << " m (step " << i << " of the sweep)";
            break;
        }
    }
    EXPECT_GT(taken, 0);
    EXPECT_GT(left, 0);
}
#endif

}  // namespace
}  // namespace blockdem
