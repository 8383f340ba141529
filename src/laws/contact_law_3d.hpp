#pragma once
// The 3-D contact law at the points of one pair (world/step_3d.cpp takes it pair by pair): the
// normal spring-dashpot of the 2-D law (laws/linear_spring_dashpot.hpp) and the vector Coulomb
// slider (laws/coulomb_slider_3d.hpp), term by term, at one point (point_law) or at two points at
// once, one a lane (two_point_law, laws/double_lanes.hpp), where both stick well inside their
// caps. In a header of its own so that a test can hold the two forms against each other.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

#include "contact/contact_table_3d.hpp"
#include "laws/contact_parameters.hpp"
#include "laws/coulomb_slider_3d.hpp"
#include "laws/double_lanes.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/quad_lanes.hpp"

namespace blockdem::law_3d {

// What a pair's points share, taken once a pair: the two bodies' motion (the dashpots and
// stiffnesses are the points' own, by their stiffness shares). The relative velocity of b's material point at p to a's,
//   v_b + w_b x (p - x_b) - v_a - w_a x (p - x_a) = base + (w_b - w_a) x (p - x_a),
//   base = v_b - v_a + w_b x (x_a - x_b),
// is then one cross product a point instead of two (the same to round-off; measured from a's
// centroid, not the origin, so that no large coordinates cancel). A body that is not dynamic
// moves without turning.
struct PairMotion {
    Vec3 base_velocity_m_s;  ///< [m/s]
    Vec3 turn_rate_rad_s;    ///< [rad/s] w_b - w_a
    Vec3 centroid_a_m;       ///< [m]
};

// What the law at a pair's points shares besides the motion: the parameters, and the dashpot
// coefficients per unit of a point's stiffness share. A point of share w has kn w and ks w, and
// its dashpot mass is w M / S (find_contacts), so its coefficient 2 h sqrt(w M / S k w) is w
// times 2 h sqrt(k) sqrt(M / S): one root a pair for both dashpots, not two a point (where S = 0
// every w is 0, and so is every coefficient).
struct PairLaw {
    double kn_N_m = 0.0;              ///< [N/m] a point's at share 1
    double ks_N_m = 0.0;              ///< [N/m]
    double cn_per_share_N_s_m = 0.0;  ///< [N s/m] 2 h_n sqrt(M kn / S)
    double cs_per_share_N_s_m = 0.0;  ///< [N s/m] 2 h_s sqrt(M ks / S)
    double ks_dt_N = 0.0;             ///< [N] ks dt: the trial's increment is ks w dt v_t
    double mu = 0.0;
    double dt_s = 0.0;                ///< [s]
    ContactTermination termination = ContactTermination::no_tension;
};

// What the law's parameters give every pair, taken once a step: 2 h sqrt(k), so that a pair's
// dashpot coefficient per share 2 h sqrt(M k / S) is it times sqrt(M / S), one root a pair.
struct LawConstants {
    PairLaw law;                     ///< its cn and cs per share not yet set
    double cn_per_root_mass = 0.0;   ///< [N s/m / kg^0.5] 2 h_n sqrt(kn)
    double cs_per_root_mass = 0.0;   ///< [N s/m / kg^0.5] 2 h_s sqrt(ks)
    DoubleLanes kn_N_m{};            ///< [N/m] law's, in both lanes (two_point_law)
    DoubleLanes ks_dt_N{};           ///< [N]
    DoubleLanes mu{};
    // The energy terms' common factors (pair_law), the same products a pair took, once a step.
    double half_kn_N_m = 0.0;        ///< [N/m] 0.5 kn
    double half_per_ks_m_N = 0.0;    ///< [m/N] 0.5 / ks, 0 where ks is 0 (no spring, no energy)
    double minus_half_dt_s = 0.0;    ///< [s] -0.5 dt
};

// The law's constants for the parameters p at the step dt_s.
inline LawConstants law_constants(const ContactParameters& p, double dt_s) {
    return {{p.kn_N_m, p.ks_N_m, 0.0, 0.0, p.ks_N_m * dt_s, p.mu, dt_s, p.termination},
            2.0 * p.h_n * std::sqrt(p.kn_N_m),
            2.0 * p.h_s * std::sqrt(p.ks_N_m),
            lanes(p.kn_N_m),
            lanes(p.ks_N_m * dt_s),
            lanes(p.mu),
            0.5 * p.kn_N_m,
            p.ks_N_m > 0.0 ? 0.5 / p.ks_N_m : 0.0,
            -0.5 * dt_s};
}

// A pair's dashpot coefficients per share (PairLaw's two per-pair members): the pair's loop keeps
// these two, and the whole PairLaw is made only where a point leaves the two-lane line
// (one_point_law; copied at every pair it was 8 instructions a pair).
struct PairDashpots {
    double cn_per_share_N_s_m = 0.0;  ///< [N s/m]
    double cs_per_share_N_s_m = 0.0;  ///< [N s/m]
};

// A pair's energy terms before their common factors: each point adds its own products, and the
// pair multiplies them by 0.5 kn, 0.5 / ks and -0.5 dt once (a point's term
// 0.5 (kn w) o^2 is 0.5 kn (w o^2), its spring's 0.5 |F_s|^2 / (ks w) is (0.5 / ks) (|F_s|^2 / w),
// its dashpots' trapezoids -0.5 (D_before + D_now) . v dt: the same terms to round-off, fewer
// operations a point).
struct PairEnergySums {
    double share_overlap_squared_m2 = 0.0;     ///< [m^2] sum of w o^2
    double spring_squared_per_share_n2 = 0.0;  ///< [N^2] sum of |F_s|^2 / w over the points with w > 0
    double normal_dashpot_power_w = 0.0;       ///< [W] sum of (D_n before + D_n now) v_n
    double shear_dashpot_power_w = 0.0;        ///< [W] sum of (D_s before + D_s now) . v_t
    double friction_j = 0.0;                   ///< [J] the sliding points' own (coulomb_slider_3d)
};

// The law at one point of a pair: its force and history into its own slot, its energy terms
// added to e, its force returned (r: the point from a's centroid). The normal half of the 2-D law
// (linear_spring_dashpot.hpp) and the vector slider (coulomb_slider_3d.hpp), term by term. The
// common case, a point sticking well inside its cap (the spring carried, the trial and the total
// all with squares below surely_within_below), is one straight line of arithmetic; any other
// point takes coulomb_slider_3d itself. On the straight line the dashpot is -c_s w v_t and the
// total trial plus it (the slider forms the total first and the dashpot as total minus trial:
// the same to round-off).
[[gnu::always_inline]] inline Vec3 point_law(const PairMotion& m, const PairLaw& law, ContactPoint3d& c, Vec3 r,
                                             PairEnergySums& e) {
    const double share = c.stiffness_share;
    const double overlap_m = c.overlap_m;
    const Vec3 normal = c.normal;
    const Vec3 relative = m.base_velocity_m_s + cross(m.turn_rate_rad_s, r);
    const double normal_speed = dot(relative, normal);
    const Vec3 tangential = relative - normal_speed * normal;
    // The normal half's own work term is left unused (the compiler drops it): e sums its factors.
    ContactForce f;
    normal_spring_dashpot(law.kn_N_m * share, law.cn_per_share_N_s_m * share, law.termination, overlap_m, normal_speed,
                          c.normal_dashpot_n, law.dt_s, f);
    const double normal_n = f.normal_n;
    const double normal_dashpot_n = f.normal_dashpot_n;
    e.normal_dashpot_power_w += (c.normal_dashpot_n + normal_dashpot_n) * normal_speed;
    const ShearHistory3d carried = carry_to_normal_for_slider(c.shear, normal);
    const double limit_n = law.mu * std::max(0.0, normal_n);
    const double within_below = surely_within_below(limit_n);
    const double ks_N_m = law.ks_N_m * share;
    const Vec3 trial = carried.spring_n - (law.ks_dt_N * share) * tangential;
    Vec3 dashpot = (-law.cs_per_share_N_s_m * share) * tangential;
    Vec3 total = trial + dashpot;
    Vec3 spring = trial;
    bool sliding = false;
    if (!(dot(carried.spring_n, carried.spring_n) < within_below && dot(trial, trial) < within_below &&
          dot(total, total) < within_below)) {
        const ShearForce3d s = coulomb_slider_3d(ks_N_m, law.cs_per_share_N_s_m * share, limit_n, tangential, carried,
                                                 law.dt_s);
        spring = s.spring_n;
        total = s.total_n;
        dashpot = s.dashpot_n;
        sliding = s.sliding;
        e.friction_j += s.friction_work_j;
    }
    e.shear_dashpot_power_w += dot(carried.dashpot_n + dashpot, tangential);
    e.share_overlap_squared_m2 += share * overlap_m * overlap_m;
    if (share > 0.0) e.spring_squared_per_share_n2 += dot(spring, spring) / share;
    const Vec3 force_n = normal_n * normal + total;
    c.normal_dashpot_n = normal_dashpot_n;
    c.shear = {spring, dashpot};
    c.sliding = sliding;
    c.force_n = force_n;
    return force_n;
}

// The sums of pair_law taken two points at a time, one lane a point: added up at the pair's end.
struct PairLaneSums {
    Vec3Lanes force_n;                               ///< [N]
    Vec3Lanes torque_n_m;                            ///< [N m] about a's centroid
    DoubleLanes share_overlap_squared_m2;            ///< [m^2] as PairEnergySums
    DoubleLanes spring_squared_per_share_n2;         ///< [N^2]
    DoubleLanes normal_dashpot_power_w;              ///< [W]
    DoubleLanes shear_dashpot_power_w;               ///< [W]
};

// A pair's sums over all its points, whichever way each point was taken: the force on b, its
// moment about a's centroid, and the energy terms (world/step_3d.cpp's pair_totals takes them).
struct PairSums {
    Vec3 force_n;     ///< [N]
    Vec3 torque_n_m;  ///< [N m] about a's centroid
    PairEnergySums e;
};

// The sums of a pair whose points went two at a time (l) or one at a time (e, force_n, torque_n_m):
// the lanes added across to the single points' sums.
inline PairSums pair_sums(const PairLaneSums& l, PairEnergySums e, Vec3 force_n, Vec3 torque_n_m) {
    force_n += lane_sum(l.force_n);
    torque_n_m += lane_sum(l.torque_n_m);
    e.share_overlap_squared_m2 += lane_sum(l.share_overlap_squared_m2);
    e.spring_squared_per_share_n2 += lane_sum(l.spring_squared_per_share_n2);
    e.normal_dashpot_power_w += lane_sum(l.normal_dashpot_power_w);
    e.shear_dashpot_power_w += lane_sum(l.shear_dashpot_power_w);
    return {force_n, torque_n_m, e};
}

// A pair's motion and dashpots in both lanes, made once a pair (a lane made from a double is a copy
// and a shuffle: made a point, they were 19 instructions an iteration).
struct PairLanes {
    Vec3Lanes base_velocity_m_s;        ///< [m/s] PairMotion's
    Vec3Lanes turn_rate_rad_s;          ///< [rad/s]
    Vec3Lanes centroid_a_m;             ///< [m]
    DoubleLanes cn_per_share_N_s_m;     ///< [N s/m] PairLaw's
    DoubleLanes minus_cs_per_share_N_s_m;  ///< [N s/m]
};

inline PairLanes pair_lanes(const PairMotion& m, const PairDashpots& d) {
    return {lanes(m.base_velocity_m_s), lanes(m.turn_rate_rad_s), lanes(m.centroid_a_m),
            lanes(d.cn_per_share_N_s_m), lanes(-d.cs_per_share_N_s_m)};
}

// point_law's straight line at two points p and q of a pair at once, one lane each (the same
// operations in the same order, so each lane's result is its point's own): the carries into the
// normal's plane (carried_into_plane, carry_to_normal_for_slider, their roots taken in both lanes
// and kept where their rule takes them), the normal half (normal_spring_dashpot), the cap's test
// (surely_within_below). Writes both points and adds to l only where both stick inside their
// caps; returns false, with nothing written, otherwise (point_law then takes each).
[[gnu::always_inline]] inline bool two_point_law(const LawConstants& constants, const PairLanes& m,
                                                 ContactPoint3d& p, ContactPoint3d& q, PairLaneSums& l) {
    const DoubleLanes zero = lanes(0.0);
    const DoubleLanes share = lanes(p.stiffness_share, q.stiffness_share);
    const DoubleLanes overlap_m = lanes(p.overlap_m, q.overlap_m);
    const Vec3Lanes normal = lanes(p.normal, q.normal);
    const Vec3Lanes r = lanes(p.point_m, q.point_m) - m.centroid_a_m;
    const Vec3Lanes relative = m.base_velocity_m_s + cross(m.turn_rate_rad_s, r);
    const DoubleLanes normal_speed = dot(relative, normal);
    const Vec3Lanes tangential = relative - normal_speed * normal;
    // normal_spring_dashpot
    const DoubleLanes spring_n = (constants.kn_N_m * share) * overlap_m;
    const DoubleLanes spring_and_dashpot_n = spring_n - (m.cn_per_share_N_s_m * share) * normal_speed;
    const DoubleLanes normal_n = constants.law.termination == ContactTermination::zero_overlap
                                     ? spring_and_dashpot_n
                                     : lane_max(zero, spring_and_dashpot_n);
    const DoubleLanes normal_dashpot_n = normal_n - spring_n;
    // carry_to_normal_for_slider: the spring laid into the plane, the dashpot scaled alike
    const Vec3Lanes last_spring = lanes(p.shear.spring_n, q.shear.spring_n);
    const DoubleLanes spring_along = dot(last_spring, normal);
    const Vec3Lanes spring_in_plane = last_spring - spring_along * normal;
    const DoubleLanes spring_squared = dot(last_spring, last_spring);
    const DoubleLanes spring_in_plane_squared = spring_squared - spring_along * spring_along;
    // carried_into_plane's ratio, 1 where the square in the plane is the whole square (its rule
    // skips the root there, and sqrt(1) is 1), 0 where nothing is left in the plane.
    const Vec3Lanes carried_spring =
        select(spring_in_plane_squared > zero, lane_sqrt(spring_squared / spring_in_plane_squared), zero) *
        spring_in_plane;
    const Vec3Lanes last_dashpot = lanes(p.shear.dashpot_n, q.shear.dashpot_n);
    const DoubleLanes dashpot_along = dot(last_dashpot, normal);
    const DoubleLanes dashpot_squared = dot(last_dashpot, last_dashpot);
    const DoubleLanes dashpot_in_plane_squared = dashpot_squared - dashpot_along * dashpot_along;
    const Vec3Lanes carried_dashpot =
        select(dashpot_in_plane_squared > zero, lane_sqrt(dashpot_squared / dashpot_in_plane_squared), zero) *
        last_dashpot;
    // the slider, sticking
    const DoubleLanes limit_n = constants.mu * lane_max(zero, normal_n);
    const DoubleLanes limit_squared = limit_n * limit_n;
    const DoubleLanes within_below = select(limit_squared >= lanes(std::numeric_limits<double>::min()),
                                            limit_squared * lanes(1.0 - 1e-15), lanes(-1.0));
    const Vec3Lanes trial = carried_spring - (constants.ks_dt_N * share) * tangential;
    const Vec3Lanes dashpot = (m.minus_cs_per_share_N_s_m * share) * tangential;
    const Vec3Lanes total = trial + dashpot;
    const DoubleLanes trial_squared = dot(trial, trial);
    // The carried spring's own square, as point_law tests it: last step's square is not a bound
    // for it (the carry's rescale rounds it up by up to 14 units in the last place at a 45-degree
    // turn, past surely_within_below's margin, so a spring at the cap would stick here and slide
    // there).
    if (!both((dot(carried_spring, carried_spring) < within_below) & (trial_squared < within_below) &
              (dot(total, total) < within_below)))
        return false;
    l.normal_dashpot_power_w += (lanes(p.normal_dashpot_n, q.normal_dashpot_n) + normal_dashpot_n) * normal_speed;
    l.shear_dashpot_power_w += dot(carried_dashpot + dashpot, tangential);
    l.share_overlap_squared_m2 += share * overlap_m * overlap_m;
    l.spring_squared_per_share_n2 += select(share > zero, trial_squared / share, zero);
    const Vec3Lanes force_n = normal_n * normal + total;
    l.force_n += force_n;
    l.torque_n_m += cross(r, force_n);
    p.normal_dashpot_n = normal_dashpot_n[0];
    q.normal_dashpot_n = normal_dashpot_n[1];
    p.shear = {lane(trial, 0), lane(dashpot, 0)};
    q.shear = {lane(trial, 1), lane(dashpot, 1)};
    p.sliding = false;
    q.sliding = false;
    p.force_n = lane(force_n, 0);
    q.force_n = lane(force_n, 1);
    return true;
}

#if BLOCKDEM_QUAD_LANES
// The law's three constants in four lanes (LawConstants' two-lane ones) and its termination, made
// once for many pairs (world/step_3d.cpp: once a chunk of pairs), so that each pair reads them from
// memory: made a pair, they were broadcast again at every pair and kept in spills.
struct LawQuads {
    QuadLanes kn_N_m;             ///< [N/m]
    QuadLanes ks_dt_N;            ///< [N]
    QuadLanes mu;
    ContactTermination termination = ContactTermination::no_tension;
};

BLOCKDEM_QUAD LawQuads law_quads(const LawConstants& k) {
    return {quad(k.law.kn_N_m), quad(k.law.ks_dt_N), quad(k.law.mu), k.law.termination};
}

// A pair's motion and dashpots in four lanes (PairLanes'), made once a pair.
struct PairQuads {
    Vec3Quad base_velocity_m_s;   ///< [m/s]
    Vec3Quad turn_rate_rad_s;     ///< [rad/s]
    Vec3Quad centroid_a_m;        ///< [m]
    QuadLanes cn_per_share_N_s_m;        ///< [N s/m]
    QuadLanes minus_cs_per_share_N_s_m;  ///< [N s/m]
};

BLOCKDEM_QUAD PairQuads pair_quads(const PairMotion& m, const PairDashpots& d) {
    return {quad(m.base_velocity_m_s), quad(m.turn_rate_rad_s), quad(m.centroid_a_m),
            quad(d.cn_per_share_N_s_m), quad(-d.cs_per_share_N_s_m)};
}

// The terms four_point_law adds up, one lane a point, not yet summed: a pair of four points sums
// them across the lanes at once (pair_sums), where two_point_law's sums took each vector's halves,
// then its two lanes.
struct PairQuadTerms {
    Vec3Quad force_n;                        ///< [N]
    Vec3Quad torque_n_m;                     ///< [N m] about a's centroid
    QuadLanes share_overlap_squared_m2;      ///< [m^2] as PairEnergySums
    QuadLanes spring_squared_per_share_n2;   ///< [N^2]
    QuadLanes normal_dashpot_power_w;        ///< [W]
    QuadLanes shear_dashpot_power_w;         ///< [W]
};

// The terms t added to two-lane sums l as two_point_law at p[0], p[1] and then at p[2], p[3] adds
// them (the same bits).
BLOCKDEM_QUAD void add_halves(PairLaneSums& l, const PairQuadTerms& t) {
    blockdem::add_halves(l.normal_dashpot_power_w, t.normal_dashpot_power_w);
    blockdem::add_halves(l.shear_dashpot_power_w, t.shear_dashpot_power_w);
    blockdem::add_halves(l.share_overlap_squared_m2, t.share_overlap_squared_m2);
    blockdem::add_halves(l.spring_squared_per_share_n2, t.spring_squared_per_share_n2);
    blockdem::add_halves(l.force_n, t.force_n);
    blockdem::add_halves(l.torque_n_m, t.torque_n_m);
}

// The sums of a pair whose four points all went through four_point_law: each term's four lanes
// summed as pair_sums sums two_point_law's lanes after the two halves (the same bits but for the
// sign of a sum of zeros), ten vectors in three groups (quad_lanes.hpp, sums_across_lanes).
BLOCKDEM_QUAD PairSums pair_sums(const PairQuadTerms& t) {
    const QuadLanes force_and_x = sums_across_lanes(t.force_n.x, t.force_n.y, t.force_n.z, t.torque_n_m.x);
    const QuadLanes torque_and_dashpots = sums_across_lanes(t.torque_n_m.y, t.torque_n_m.z, t.normal_dashpot_power_w,
                                                            t.shear_dashpot_power_w);
    const DoubleLanes springs = sums_across_lanes(t.share_overlap_squared_m2, t.spring_squared_per_share_n2);
    return {{force_and_x[0], force_and_x[1], force_and_x[2]},
            {force_and_x[3], torque_and_dashpots[0], torque_and_dashpots[1]},
            {springs[0], springs[1], torque_and_dashpots[2], torque_and_dashpots[3], 0.0}};
}

// The law's results at four points p[0..3], one lane a point, written into the points: the lanes
// transposed so that each point's normal dashpot and shear spring (four doubles side by side) go as
// one 32-byte store, its shear dashpot's and force's x and y as two 16-byte ones, their z and the
// flag one at a time (written a value at a time from the vectors' halves, GCC kept the halves
// spilled: about 110 instructions a pair, about 45 now).
BLOCKDEM_QUAD void store_four(ContactPoint3d* p, QuadLanes normal_dashpot_n, const Vec3Quad& spring_n,
                              const Vec3Quad& dashpot_n, const Vec3Quad& force_n) {
    static_assert(sizeof(Vec3) == 3 * sizeof(double) && offsetof(ShearHistory3d, dashpot_n) == sizeof(Vec3));
    constexpr std::size_t history_at = offsetof(ContactPoint3d, normal_dashpot_n);
    static_assert(offsetof(ContactPoint3d, shear) == history_at + sizeof(double));
    constexpr std::size_t dashpot_at = offsetof(ContactPoint3d, shear) + offsetof(ShearHistory3d, dashpot_n);
    constexpr std::size_t force_at = offsetof(ContactPoint3d, force_n);
    QuadLanes history[4], xy[4];
    transpose(normal_dashpot_n, spring_n.x, spring_n.y, spring_n.z, history);
    transpose(dashpot_n.x, dashpot_n.y, force_n.x, force_n.y, xy);
#pragma GCC unroll 4  // a loop, it kept the transposed vectors in memory to index them
    for (int i = 0; i < 4; ++i) {
        auto* bytes = reinterpret_cast<unsigned char*>(&p[i]);
        std::memcpy(bytes + history_at, &history[i], sizeof(QuadLanes));
        const DoubleLanes dashpot_xy = low_half(xy[i]), force_xy = high_half(xy[i]);
        std::memcpy(bytes + dashpot_at, &dashpot_xy, sizeof(DoubleLanes));
        std::memcpy(bytes + force_at, &force_xy, sizeof(DoubleLanes));
        p[i].shear.dashpot_n.z = dashpot_n.z[i];
        p[i].force_n.z = force_n.z[i];
        p[i].sliding = false;
    }
}

// two_point_law at four points p[0..3] of a pair at once, one lane each, for AVX2 (laws/quad_lanes.hpp):
// the same operations in the same order, so each lane's result is its point's own; the terms to sum
// left in t, one lane a point. Writes the four points and t only where all four stick inside their
// caps; returns false, with nothing written, otherwise (two_point_law then takes each two).
BLOCKDEM_QUAD bool four_point_law(const LawQuads& law, const PairQuads& m, ContactPoint3d* p, PairQuadTerms& t) {
    const QuadLanes zero = quad(0.0);
    // The points' fields read four doubles at a time, transposed: the point and the normal's x, then
    // the normal's y and z, the overlap and the share (side by side in ContactPoint3d).
    static_assert(offsetof(ContactPoint3d, normal) == offsetof(ContactPoint3d, point_m) + sizeof(Vec3) &&
                  offsetof(ContactPoint3d, overlap_m) == offsetof(ContactPoint3d, normal) + sizeof(Vec3) &&
                  offsetof(ContactPoint3d, stiffness_share) == offsetof(ContactPoint3d, overlap_m) + sizeof(double));
    const unsigned char* bytes[4] = {reinterpret_cast<const unsigned char*>(&p[0]),
                                     reinterpret_cast<const unsigned char*>(&p[1]),
                                     reinterpret_cast<const unsigned char*>(&p[2]),
                                     reinterpret_cast<const unsigned char*>(&p[3])};
    constexpr std::size_t first = offsetof(ContactPoint3d, point_m);
    constexpr std::size_t second = offsetof(ContactPoint3d, normal) + sizeof(double);
    QuadLanes point_and_x[4], yz_overlap_share[4];
    load_transposed(bytes[0] + first, bytes[1] + first, bytes[2] + first, bytes[3] + first, point_and_x);
    load_transposed(bytes[0] + second, bytes[1] + second, bytes[2] + second, bytes[3] + second, yz_overlap_share);
    const QuadLanes share = yz_overlap_share[3];
    const QuadLanes overlap_m = yz_overlap_share[2];
    const Vec3Quad normal{point_and_x[3], yz_overlap_share[0], yz_overlap_share[1]};
    const Vec3Quad r = Vec3Quad{point_and_x[0], point_and_x[1], point_and_x[2]} - m.centroid_a_m;
    const Vec3Quad relative = m.base_velocity_m_s + cross(m.turn_rate_rad_s, r);
    const QuadLanes normal_speed = dot(relative, normal);
    const Vec3Quad tangential = relative - normal_speed * normal;
    // normal_spring_dashpot
    const QuadLanes spring_n = (law.kn_N_m * share) * overlap_m;
    const QuadLanes spring_and_dashpot_n = spring_n - (m.cn_per_share_N_s_m * share) * normal_speed;
    const QuadLanes normal_n = law.termination == ContactTermination::zero_overlap ? spring_and_dashpot_n
                                                                               : quad_max(zero, spring_and_dashpot_n);
    const QuadLanes normal_dashpot_n = normal_n - spring_n;
    // carry_to_normal_for_slider
    const Vec3Quad last_spring =
        quad(p[0].shear.spring_n, p[1].shear.spring_n, p[2].shear.spring_n, p[3].shear.spring_n);
    const QuadLanes spring_along = dot(last_spring, normal);
    const Vec3Quad spring_in_plane = last_spring - spring_along * normal;
    const QuadLanes spring_squared = dot(last_spring, last_spring);
    const QuadLanes spring_in_plane_squared = spring_squared - spring_along * spring_along;
    const Vec3Quad carried_spring =
        select(spring_in_plane_squared > zero, quad_sqrt(spring_squared / spring_in_plane_squared), zero) *
        spring_in_plane;
    // the slider, sticking
    const QuadLanes limit_n = law.mu * quad_max(zero, normal_n);
    const QuadLanes limit_squared = limit_n * limit_n;
    const QuadLanes within_below = select(limit_squared >= quad(std::numeric_limits<double>::min()),
                                          limit_squared * quad(1.0 - 1e-15), quad(-1.0));
    const Vec3Quad trial = carried_spring - (law.ks_dt_N * share) * tangential;
    const Vec3Quad dashpot = (m.minus_cs_per_share_N_s_m * share) * tangential;
    const Vec3Quad total = trial + dashpot;
    const QuadLanes trial_squared = dot(trial, trial);
    if (!all_four((dot(carried_spring, carried_spring) < within_below) & (trial_squared < within_below) &
                  (dot(total, total) < within_below)))
        return false;
    // Last step's shear dashpot carried into the plane only now: only the energy term needs it, and
    // read before the test its vectors were kept in memory across it.
    const Vec3Quad last_dashpot =
        quad(p[0].shear.dashpot_n, p[1].shear.dashpot_n, p[2].shear.dashpot_n, p[3].shear.dashpot_n);
    const QuadLanes dashpot_along = dot(last_dashpot, normal);
    const QuadLanes dashpot_squared = dot(last_dashpot, last_dashpot);
    const QuadLanes dashpot_in_plane_squared = dashpot_squared - dashpot_along * dashpot_along;
    const Vec3Quad carried_dashpot =
        select(dashpot_in_plane_squared > zero, quad_sqrt(dashpot_squared / dashpot_in_plane_squared), zero) *
        last_dashpot;
    const QuadLanes last_normal_dashpot_n = quad(p[0].normal_dashpot_n, p[1].normal_dashpot_n,
                                                 p[2].normal_dashpot_n, p[3].normal_dashpot_n);
    t.normal_dashpot_power_w = (last_normal_dashpot_n + normal_dashpot_n) * normal_speed;
    t.shear_dashpot_power_w = dot(carried_dashpot + dashpot, tangential);
    t.share_overlap_squared_m2 = share * overlap_m * overlap_m;
    t.spring_squared_per_share_n2 = select(share > zero, trial_squared / share, zero);
    const Vec3Quad force_n = normal_n * normal + total;
    t.force_n = force_n;
    t.torque_n_m = cross(r, force_n);
    store_four(p, normal_dashpot_n, trial, dashpot, force_n);
    return true;
}
#endif

}  // namespace blockdem::law_3d
