// The DEM against limit analysis (analysis/limit_analysis.hpp): on a tilting table (gravity
// turned at a slow rate, geometry level) an assembly of dry blocks collapses when tan(tilt)
// reaches the LP's collapse multiplier lambda (dead load g cos a, live load g sin a: the same
// ratio as lambda m g on m g), and its blocks move as the LP's mechanism: the same interfaces
// hinge, at the same ends. Cases: a slender block, a stack of two blocks, a semicircular arch of
// 20 voussoirs at t/R = 0.15; the arch under its own weight, standing at t/R = 0.12 and falling
// at t/R = 0.10 (the LP's minimum: 0.1074); and a running-bond wall with a window, against both
// the associative and the non-associative LP (the blocks that move compared with the LP's).
//
// How the DEM's collapse is read: the tilt at which some block has moved by onset_m = 1 mm (its
// centroid plus its rotation times its bounding radius, from the settled start; before the
// mechanism, an arch's voussoirs creep by up to 1e-4 m as joints beside forming hinges slip
// locally, so a smaller threshold reads that creep, 5 % early), and the mechanism from
// every block's displacement when the largest has moved by mechanism_m, classified like the LP's
// virtual velocities (without the LP's dilation, which the DEM does not have).
//
// Tolerance, and why: 3 % of lambda (the issue's). The DEM is quasi-static but not exactly:
// the tilt keeps rising while the mechanism grows from its onset to onset_m (about 0.2 s at
// these rates, 0.02 to 0.04 deg of tilt, 0.1 to 0.5 % of lambda), the contacts are elastic
// (kn = 1e9 N/m: joints close by m g / kn ~ 1e-6 m, a lean of 1e-5 rad, 0.01 % of lambda), and
// a corner-to-edge contact point sits at the corner, as the LP's interface end does. What is
// left is measured (printed) and well inside 3 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <numbers>

#include "analysis/limit_analysis.hpp"
#include "scenes/assemblies.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using testing::rectangle_body;

using validation::deg;
using validation::g;

struct DemCollapse {
    double tilt_deg = NAN;                 ///< the table's tilt at the onset (NaN: none)
    std::vector<BodyMotion> displacement;  ///< [m], [rad] when the largest reached mechanism_m (empty: never)
    double largest_m = 0.0;                ///< [m] the largest movement reached
};

// Each dynamic block's movement from its reference: centroid displacement plus rotation times
// its bounding radius [m].
double moved_m(const World& w, std::size_t i, const std::vector<Vec2>& p0, const std::vector<double>& a0) {
    return length(w.bodies.position_m[i] - p0[i]) + std::abs(w.bodies.rotation_rad[i] - a0[i]) * w.bodies.bounding_radius_m[i];
}

// Settles m at start_deg (friction held; or starts it as built, settling = nullopt), then raises the tilt at rate_deg_s for up to max_s,
// at dt_fraction x the time step blockdem derives.
DemCollapse tilt_until_collapse(Model m, double start_deg, double rate_deg_s, double max_s, double onset_m, double mechanism_m,
                                double dt_fraction = 1.0, std::optional<SettlingSettings> settling = SettlingSettings{}) {
    m.settings.duration_s = max_s;
    m.settings.dt_s.reset();
    if (dt_fraction != 1.0) m.settings.dt_s = dt_fraction * build_world(m).dt_s;
    m.settings.tilt_rad = start_deg * deg;
    m.settings.tilt_rate_rad_s = rate_deg_s * deg;
    m.settling = settling;
    World w = build_world(m);
    const std::vector<Vec2> p0 = w.bodies.position_m;
    const std::vector<double> a0 = w.bodies.rotation_rad;
    DemCollapse out;
    while (w.time_s < max_s) {
        step_begin(w);
        step_end(w);
        double largest = 0.0;
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            if (w.bodies.kind[i] == BodyKind::dynamic) largest = std::max(largest, moved_m(w, i, p0, a0));
        out.largest_m = largest;
        if (std::isnan(out.tilt_deg) && largest > onset_m) out.tilt_deg = tilt_at_rad(w.settings, w.time_s) / deg;
        if (largest > mechanism_m) {
            for (std::size_t i = 0; i < w.bodies.size(); ++i)
                out.displacement.push_back({w.bodies.position_m[i] - p0[i], w.bodies.rotation_rad[i] - a0[i]});
            break;
        }
    }
    return out;
}

