// Joints with stiffness per unit length and the Mohr-Coulomb bond (laws/mohr_coulomb_joint.hpp)
// against closed forms:
//  - a column of blocks under gravity closes each joint by sigma / kn (kn in Pa/m);
//  - a block under a steady shear displaces by tau / ks;
//  - direct shear of a bonded block peaks at c A + N tan(phi), then slides at N tan(phi_r);
//  - direct tension breaks the bond at sigma_t A;
//  - a bonded cantilever of blocks cracks at its root when the discrete joint's moment capacity
//    (two points h apart, each of area h t / 2: M = sigma_t t h^2 / 2 plus the axial force's
//    share) is reached.
// Tolerances, and why: the closures and displacements are those of linear springs in static
// equilibrium, reached by damping (h = 0.5); what is left of the motion after the settling
// time is far below 1e-4 of them, so 1% is the engineering tolerance of the issue with margin.
// The peaks are reached by a slow ramp (tilt or table acceleration) whose inertia is below
// 1e-3 of the load. The peak shear is that of the discrete joint, whose two points fail one
// after the other: the moment of the shear force about the joint (arm h/2 = 2.5 cm over a 2 m
// joint) makes their normal forces differ by F_s h / w, so the first point fails at
// (c A + N tan phi) / (1 + tan(phi) h / w), 1.5% below the continuum's c A + N tan(phi):
// asserted within 0.2% of the former (the ramp moves the load by 1e-4 a step) and 2% of the
// latter. The tension is uniform, so there the two points break together: within 1%. The
// residual slide is the Coulomb cap itself: within 0.1%.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;
using validation::deg;

ContactParameters joint(double kn_pa_m, double ks_pa_m, double mu) {
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = kn_pa_m;
    p.ks_pa_m = ks_pa_m;
    p.mu = mu;
    p.h_n = 0.5;
    p.h_s = 0.5;
    return p;
}

Model joint_model(std::vector<BodyDef> bodies, const ContactParameters& c, double duration_s) {
    Model m = testing::model_with(std::move(bodies), c, 0.0, g, duration_s);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    return m;
}

void run_to(World& w, double t_s) {
    while (w.time_s < t_s) {
        step_begin(w);
        step_end(w);
    }
}

// The pair's summed forces on b: normal and shear [N].
struct PairLoad {
    double normal_n = 0.0;
    double shear_n = 0.0;
    int intact = 0;
};

PairLoad load_of(const World& w, std::uint32_t a, std::uint32_t b) {
    PairLoad l;
    for (const PairContact& pair : w.contacts) {
        if (pair.a != std::min(a, b) || pair.b != std::max(a, b)) continue;
        for (std::uint32_t k = 0; k < pair.count; ++k) {
            l.normal_n += pair.points[k].normal_force_n;
            l.shear_n += pair.points[k].shear_force_n;
            l.intact += pair.points[k].bond == BondState::intact ? 1 : 0;
        }
    }
    return l;
}

double mean_overlap(const World& w, std::uint32_t a, std::uint32_t b) {
    for (const PairContact& pair : w.contacts)
        if (pair.a == std::min(a, b) && pair.b == std::max(a, b) && pair.count == 2)
            return 0.5 * (pair.points[0].overlap_m + pair.points[1].overlap_m);
    return NAN;
}

TEST(Joints, ColumnUnderGravityClosesEachJointBySigmaOverKn) {
    // Four blocks 0.5 m wide, 0.25 m tall, 0.4 m thick, 2000 kg/m^3 (100 kg each) on a fixed
    // base; JKN = 1e9 Pa/m. Joint j from the bottom carries (4 - j) blocks.
    const double width = 0.5, height = 0.25, thickness = 0.4, mass = 2000.0 * width * height * thickness;
    std::vector<BodyDef> bodies{testing::rectangle_body("base", BodyKind::fixed, 1.0, 0.2, {0.0, -0.1})};
    for (int i = 0; i < 4; ++i) {
        BodyDef b = testing::rectangle_body("block" + std::to_string(i), BodyKind::dynamic, width, height,
                                            {0.0, (i + 0.5) * height}, 0.0, mass);
        b.thickness_m = thickness;
        bodies.push_back(b);
    }
    bodies[0].thickness_m = 1.0;  // the thinner body's thickness counts: the blocks'
    const double kn = 1e9;
    World w = build_world(joint_model(bodies, joint(kn, 0.5 * kn, 0.6), 0.3));
    run_to(w, 0.3);
    for (int j = 0; j < 4; ++j) {
        const double sigma_pa = (4 - j) * mass * g / (width * thickness);
        const double closure_m = mean_overlap(w, j, j + 1);
        EXPECT_NEAR(closure_m, sigma_pa / kn, 0.01 * sigma_pa / kn) << "joint " << j;
    }
    EXPECT_LT(w.energy.balance_error(), 1e-3);
}

TEST(Joints, BlockUnderShearDisplacesByTauOverKsBeforeSliding) {
    // A flat block 1 m x 0.1 m of 500 kg on a table tilted 10 deg (tan 10 deg = 0.18 < mu = 0.6):
    // tau = m g sin(10 deg) / (w t); the base slips by tau / ks elastically.
    const double width = 1.0, height = 0.1, mass = 500.0, ks = 5e8;
    Model m = joint_model({testing::rectangle_body("table", BodyKind::fixed, 2.0, 0.2, {0.0, -0.1}),
                           testing::rectangle_body("block", BodyKind::dynamic, width, height, {0.0, 0.05}, 0.0, mass)},
                          joint(1e9, ks, 0.6), 0.3);
    m.settings.tilt_rad = 10.0 * deg;
    World w = build_world(m);
    run_to(w, 0.3);
    // The middle of the block's base: the centroid's motion plus the turn times h/2.
    const double base_slip_m = (w.bodies.position_m[1].x - w.bodies.initial_position_m[1].x) +
                               w.bodies.rotation_rad[1] * 0.5 * height;
    const double expected_m = -mass * g * std::sin(10.0 * deg) / (ks * width * 1.0);  // gravity pulls toward -x
    EXPECT_NEAR(base_slip_m, expected_m, 0.01 * std::abs(expected_m));
    EXPECT_FALSE(w.contacts[0].points[0].sliding);
}

// A 2 m x 5 cm block of 1000 kg (its mass given: a thin block keeps the shear force's moment
// small) bonded to a fixed table, c = 1 kPa, sigma_t = 1 kPa, mu = 0.6, residual 0.4; the
// table tilts from 30 deg at 20 deg/s.
TEST(Joints, DirectShearPeaksAtCohesionPlusFrictionThenResidual) {
    const double width = 2.0, height = 0.05, mass = 1000.0, c = 1e3, mu = 0.6, residual = 0.4;
    std::vector<BodyDef> bodies{testing::rectangle_body("table", BodyKind::fixed, 3.0, 0.2, {0.0, -0.1}),
                                testing::rectangle_body("block", BodyKind::dynamic, width, height, {0.0, 0.5 * height}, 0.0, mass)};
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p = joint(1e9, 5e8, mu);
    p.cohesion_pa = c;
    p.tensile_strength_pa = 1e3;
    p.residual_mu = residual;
    Model m = joint_model(bodies, p, 1.2);
    m.settings.tilt_rad = 30.0 * deg;
    m.settings.tilt_rate_rad_s = 20.0 * deg;
    World w = build_world(m);
    ASSERT_EQ(load_of(w, 0, 1).intact, 2);
    // The shear and normal force of the joint at the last step before its first point broke.
    PairLoad before_break;
    double residual_ratio = NAN;
    while (w.time_s < 1.2) {
        step_begin(w);
        const PairLoad l = load_of(w, 0, 1);
        if (l.intact == 2) before_break = l;
        if (l.intact == 0 && w.time_s > 1.0) residual_ratio = std::abs(l.shear_n) / l.normal_n;
        step_end(w);
    }
    const double area = width * 1.0;
    const double continuum_n = c * area + mu * before_break.normal_n;
    // The discrete joint: the shear's moment F h / 2 unloads the downhill point by F h / (2 w),
    // so it reaches its c A / 2 + mu N_i first, at F = (c A + mu N) / (1 + mu h / w).
    const double discrete_n = continuum_n / (1.0 + mu * height / width);
    EXPECT_NEAR(std::abs(before_break.shear_n), discrete_n, 0.002 * discrete_n);
    EXPECT_NEAR(std::abs(before_break.shear_n), continuum_n, 0.02 * continuum_n);
    EXPECT_NEAR(residual_ratio, residual, 1e-3 * residual);
    EXPECT_GT(w.energy.bond_breakage_j, 0.0);
    EXPECT_LT(w.energy.balance_error(), 1e-2);
}