struct Comparison {
    double lp_lambda = 0.0;
    double dem_lambda = 0.0;
    std::size_t interfaces = 0;
    std::size_t mismatched = 0;   ///< interfaces whose motion differs between the LP and the DEM
    std::size_t lp_hinges = 0;
};

// The LP (live load towards -x: a positive tilt raises +x) against the DEM, from one degree
// below atan(lambda) at rate_deg_s.
Comparison compare(const Model& m, const char* what, double rate_deg_s, double max_s, double onset_m, double mechanism_m) {
    const LimitResult lp = solve_limit_analysis(m, {.live_load_direction = {-1.0, 0.0}});
    EXPECT_EQ(lp.status, LimitStatus::collapse) << what;
    Comparison c;
    c.lp_lambda = lp.lambda;
    c.interfaces = lp.interfaces.size();
    const double lp_tilt_deg = std::atan(lp.lambda) / deg;
    const DemCollapse dem = tilt_until_collapse(m, lp_tilt_deg - 1.0, rate_deg_s, max_s, onset_m, mechanism_m);
    c.dem_lambda = std::tan(dem.tilt_deg * deg);
    std::vector<InterfaceKinematics> dem_motion;
    if (!dem.displacement.empty()) dem_motion = interface_kinematics(m, lp.interfaces, dem.displacement, false, 0.1);
    for (std::size_t k = 0; k < lp.interfaces.size(); ++k) {
        const InterfaceMotion l = lp.kinematics[k].motion;
        c.lp_hinges += l == InterfaceMotion::hinge_at_end_0 || l == InterfaceMotion::hinge_at_end_1;
        if (dem_motion.empty() || dem_motion[k].motion != l) {
            ++c.mismatched;
            std::printf("  %s, interface %s / %s: LP %s, DEM %s\n", what, m.bodies[lp.interfaces[k].body_a].name.c_str(),
                        m.bodies[lp.interfaces[k].body_b].name.c_str(), to_string(l),
                        dem_motion.empty() ? "-" : to_string(dem_motion[k].motion));
        }
    }
    std::printf("%s: LP lambda = %.5f (tilt %.4f deg); DEM collapse at tilt %.4f deg, tan = %.5f (%+.2f %%); %zu interfaces, "
                "%zu LP hinges, %zu differ in the DEM\n",
                what, c.lp_lambda, lp_tilt_deg, dem.tilt_deg, c.dem_lambda, 100.0 * (c.dem_lambda / c.lp_lambda - 1.0),
                c.interfaces, c.lp_hinges, c.mismatched);
    return c;
}

Model with_base(std::vector<BodyDef> blocks, double base_width_m, double mu, double kn_N_m = 1e9) {
    std::vector<BodyDef> bodies{rectangle_body("base", BodyKind::fixed, base_width_m, 0.2, {0.0, -0.1})};
    for (BodyDef& b : blocks) bodies.push_back(std::move(b));
    return testing::model_with(std::move(bodies), testing::contact(kn_N_m, mu, 0.3, 1.0), 0.0, g);
}

BodyDef block(const std::string& name, double width_m, double height_m, Vec2 centre_m) {
    return rectangle_body(name, BodyKind::dynamic, width_m, height_m, centre_m, 0.0, 2500.0 * width_m * height_m);
}

void expect_agreement(const Comparison& c) {
    EXPECT_NEAR(c.dem_lambda / c.lp_lambda, 1.0, 0.03);
    EXPECT_EQ(c.mismatched, 0u);
}

TEST(LimitAnalysisDem, SlenderBlockTopplesAtTheMultiplier) {
    const Model m = with_base({block("block", 0.2, 0.8, {0.0, 0.4})}, 2.0, 0.6);
    const Comparison c = compare(m, "slender block 0.2 x 0.8 m", 0.25, 8.0, 1e-3, 5e-3);
    EXPECT_NEAR(c.lp_lambda, 0.25, 1e-9);
    expect_agreement(c);
}

TEST(LimitAnalysisDem, TwoBlockStackTopplesAsOne) {
    const Model m = with_base({block("low", 0.3, 0.6, {0.0, 0.3}), block("high", 0.4, 0.4, {0.0, 0.8})}, 2.0, 0.8);
    const Comparison c = compare(m, "two-block stack", 0.25, 8.0, 1e-3, 5e-3);
    expect_agreement(c);
}

// A running-bond wall 0.8 m long, 10 courses of 0.2 x 0.1 m bricks (1.0 m), with a window
// 0.4 x 0.3 m at 0.4 m and a lintel bearing 0.1 m each side, mu = 0.8, kn as given (38 bricks:
// about 6 s of CPU on the table; the 16-course wall of the first study took 35 s).
Model wall_with_window(double kn_N_m) {
    scenes::WallSpec spec;
    spec.origin_m = {-0.6, 0.0};
    spec.length_m = 0.8;
    spec.courses = 10;
    spec.openings.push_back({.x_m = 0.2, .y_m = 0.4, .width_m = 0.4, .height_m = 0.3, .lintel_bearing_m = 0.1});
    return with_base(scenes::as_bodies(scenes::masonry_wall(spec), {.name_prefix = "brick", .density_kg_m3 = 2500.0}), 2.0, 0.8,
                     kn_N_m);
}

// The blocks that move in a mechanism: those whose fastest point moves by more than 10 % of
// the fastest of all (a DEM displacement or an LP virtual velocity alike).
std::vector<bool> moving_blocks(const Model& m, const std::vector<BodyMotion>& motion) {
    const std::vector<Vec2> c = body_centroids_m(m);
    std::vector<double> fastest(motion.size(), 0.0);
    double largest = 0.0;
    for (std::size_t i = 0; i < motion.size(); ++i) {
        for (Vec2 v : m.bodies[i].vertices_m) fastest[i] = std::max(fastest[i], length(motion[i].velocity + cross(motion[i].rotation, v - c[i])));
        largest = std::max(largest, fastest[i]);
    }
    std::vector<bool> out(motion.size());
    for (std::size_t i = 0; i < motion.size(); ++i) out[i] = fastest[i] > 0.1 * largest;
    return out;
}

std::size_t count(const std::vector<bool>& v) { return static_cast<std::size_t>(std::count(v.begin(), v.end(), true)); }

std::size_t count_both(const std::vector<bool>& a, const std::vector<bool>& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) n += a[i] && b[i];
    return n;
}

// The wall on the table, settled start_below_deg under the associative LP's tilt (8 deg: the DEM
// collapses 4.5 deg under it, and a wall settled 4 deg under it falls while settling).
DemCollapse run_wall(const Model& m, double lp_lambda, double start_below_deg, double rate_deg_s, double dt_fraction) {
    const DemCollapse dem = tilt_until_collapse(m, std::atan(lp_lambda) / deg - start_below_deg, rate_deg_s, 30.0, 1e-3, 5e-3, dt_fraction);
    std::printf("  wall, kn = %.0e N/m, from %.0f deg below at %.2f deg/s, dt x %.2f: DEM tan(tilt) = %.5f\n",
                m.contact.at(0, 0).kn_N_m, start_below_deg, rate_deg_s, dt_fraction, std::tan(dem.tilt_deg * deg));
    return dem;
}