// A 0.5 m x 0.2 m block of 100 kg bonded under a driven ceiling, sigma_t = 10 kPa over
// A = 0.5 m^2: it breaks when m (g + a) = sigma_t A = 5000 N, a = 40.19 m/s^2; the ceiling
// accelerates upwards at a rate of 100 m/s^3.
TEST(Joints, DirectTensionBreaksAtTensileStrengthTimesArea) {
    const double width = 0.5, mass = 100.0, sigma_t = 1e4;
    std::vector<BodyDef> bodies{testing::rectangle_body("ceiling", BodyKind::driven, 1.0, 0.2, {0.0, 0.1}),
                                testing::rectangle_body("block", BodyKind::dynamic, width, 0.2, {0.0, -0.1}, 0.0, mass)};
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p = joint(1e9, 5e8, 0.6);
    p.cohesion_pa = 1e5;
    p.tensile_strength_pa = sigma_t;
    p.h_n = 1.0;
    Model m = joint_model(bodies, p, 0.6);
    m.table_motion.vertical = make_acceleration_series({0.0, 1.0}, {0.0, 100.0});
    World w = build_world(m);
    ASSERT_EQ(load_of(w, 0, 1).intact, 2);
    double pull_at_break = NAN;
    double last_pull = 0.0;
    while (w.time_s < 0.6 && std::isnan(pull_at_break)) {
        step_begin(w);
        const PairLoad l = load_of(w, 0, 1);
        if (l.intact < 2) pull_at_break = last_pull;
        last_pull = -l.normal_n;  // n points from the ceiling (a) down to the block (b): a pull is < 0
        step_end(w);
    }
    EXPECT_NEAR(pull_at_break, sigma_t * width * 1.0, 0.01 * sigma_t * width);
    EXPECT_LT(w.energy.balance_error(), 1e-2);
}