TEST(LimitAnalysisDem, WallWithWindow) {
    const Model m = wall_with_window(1e9);
    const LimitResult lp = solve_limit_analysis(m, {.live_load_direction = {-1.0, 0.0}});
    const LimitResult na = solve_limit_analysis(m, {.live_load_direction = {-1.0, 0.0}, .friction = FrictionFlow::non_associative});
    ASSERT_EQ(lp.status, LimitStatus::collapse);
    ASSERT_EQ(na.status, LimitStatus::collapse);
    const DemCollapse dem = run_wall(m, lp.lambda, 8.0, 1.0, 1.0);
    ASSERT_FALSE(dem.displacement.empty());
    const double dem_lambda = std::tan(dem.tilt_deg * deg);
    const std::vector<bool> dem_moving = moving_blocks(m, dem.displacement);
    const std::vector<bool> lp_moving = moving_blocks(m, lp.mechanism);
    const std::vector<bool> na_moving = moving_blocks(m, na.mechanism);
    std::printf("wall with window: LP lambda = %.5f associative (%zu blocks move), %.5f non-associative (%zu); DEM %.5f (%+.1f %%, "
                "%+.1f %%), %zu blocks move, %zu of them in the associative mechanism, %zu in the non-associative\n",
                lp.lambda, count(lp_moving), na.lambda, count(na_moving), dem_lambda, 100.0 * (dem_lambda / lp.lambda - 1.0),
                100.0 * (dem_lambda / na.lambda - 1.0), count(dem_moving), count_both(dem_moving, lp_moving),
                count_both(dem_moving, na_moving));
    // What holds, and why (docs/limit_analysis.md): the associative LP is an upper bound of a
    // collapse with friction that does not dilate (Drucker 1954), and the DEM is below it; the
    // iterated non-associative LP is one of the non-unique non-associative solutions, not a
    // bound, and the DEM (which depends on the contacts' elastic history) is 9 % under it; the
    // blocks that move are the associative LP's (24 of 38), each of them.
    // Joint by joint (printed, not asserted: the non-associative mechanism is not unique): the
    // DEM's opening, hinging and sliding joints against each LP's.
    const std::vector<InterfaceKinematics> dem_joints = interface_kinematics(m, lp.interfaces, dem.displacement, false, 0.1);
    for (const LimitResult* r : {&lp, &na}) {
        std::size_t moving = 0, same = 0;
        for (std::size_t k = 0; k < dem_joints.size(); ++k) {
            moving += r->kinematics[k].motion != InterfaceMotion::locked || dem_joints[k].motion != InterfaceMotion::locked;
            same += r->kinematics[k].motion != InterfaceMotion::locked && dem_joints[k].motion == r->kinematics[k].motion;
        }
        std::printf("  joints that move in the DEM or the %s LP: %zu; the same motion in both: %zu\n",
                    r == &lp ? "associative" : "non-associative", moving, same);
    }
    EXPECT_LT(dem_lambda, lp.lambda);
    EXPECT_GT(dem_lambda, 0.88 * na.lambda);
    EXPECT_LT(dem_lambda, na.lambda);
    EXPECT_EQ(dem_moving, lp_moving);
}

// The same wall with associative joints: per-length stiffness (JKN = 1e10 Pa/m, JKS = 5e9 Pa/m:
// a bed joint's point, 0.05 m of joint, 5e8 N/m, as stiff as the per-point wall's within a
// factor 2) and dilation angle = friction angle, tan(psi) = mu = 0.8. Such joints dilate as the
// associative LP's mechanism does, so the LP's multiplier is the collapse load (Drucker's
// bound is then exact; docs/limit_analysis.md).
Model wall_with_associative_joints() {
    Model m = wall_with_window(1e9);
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e10;
    p.ks_pa_m = 5e9;
    p.mu = 0.8;
    p.tan_dilation = 0.8;
    p.h_n = 0.3;
    p.h_s = 1.0;
    m.contact = MaterialPairs::uniform(p);
    // (The instability guard is the default one: the head joints' flicker between one- and
    // two-point contacts that lifted it is gone: tests/validation/test_jointed_wall_at_rest.cpp.)
    return m;
}

TEST(LimitAnalysisDem, WallWithWindowAndAssociativeJoints) {
    const Model m = wall_with_associative_joints();
    const LimitResult lp = solve_limit_analysis(m, {.live_load_direction = {-1.0, 0.0}});
    ASSERT_EQ(lp.status, LimitStatus::collapse);
    // (As built: settled with friction held, this per-length wall does not come to rest;
    // docs/limit_analysis.md.) The collapse is read where the mechanism runs away, at 1 cm.
    const DemCollapse dem = tilt_until_collapse(m, std::atan(lp.lambda) / deg - 8.0, 1.0, 30.0, 1e-2, 1e-2, 1.0, std::nullopt);
    ASSERT_FALSE(dem.displacement.empty());
    const double dem_lambda = std::tan(dem.tilt_deg * deg);
    const std::vector<bool> dem_moving = moving_blocks(m, dem.displacement);
    const std::vector<bool> lp_moving = moving_blocks(m, lp.mechanism);
    std::printf("wall with window, associative joints (tan psi = mu = 0.8): LP lambda = %.5f (%zu blocks move); DEM %.5f "
                "(%+.2f %%), %zu blocks move, %zu of them in the LP's mechanism\n",
                lp.lambda, count(lp_moving), dem_lambda, 100.0 * (dem_lambda / lp.lambda - 1.0), count(dem_moving),
                count_both(dem_moving, lp_moving));
    // (This protocol: the tilt set 8 deg below at t = 0 on the wall as built. Settled 8 deg
    // below: -1.9 %, the test below; from rest at 0 deg: -0.66 %, DISABLED_AssociativeWall-
    // FromThreeStarts: docs/limit_analysis.md. Asserted: what this protocol gives, and the LP
    // as upper bound.)
    EXPECT_LT(dem_lambda, lp.lambda);
    EXPECT_NEAR(dem_lambda / lp.lambda, 1.0, 0.03);
    EXPECT_EQ(count_both(dem_moving, lp_moving), count(lp_moving));  // every brick of the LP's mechanism moves
    EXPECT_LE(count(dem_moving), count(lp_moving) + 4);
}

// The same wall settled with the default criterion 8 deg below the LP's tilt (it settles now:
// test_jointed_wall_at_rest.cpp), then tilted at 1 deg/s: the collapse from a settled start.
// Its dilating joints settle under their own friction and dilation (world/settling.cpp: held
// friction left them outside their Coulomb cone, and the wall collapsed at 0.40904, -13.5 %).
// Asserted: the 3 % of the LP, as from the as-built start above (measured -1.92 %
// against -2.03 % as built: the collapse no longer depends on which of the two starts), and the
// LP as upper bound.
TEST(LimitAnalysisDem, WallWithWindowAndAssociativeJointsSettled) {
    const Model m = wall_with_associative_joints();
    const LimitResult lp = solve_limit_analysis(m, {.live_load_direction = {-1.0, 0.0}});
    ASSERT_EQ(lp.status, LimitStatus::collapse);
    const DemCollapse dem = tilt_until_collapse(m, std::atan(lp.lambda) / deg - 8.0, 1.0, 30.0, 1e-2, 1e-2, 1.0);
    ASSERT_FALSE(dem.displacement.empty());
    const double dem_lambda = std::tan(dem.tilt_deg * deg);
    std::printf("wall with window, associative joints, settled: LP lambda = %.5f; DEM %.5f (%+.2f %%)\n", lp.lambda, dem_lambda,
                100.0 * (dem_lambda / lp.lambda - 1.0));
    EXPECT_LT(dem_lambda, lp.lambda);
    EXPECT_NEAR(dem_lambda / lp.lambda, 1.0, 0.03);
}

// The study behind the settings above, run by hand (about 90 s of CPU): the DEM's multiplier
// against the rate, dt and kn.
TEST(LimitAnalysisDem, DISABLED_WallStudy) {
    for (double kn : {1e8, 1e9, 1e10}) {
        const Model m = wall_with_window(kn);
        const double lambda = solve_limit_analysis(m, {.live_load_direction = {-1.0, 0.0}}).lambda;
        run_wall(m, lambda, 8.0, 1.0, 1.0);
        if (kn != 1e9) continue;
        run_wall(m, lambda, 8.0, 0.5, 1.0);
        run_wall(m, lambda, 8.0, 1.0, 0.5);
        run_wall(m, lambda, 12.0, 1.0, 1.0);
    }
}

// The associative wall's start dependence, traced: every 0.5 deg of tilt, the largest
// movement, the accumulated dilation (sum and largest u_d), the points sliding, the changes of
// a pair's point count since the last line, and the kinetic energy. Returns tan(tilt) at 1 cm.
double trace_associative_wall(const char* what, double start_deg, std::optional<SettlingSettings> settling) {
    Model m = wall_with_associative_joints();
    m.settings.duration_s = 40.0;
    m.settings.dt_s.reset();
    m.settings.tilt_rad = start_deg * deg;
    m.settings.tilt_rate_rad_s = 1.0 * deg;
    m.settling = settling;
    World w = build_world(m);
    const std::vector<Vec2> p0 = w.bodies.position_m;
    const std::vector<double> a0 = w.bodies.rotation_rad;
    const std::size_t n = w.bodies.size();
    std::vector<std::uint32_t> counts(n * n, 0);  // by (a, b): the pair's point count last step
    std::size_t changes = 0;
    double next_deg = std::floor(start_deg) + 0.5;
    std::printf("%s\n  tilt deg   largest m   sum u_d m   max u_d m  sliding  changes  kinetic J\n", what);
    while (w.time_s < m.settings.duration_s) {
        step_begin(w);
        step_end(w);
        double sum_ud = 0.0, max_ud = 0.0;
        std::size_t sliding = 0;
        for (const PairContact& pair : w.contacts) {
            std::uint32_t& c = counts[pair.a * n + pair.b];
            if (c != pair.count) ++changes;
            c = pair.count;
            for (std::uint32_t k = 0; k < pair.count; ++k) {
                sum_ud += pair.points[k].dilation_m;
                max_ud = std::max(max_ud, pair.points[k].dilation_m);
                sliding += pair.points[k].sliding;
            }
        }
        double largest = 0.0;
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            if (w.bodies.kind[i] == BodyKind::dynamic) largest = std::max(largest, moved_m(w, i, p0, a0));
        const double tilt_deg = tilt_at_rad(w.settings, w.time_s) / deg;
        if (tilt_deg >= next_deg || largest > 1e-2) {
            std::printf("  %8.3f  %10.3e  %10.3e  %10.3e  %7zu  %7zu  %9.3e\n", tilt_deg, largest, sum_ud, max_ud, sliding, changes,
                        w.energy.kinetic_j);
            std::fflush(stdout);
            changes = 0;
            next_deg += 0.5;
        }
        if (largest > 1e-2) return std::tan(tilt_deg * deg);
    }
    return NAN;
}