// A cantilever of four bonded 0.5 x 0.2 m blocks (2000 kg/m^3, t = 1 m) out of a fixed wall;
// the table's tilt falls from 89 deg (gravity along the beam, pressing it on the wall) at
// 40 deg/s, so the bending load g cos(tilt) grows slowly against the axial g sin(tilt). The
// root joint's two points, h apart at the top and bottom corners, carry the moment
// M = w cos(tilt) L^2 / 2 and the compression N = w sin(tilt) L (w = rho g h t, L = 2 m): the
// top point pulls with T = M / h - N / 2 and its bond breaks at T = sigma_t (h / 2) t. The
// tolerance, 0.5 deg: the ramp's dynamic share (the beam's first period, 0.05 s, is 2 deg of
// ramp; damping h = 0.5) and the joints' elastic rotation, which shortens no lever.
TEST(Joints, BondedCantileverCracksAtTheDiscreteJointsMomentCapacity) {
    const double length = 0.5, height = 0.2, density = 2000.0, sigma_t = 3.2e5;
    const int blocks = 4;
    std::vector<BodyDef> bodies{testing::rectangle_body("wall", BodyKind::fixed, 0.4, 1.0, {-0.2, 0.0})};
    for (int i = 0; i < blocks; ++i)
        bodies.push_back(testing::rectangle_body("block" + std::to_string(i), BodyKind::dynamic, length, height,
                                                 {(i + 0.5) * length, 0.0}, 0.0, density * length * height));
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p = joint(1e10, 4e9, 0.6);
    p.cohesion_pa = 1e6;
    p.tensile_strength_pa = sigma_t;
    Model m = joint_model(bodies, p, 1.6);
    m.settings.tilt_rad = 89.0 * deg;
    m.settings.tilt_rate_rad_s = -40.0 * deg;
    World w = build_world(m);
    ASSERT_EQ(load_of(w, 0, 1).intact, 2);
    double crack_tilt_deg = NAN;
    bool root_first = false;
    while (w.time_s < 1.6 && std::isnan(crack_tilt_deg)) {
        step_begin(w);
        for (const PairContact& pair : w.contacts)
            for (std::uint32_t k = 0; k < pair.count; ++k)
                if (is_broken(pair.points[k].bond) && std::isnan(crack_tilt_deg)) {
                    crack_tilt_deg = 89.0 - 40.0 * w.time_s;
                    root_first = pair.a == 0 && pair.b == 1;
                }
        step_end(w);
    }
    // The closed form: the tilt at which T = sigma_t h t / 2 (bisection; T grows as the tilt falls).
    const double w_n_m = density * g * height * 1.0, span = blocks * length;
    auto pull_beyond_strength = [&](double tilt_deg) {
        const double a = tilt_deg * deg;
        return w_n_m * std::cos(a) * span * span / (2.0 * height) - 0.5 * w_n_m * std::sin(a) * span -
               0.5 * sigma_t * height * 1.0;
    };
    double lo = 0.0, hi = 89.0;  // pull_beyond_strength(lo) > 0 > pull_beyond_strength(hi)
    for (int i = 0; i < 60; ++i) (pull_beyond_strength(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_TRUE(root_first);
    EXPECT_NEAR(crack_tilt_deg, lo, 0.5);
    // The continuum's capacity sigma_t t h^2 / 6 is a third of the discrete joint's: that
    // section would have cracked much earlier (at a steeper tilt).
    auto continuum_beyond = [&](double tilt_deg) {
        const double a = tilt_deg * deg;
        return w_n_m * std::cos(a) * span * span / 2.0 - sigma_t * height * height / 6.0 -
               w_n_m * std::sin(a) * span * height / 6.0;
    };
    EXPECT_GT(continuum_beyond(crack_tilt_deg + 5.0), 0.0);
}

// The same cantilever with its joints discretised into n sub-contacts (contact/sub_contacts.hpp):
// its root cracks when the top point's stress, M (h/2) / I_n - N / h with the discrete second
// moment I_n = (h^3 / 12) (1 + 2 / (n - 1)^2) (trapezoid rule, t = 1 m), reaches sigma_t. The
// moment capacity falls towards the continuous joint's, sigma_t t h^2 / 6 (plus the axial
// force's share N h / 6), as n grows. Returns the tilt [deg] at the first broken point, and
// whether it was in the root joint.
struct Crack {
    double tilt_deg = NAN;
    bool at_root = false;
    double balance_error = NAN;  ///< the energy ledger's relative error at the crack
};

constexpr double cantilever_length = 0.5, cantilever_height = 0.2, cantilever_density = 2000.0, cantilever_sigma_t = 3.2e5;
constexpr int cantilever_blocks = 4;
constexpr double cantilever_start_deg = 89.0, cantilever_rate_deg_s = 10.0, cantilever_ramp_s = 6.5;

Crack bonded_cantilever_crack(std::uint32_t sub_contacts) {
    const double length = cantilever_length, height = cantilever_height, density = cantilever_density;
    std::vector<BodyDef> bodies{testing::rectangle_body("wall", BodyKind::fixed, 0.4, 1.0, {-0.2, 0.0})};
    for (int i = 0; i < cantilever_blocks; ++i)
        bodies.push_back(testing::rectangle_body("block" + std::to_string(i), BodyKind::dynamic, length, height,
                                                 {(i + 0.5) * length, 0.0}, 0.0, density * length * height));
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p = joint(1e10, 4e9, 0.6);
    p.cohesion_pa = 1e6;
    p.tensile_strength_pa = cantilever_sigma_t;
    Model m = joint_model(bodies, p, cantilever_ramp_s);
    m.contact.sub_contacts = sub_contacts;
    m.settings.tilt_rad = cantilever_start_deg * deg;
    m.settings.tilt_rate_rad_s = -cantilever_rate_deg_s * deg;
    World w = build_world(m);
    Crack crack;
    auto broken = [](const ContactPoint& q) { return is_broken(q.bond); };
    while (w.time_s < cantilever_ramp_s && std::isnan(crack.tilt_deg)) {
        step_begin(w);
        for (std::size_t i = 0; i < w.contacts.size(); ++i) {
            const PairContact& pair = w.contacts[i];
            bool any = std::any_of(pair.points, pair.points + pair.count, broken);
            if (i < w.sub_contacts.size())
                any = any || std::any_of(w.sub_contacts[i].points, w.sub_contacts[i].points + w.sub_contacts[i].count, broken);
            if (any && std::isnan(crack.tilt_deg)) {
                crack.tilt_deg = cantilever_start_deg - cantilever_rate_deg_s * w.time_s;
                crack.at_root = pair.a == 0 && pair.b == 1;
            }
        }
        step_end(w);
    }
    crack.balance_error = w.energy.balance_error();
    return crack;
}

// The tilt [deg] at which the root's top point of an n-point joint reaches sigma_t (bisection).
double discrete_crack_tilt_deg(std::uint32_t n) {
    const double h = cantilever_height, w_n_m = cantilever_density * g * h * 1.0;
    const double span = cantilever_blocks * cantilever_length;
    const double second_moment = h * h * h / 12.0 * (1.0 + 2.0 / ((n - 1.0) * (n - 1.0)));
    auto beyond = [&](double tilt_deg) {
        const double a = tilt_deg * deg;
        return w_n_m * std::cos(a) * span * span / 2.0 * (h / 2.0) / second_moment - w_n_m * std::sin(a) * span / h -
               cantilever_sigma_t;
    };
    double lo = 0.0, hi = 89.0;
    for (int i = 0; i < 60; ++i) (beyond(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    return lo;
}

// The ramp is 10 deg/s from 89 deg, four times slower than the two-point test's: the refined
// joints crack near 70 deg, where the bending moment grows by tan(tilt) of itself per radian,
// so a fast ramp's dynamic share (measured: 0.8 deg at 40 deg/s, n = 4) would blur the trend
// (and a start closer to the crack tilt loads the beam suddenly and cracks it at once).
// Tolerances: each crack within 0.3 deg of its discrete closed form (measured within 0.16 deg:
// the ramp's dynamic share, the joints' elastic rotation). The moment capacity at the n = 16
// crack, M - N h / 6 from the measured tilt, within 2 % of the continuous joint's
// sigma_t t h^2 / 6: the 16-point joint is 0.9 % above it in bending, and 0.3 deg of tilt is
// about 1 % of the moment there (measured: 1.5 % above).
TEST(Joints, SubContactsBringTheCantileversCrackToTheContinuousJointsCapacity) {
    const std::uint32_t counts[] = {2, 4, 8, 16};
    double previous_tilt_deg = -INFINITY;
    double last_capacity_n_m = NAN;
    for (const std::uint32_t n : counts) {
        const Crack crack = bonded_cantilever_crack(n);
        SCOPED_TRACE(n);
        EXPECT_TRUE(crack.at_root);
        EXPECT_LT(crack.balance_error, 1e-2);  // as the direct tension test's ledger
        EXPECT_NEAR(crack.tilt_deg, discrete_crack_tilt_deg(n), 0.3);
        // Less capacity, earlier crack: at a steeper tilt for every refinement.
        EXPECT_GT(crack.tilt_deg, previous_tilt_deg);
        previous_tilt_deg = crack.tilt_deg;
        const double a = crack.tilt_deg * deg, h = cantilever_height;
        const double w_n_m = cantilever_density * g * h, span = cantilever_blocks * cantilever_length;
        last_capacity_n_m = w_n_m * std::cos(a) * span * span / 2.0 - w_n_m * std::sin(a) * span * h / 6.0;
    }
    const double continuous_n_m = cantilever_sigma_t * 1.0 * cantilever_height * cantilever_height / 6.0;
    EXPECT_NEAR(last_capacity_n_m, continuous_n_m, 0.02 * continuous_n_m);
}

// The cracking of the cantilever's root joint with n sub-contacts, run on past the first crack
// (contact/sub_contacts.hpp, "Crack growth"): which points of the root joint broke, in order.
struct Cracking {
    std::vector<double> break_heights_m;   ///< of the root's points, in the order they broke (+h/2: the top)
    std::vector<double> break_tilts_deg;   ///< the table's tilt at each break
    std::vector<bool> broke_in_tension;
    int intact_points_dropped = 0;         ///< intact points that left the root joint without breaking
    bool rebonded = false;                 ///< a point was intact after it broke
    double balance_error = NAN;            ///< the energy ledger's relative error when the last point broke
};

// The root joint's points now, by height (top first), with their bonds.
std::vector<std::pair<double, BondState>> root_points(const World& w) {
    std::vector<std::pair<double, BondState>> points;
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const PairContact& pair = w.contacts[i];
        if (pair.a != 0 || pair.b != 1) continue;
        for (std::uint32_t k = 0; k < pair.count; ++k) points.emplace_back(pair.points[k].point_m.y, pair.points[k].bond);
        if (i < w.sub_contacts.size())
            for (std::uint32_t k = 0; k < w.sub_contacts[i].count; ++k)
                points.emplace_back(w.sub_contacts[i].points[k].point_m.y, w.sub_contacts[i].points[k].bond);
    }
    std::sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    return points;
}

Cracking cantilever_cracking(std::uint32_t n) {
    const double length = cantilever_length, height = cantilever_height, density = cantilever_density;
    std::vector<BodyDef> bodies{testing::rectangle_body("wall", BodyKind::fixed, 0.4, 1.0, {-0.2, 0.0})};
    for (int i = 0; i < cantilever_blocks; ++i)
        bodies.push_back(testing::rectangle_body("block" + std::to_string(i), BodyKind::dynamic, length, height,
                                                 {(i + 0.5) * length, 0.0}, 0.0, density * length * height));
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p = joint(1e10, 4e9, 0.6);
    p.cohesion_pa = 1e6;
    p.tensile_strength_pa = cantilever_sigma_t;
    Model m = joint_model(bodies, p, cantilever_ramp_s);
    m.contact.sub_contacts = n;
    m.settings.tilt_rad = cantilever_start_deg * deg;
    m.settings.tilt_rate_rad_s = -cantilever_rate_deg_s * deg;
    World w = build_world(m);
    Cracking c;
    std::vector<std::pair<double, BondState>> previous = root_points(w);
    auto intact = [](const auto& q) { return q.second == BondState::intact; };
    while (w.time_s < cantilever_ramp_s && std::any_of(previous.begin(), previous.end(), intact)) {
        step_begin(w);
        const std::vector<std::pair<double, BondState>> now = root_points(w);
        for (const auto& q : previous) {
            const auto same = std::find_if(now.begin(), now.end(), [&](const auto& r) { return std::abs(r.first - q.first) < 1e-3; });
            if (same == now.end()) {
                c.intact_points_dropped += intact(q) ? 1 : 0;
                continue;
            }
            if (intact(q) && is_broken(same->second)) {
                c.break_heights_m.push_back(q.first);
                c.break_tilts_deg.push_back(cantilever_start_deg - cantilever_rate_deg_s * w.time_s);
                c.broke_in_tension.push_back(same->second == BondState::broken_tension);
            }
            c.rebonded = c.rebonded || (is_broken(q.second) && intact(*same));
        }
        previous = now;
        step_end(w);
    }
    c.balance_error = w.energy.balance_error();
    return c;
}

// With n sub-contacts the root joint cracks point by point from its top (the tension side):
// each of its n points breaks in turn, top to bottom, h / (n - 1) apart, the first n - 1 in
// tension as the crack front runs down the joint while the load grows; the last, the bottom
// corner, is the hinge the cracked beam then falls about, and breaks when the fall pulls it.
// No point leaves the joint while bonded, none bonds again, and the ledger stays closed through
// the cracking: within 1e-3 (measured below 2.5e-4; the bond breakage term books each break).
// Measured (n = 16): the front runs from 72.09 to 70.45 deg of tilt, i.e. the load at which the
// crack runs through is 11 % above the first crack's; n = 4: 68.26 to 67.71 deg; n = 8: 71.43 to
// 70.39 deg. (The load at the first crack against sigma_t t h^2 / 6: the test above.)
TEST(Joints, SubContactsCrackTheCantileversRootPointByPoint) {
    for (const std::uint32_t n : {4u, 8u, 16u}) {
        SCOPED_TRACE(n);
        const Cracking c = cantilever_cracking(n);
        std::printf("n = %u: the root's points broke at heights [m] / tilts [deg]:", n);
        for (std::size_t k = 0; k < c.break_heights_m.size(); ++k)
            std::printf(" %.4f/%.3f%s", c.break_heights_m[k], c.break_tilts_deg[k], c.broke_in_tension[k] ? "" : " (shear)");
        std::printf("; balance error %.3g\n", c.balance_error);
        ASSERT_EQ(c.break_heights_m.size(), n) << "every point of the root joint breaks once";
        const double spacing_m = cantilever_height / (n - 1);
        for (std::uint32_t k = 0; k < n; ++k)
            EXPECT_NEAR(c.break_heights_m[k], 0.5 * cantilever_height - k * spacing_m, 1e-3) << "break " << k;
        for (std::uint32_t k = 0; k + 1 < n; ++k) EXPECT_TRUE(c.broke_in_tension[k]) << "break " << k;
        EXPECT_NEAR(c.break_tilts_deg.front(), discrete_crack_tilt_deg(n), 0.3);
        EXPECT_EQ(c.intact_points_dropped, 0);
        EXPECT_FALSE(c.rebonded);
        EXPECT_LT(c.balance_error, 1e-3);
    }
}

}  // namespace
}  // namespace blockdem