// Run by hand (54 s of CPU, the start from rest 35 of them): the associative wall from three
// starts, each within 3 % of the LP, as an associative system's collapse must be whatever its
// (admissible) start. Measured: as built 8 deg below -2.03 %, settled 8 deg below -1.92 %
// (-13.5 % when settling held the joints' friction: world/settling.cpp), from rest at 0 deg
// -0.66 % (docs/limit_analysis.md).
TEST(LimitAnalysisDem, DISABLED_AssociativeWallFromThreeStarts) {
    const double lp = solve_limit_analysis(wall_with_associative_joints(), {.live_load_direction = {-1.0, 0.0}}).lambda;
    const double lp_deg = std::atan(lp) / deg;
    for (const double dem : {trace_associative_wall("as built, 8 deg below", lp_deg - 8.0, std::nullopt),
                             trace_associative_wall("settled, 8 deg below", lp_deg - 8.0, SettlingSettings{}),
                             trace_associative_wall("as built, from 0 deg", 0.0, std::nullopt)}) {
        std::printf("DEM %.5f against LP %.5f (%+.2f %%)\n", dem, lp, 100.0 * (dem / lp - 1.0));
        EXPECT_NEAR(dem / lp, 1.0, 0.03);
    }
}

Model semicircular_arch(double thickness_over_radius, int voussoirs) {
    scenes::ArchSpec spec;
    spec.span_m = 2.0;
    spec.rise_m = 1.0;
    spec.ring_thickness_m = thickness_over_radius;
    spec.voussoirs = voussoirs;
    return testing::model_with(scenes::arch_bodies(scenes::masonry_arch(spec), {.name_prefix = "v", .density_kg_m3 = 2500.0},
                                                   BodyKind::fixed),
                               testing::contact(1e9, 0.8, 0.3, 1.0), 0.0, g);
}

TEST(LimitAnalysisDem, ArchUnderLateralLoad) {
    const Comparison c = compare(semicircular_arch(0.15, 20), "arch t/R = 0.15, 20 voussoirs", 0.25, 8.0, 1e-3, 5e-3);
    EXPECT_EQ(c.lp_hinges, 4u);
    expect_agreement(c);
}

// Under its own weight (no tilt, no settling: it starts from rest as built): the crown's drop
// after 2 s. Standing, the ring only closes its joints elastically (m g / kn ~ 1e-6 m per joint);
// falling, it has dropped by centimetres (measured below).
double crown_drop_m(double thickness_over_radius) {
    Model m = semicircular_arch(thickness_over_radius, 20);
    m.settings.duration_s = 2.0;
    m.settings.dt_s.reset();
    World w = build_world(m);
    const std::size_t crown = 9;  // of 20 voussoirs, 9 and 10 meet at the crown
    const double y0 = w.bodies.position_m[crown].y;
    while (w.time_s < m.settings.duration_s) {
        step_begin(w);
        step_end(w);
    }
    return y0 - w.bodies.position_m[crown].y;
}

TEST(LimitAnalysisDem, ArchStandsAtTwelveAndFallsAtTenPercent) {
    const double stands = crown_drop_m(0.12);
    const double falls = crown_drop_m(0.10);
    std::printf("arch of 20 voussoirs under its own weight, crown drop after 2 s: t/R = 0.12: %.3g m; t/R = 0.10: %.3g m\n", stands,
                falls);
    EXPECT_LT(stands, 1e-4);
    EXPECT_GT(falls, 0.02);
}

}  // namespace
}  // namespace blockdem
