#include "contact/contact_forces.hpp"

#include <algorithm>
#include <cmath>

#include "contact/narrow_phase_pair.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/mohr_coulomb_joint.hpp"
#include "world/parallel.hpp"


namespace blockdem {
namespace {

ContactParameters softened(ContactParameters p, double scale) {
    p.kn_N_m *= scale;
    p.ks_N_m *= scale;
    return p;
}

// The relative velocity of b's and a's material points at x.
Vec2 relative_velocity(const Bodies& b, std::uint32_t ia, std::uint32_t ib, Vec2 x) {
    const Vec2 ra = x - b.position_m[ia];
    const Vec2 rb = x - b.position_m[ib];
    return (b.velocity_m_s[ib] + cross(b.angular_velocity_rad_s[ib], rb)) -
           (b.velocity_m_s[ia] + cross(b.angular_velocity_rad_s[ia], ra));
}

// The last half interval of the dashpots of interior points that were dropped (as
// opened_points_work below, for the pair's own points), along normal n of when they were placed.
ContactEnergy dropped_sub_points_work(const Bodies& b, const PairContact& pair, Vec2 n, const DroppedSubPoints& dropped,
                                      double dt_s) {
    ContactEnergy energy;
    for (std::uint32_t k = 0; k < dropped.count; ++k) {
        const ContactPoint& point = dropped.points[k];
        const Vec2 relative = relative_velocity(b, pair.a, pair.b, point.point_m);
        energy.normal_dashpot_j -= 0.5 * point.normal_dashpot_n * dot(relative, n) * dt_s;
        energy.shear_dashpot_j -= 0.5 * point.shear_dashpot_n * dot(relative, perp(n)) * dt_s;
    }
    return energy;
}

// The dashpots of a joint point (dashpot_coefficients with the point's own stiffnesses; the
// pair's parameters are not copied for it, a copy per pair showed in profiles).
DashpotCoefficients joint_dashpots(const ContactParameters& p, const JointPoint& joint, double mass_kg) {
    return {2.0 * p.h_n * std::sqrt(mass_kg * joint.kn_N_m), 2.0 * p.h_s * std::sqrt(mass_kg * joint.ks_N_m)};
}

// The two bodies of a pair as the joint law reads them: their entries, found once per pair.
// (References, not copies: a copy per pair was spilled and copied again by the compiler.)
struct PairMotion {
    const Vec2& position_a_m;             ///< [m]
    const Vec2& position_b_m;             ///< [m]
    const Vec2& velocity_a_m_s;           ///< [m/s]
    const Vec2& velocity_b_m_s;           ///< [m/s]
    const double& angular_velocity_a_rad_s;  ///< [rad/s]
    const double& angular_velocity_b_rad_s;  ///< [rad/s]
};

PairMotion pair_motion(const Bodies& b, std::uint32_t ia, std::uint32_t ib) {
    return {b.position_m[ia], b.position_m[ib], b.velocity_m_s[ia], b.velocity_m_s[ib],
            b.angular_velocity_rad_s[ia], b.angular_velocity_rad_s[ib]};
}

// What one pass of the per-length law over a pair shares between its points.
struct JointPass {
    const PairMotion& motion;
    Vec2 n, t;
    const ContactParameters& params;
    double dt_s;
};

// A point's force on b and its moments about the two bodies' centres (what the pair's slot holds).
struct PointLoad {
    Vec2 on_b_n;             ///< [N]
    double on_b_n_m = 0.0;   ///< [N m] torque on b
    double on_a_n_m = 0.0;   ///< [N m] torque on a, of the force on b (the slot's sign convention)
};

// A point of a joint that is open and not bonded (a cracked point past which the crack opened,
// kept with its face: sub_contacts.hpp) carries nothing: the law's dry point would still push
// with its normal dashpot where the gap closes. What it held is let go as the dry point lets it
// go when it opens: the last half interval of its normal dashpot, and the shear spring slides
// to a zero cap (the slider books the release as friction work).
JointForce open_point(const JointPoint& joint, const DashpotCoefficients& dash, const ContactKinematics& k,
                      const ContactHistory& previous, BondState bond, double dilation_m, double dt_s) {
    JointForce out;
    out.bond = bond;
    out.dilation_m = dilation_m;  // (kept, as the dilating law keeps an open point's)
    out.force.normal_dashpot_work_j = -0.5 * previous.normal_dashpot_n * k.normal_speed_m_s * dt_s;
    coulomb_slider(joint.ks_N_m, dash.cs_N_s_m, 0.0, k.tangential_speed_m_s, previous, dt_s, out.force);
    return out;
}

// The law at one point of a per-length joint: updates the point and the ledger's terms, and
// returns the point's force on b and its moments. (Flattened: the law and the energy inline
// here, as the dry law does in pair_law; a call per point cost a bonded wall a third of its step.)
[[gnu::flatten]] PointLoad joint_point_step(const JointPass& s, ContactPoint& point, const JointPoint& joint,
                                            const DashpotCoefficients& dash, ContactEnergy& energy) {
    const PairMotion& m = s.motion;
    const Vec2 ra = point.point_m - m.position_a_m;
    const Vec2 rb = point.point_m - m.position_b_m;
    const Vec2 relative = (m.velocity_b_m_s + cross(m.angular_velocity_b_rad_s, rb)) -
                          (m.velocity_a_m_s + cross(m.angular_velocity_a_rad_s, ra));
    const ContactKinematics kin{point.overlap_m, dot(relative, s.n), dot(relative, s.t)};
    // (A dilating joint's law treats its open points itself: its trial may dip below zero
    // overlap in steady sliding and dilate back: laws/mohr_coulomb_joint.hpp.)
    const JointForce j = point.overlap_m < 0.0 && point.bond != BondState::intact && s.params.tan_dilation == 0.0
                             ? open_point(joint, dash, kin, point.history(), point.bond, point.dilation_m, s.dt_s)
                             : mohr_coulomb_joint(s.params, joint, dash, kin, point.history(), point.bond, s.dt_s,
                                                  {point.dilation_m, point.normal_force_n});
    const ContactForce& f = j.force;
    point.normal_force_n = f.normal_n;
    point.shear_spring_n = f.shear_spring_n;
    point.shear_force_n = f.shear_n;
    point.normal_dashpot_n = f.normal_dashpot_n;
    point.shear_dashpot_n = f.shear_dashpot_n;
    point.sliding = f.sliding;
    point.bond = j.bond;
    point.dilation_m = j.dilation_m;
    energy.normal_dashpot_j += f.normal_dashpot_work_j;
    energy.shear_dashpot_j += f.shear_dashpot_work_j;
    energy.friction_j += f.friction_work_j;
    energy.bond_breakage_j += j.bond_breakage_j;
    energy.elastic_j += joint_elastic_energy(joint, point.overlap_m, point.shear_spring_n, point.bond, point.dilation_m);
    const Vec2 on_b = f.normal_n * s.n + f.shear_n * s.t;
    return {on_b, cross(rb, on_b), cross(ra, on_b)};
}

// The stiffness and area of an end point of a per-length pair (joint_point_of, inline here:
// the law calls it once per pair at every step).
inline JointPoint end_joint_point(const Bodies& b, const PairContact& pair, const ContactParameters& p,
                                  double rounding_m, std::uint32_t points) {
    const double thickness_m = std::min(b.thickness_m[pair.a], b.thickness_m[pair.b]);
    const double least_width_m = std::min(b.least_width_m[pair.a], b.least_width_m[pair.b]);
    double tributary_m = tributary_length_m(pair.count, pair.points[0].point_m, pair.points[1].point_m, least_width_m, rounding_m);
    if (points > 2) tributary_m /= points - 1;  // an end's share of n points (contact/sub_contacts.hpp)
    // (The softening of a vanishing overlap applies as to a per-point contact: polygon_contact.hpp.)
    return joint_point(p, tributary_m * pair.stiffness_scale, thickness_m);
}

// The per-length law at the points of a pair that has no interior points and does not dilate
// (every pair of a wall without sub-contacts or dilation): joint_pair_law's results, bit for
// bit, with 12 % fewer instructions (docs/performance.md, "The per-length wall without
// bonds"). What it leaves out:
// the interior points' bookkeeping; the dilation branch; the JointForce of a point that is not
// bonded (a dry point keeps its bond, breaks nothing, and has no dilation once closed, as in
// mohr_coulomb_joint); and the mass shares' product, end share times pair share, which for a
// pair's own one or two points is mass_sharing_points exactly (a halving and a doubling).
// The ledger's terms are summed in locals and written once.
[[gnu::flatten]] inline void joint_ends_law(PairContact& pair, const Bodies& b, const ContactParameters& p,
                                        double rounding_m, double dt_s, std::uint32_t mass_sharing_points,
                                        PairForces& out, ContactEnergy& energy) {
    const std::uint32_t ia = pair.a;
    const std::uint32_t ib = pair.b;
    const JointPoint joint = end_joint_point(b, pair, p, rounding_m, pair.count);
    const double reduced_mass = 1.0 / (b.inv_mass_1_kg[ia] + b.inv_mass_1_kg[ib]);
    const DashpotCoefficients dash = joint_dashpots(p, joint, reduced_mass / mass_sharing_points);
    const double broken_mu = residual_friction(p);
    const Vec2 n = pair.normal;
    const Vec2 t = perp(n);
    double normal_dashpot_j = 0.0, shear_dashpot_j = 0.0, friction_j = 0.0, breakage_j = 0.0, elastic_j = 0.0;
    double deepest_m = 0.0;
    for (std::uint32_t k = 0; k < pair.count; ++k) {
        ContactPoint& point = pair.points[k];
        const Vec2 ra = point.point_m - b.position_m[ia];
        const Vec2 rb = point.point_m - b.position_m[ib];
        const Vec2 relative = (b.velocity_m_s[ib] + cross(b.angular_velocity_rad_s[ib], rb)) -
                              (b.velocity_m_s[ia] + cross(b.angular_velocity_rad_s[ia], ra));
        const ContactKinematics kin{point.overlap_m, dot(relative, n), dot(relative, t)};
        ContactForce f;
        double normal_m;  // [m] what the normal spring stores energy on (joint_elastic_energy)
        if (point.bond == BondState::intact) {
            // (No dilation history: an intact bond does not dilate, nor does this pair.)
            const JointForce j = mohr_coulomb_joint(p, joint, dash, kin, point.history(), point.bond, dt_s);
            f = j.force;
            point.bond = j.bond;
            point.dilation_m = j.dilation_m;
            breakage_j += j.bond_breakage_j;
            normal_m = j.bond == BondState::intact ? point.overlap_m : std::max(0.0, point.overlap_m + j.dilation_m);
        } else if (point.overlap_m < 0.0) {
            // An open point that held nothing last step either (a kept open face) holds nothing
            // now: its shear spring, released to a zero cap, is a zero with the sign of the
            // trial, and every work term a zero, which adds nothing to the sums (never -0: they
            // start at +0). What open_point gives, without its arithmetic; a zero trial (no slip)
            // or one not finite takes open_point.
            const double trial_n = point.shear_spring_n - joint.ks_N_m * (kin.tangential_speed_m_s * dt_s);
            if (point.shear_spring_n == 0.0 && point.normal_dashpot_n == 0.0 && point.shear_dashpot_n == 0.0 &&
                std::abs(trial_n) > 0.0 && std::abs(trial_n) < INFINITY) {
                f.shear_spring_n = trial_n < 0.0 ? -0.0 : 0.0;
                f.shear_n = f.shear_spring_n;
                f.sliding = true;
            } else {
                f = open_point(joint, dash, kin, point.history(), point.bond, point.dilation_m, dt_s).force;
            }
            normal_m = std::max(0.0, point.overlap_m + point.dilation_m);
        } else {
            const double friction = point.bond == BondState::none ? p.mu : broken_mu;
            f = joint_detail::dry_point(p, friction, joint, dash, kin, point.history(), dt_s);
            point.dilation_m = 0.0;
            normal_m = std::max(0.0, point.overlap_m);  // (overlap + 0: the same bits)
        }
        point.normal_force_n = f.normal_n;
        point.shear_spring_n = f.shear_spring_n;
        point.shear_force_n = f.shear_n;
        point.normal_dashpot_n = f.normal_dashpot_n;
        point.shear_dashpot_n = f.shear_dashpot_n;
        point.sliding = f.sliding;
        normal_dashpot_j += f.normal_dashpot_work_j;
        shear_dashpot_j += f.shear_dashpot_work_j;
        friction_j += f.friction_work_j;
        const double shear_j = joint.ks_N_m > 0.0 ? 0.5 * f.shear_spring_n * f.shear_spring_n / joint.ks_N_m : 0.0;
        elastic_j += 0.5 * joint.kn_N_m * normal_m * normal_m + shear_j;
        const Vec2 on_b = f.normal_n * n + f.shear_n * t;
        out.on_b_n[k] = on_b;
        out.torque_on_b_n_m[k] = cross(rb, on_b);
        out.torque_on_a_n_m[k] = cross(ra, on_b);
        deepest_m = std::max(deepest_m, point.overlap_m);
    }
    energy.normal_dashpot_j = normal_dashpot_j;
    energy.shear_dashpot_j = shear_dashpot_j;
    energy.friction_j = friction_j;
    energy.bond_breakage_j = breakage_j;
    energy.elastic_j = elastic_j;
    energy.deepest_overlap_ratio = deepest_m / std::min(b.least_width_m[ia], b.least_width_m[ib]);
}

// The interior points of a pair with sub-contacts (points > 2 in all), placed from this step's
// ends; returns the work of the dashpots of those dropped. Out of line, as interior_points_law.
[[gnu::noinline]] ContactEnergy place_interior_points(const Bodies& b, const PairContact& pair, SubContacts& sub,
                                                      std::uint32_t points, double dt_s) {
    const double match_distance_m = 0.05 * std::min(b.part_radius_m[pair.part_a], b.part_radius_m[pair.part_b]);
    return dropped_sub_points_work(b, pair, sub.normal, place_sub_points(sub, pair, points, match_distance_m), dt_s);
}

// The law at the interior points of a pair with sub-contacts: twice an end's tributary length,
// stiffness and mass share; their forces go to the first end's slot. Returns energy with their
// terms added. Out of line: most joints have none, and inlined, its point arrays crowded the
// ends' loop off the registers. (The pass and the energy go by value: by reference they would
// have to live in memory through the ends' loop.)
[[gnu::noinline, gnu::flatten]] ContactEnergy interior_points_law(const Bodies& b, const PairContact& pair,
                                                                  const ContactParameters& params, double dt_s,
                                                                  SubContacts& sub, JointPoint end, double reduced_mass_kg,
                                                                  double end_share, ContactEnergy energy, PairForces& out) {
    const PairMotion motion = pair_motion(b, pair.a, pair.b);
    const JointPass pass{motion, pair.normal, perp(pair.normal), params, dt_s};
    const JointPoint inner{2.0 * end.kn_N_m, 2.0 * end.ks_N_m, 2.0 * end.area_m2};
    const DashpotCoefficients inner_dash = joint_dashpots(params, inner, 2.0 * reduced_mass_kg / end_share);
    for (std::uint32_t k = 0; k < sub.count; ++k) {
        const PointLoad load = joint_point_step(pass, sub.points[k], inner, inner_dash, energy);
        out.on_b_n[0] += load.on_b_n;
        out.torque_on_b_n_m[0] += load.on_b_n_m;
        out.torque_on_a_n_m[0] += load.on_a_n_m;
    }
    return energy;
}

// The per-length joint at every point of one pair (laws/mohr_coulomb_joint.hpp): each point
// with its own tributary length, stiffness and dashpots; with sub-contacts (sub: the pair's
// interior points, or null), an edge-to-edge contact has n points (contact/sub_contacts.hpp),
// whose interior points' forces are added to the first end's slot. Each point's dashpots take
// the share of the pair's reduced mass that its tributary length has of the contact's, so the
// points' dashpots together give the pair the requested damping ratio. Kept apart from
// pair_law so that the per-point law's loop is what it was. mass_sharing_points: the active
// points of the body pair over all its part pairs (concave bodies), pair.count otherwise.
// (Flattened, as joint_point_step: the ends' points in one body of code.)
[[gnu::flatten]] inline ContactEnergy joint_pair_law(PairContact& pair, const Bodies& b, const ContactParameters& stored, double rounding_m,
                                                 std::uint32_t sub_contacts, SubContacts* sub, double dt_s,
                                                 std::uint32_t mass_sharing_points, PairForces& out) {
    const std::uint32_t ia = pair.a;
    const std::uint32_t ib = pair.b;
    const std::uint32_t points = sub != nullptr && pair.count == 2 ? sub_contacts : pair.count;
    ContactEnergy energy;
    if (points > 2) energy = place_interior_points(b, pair, *sub, points, dt_s);
    const PairMotion motion = pair_motion(b, ia, ib);
    const JointPass pass{motion, pair.normal, perp(pair.normal), stored, dt_s};
    const JointPoint joint = end_joint_point(b, pair, stored, rounding_m, points);
    const double reduced_mass = 1.0 / (b.inv_mass_1_kg[ia] + b.inv_mass_1_kg[ib]);
    const double end_share = pair.count == 2 ? 2.0 * (points - 1) : 1.0;
    // (An end's share: 1 / (2 (n - 1)) of the mass for an edge contact, all of it for a corner,
    // and of that the part pair's share of the body pair's points.)
    const double pair_share = static_cast<double>(mass_sharing_points) / pair.count;
    const DashpotCoefficients dash = joint_dashpots(stored, joint, reduced_mass / (end_share * pair_share));
    double deepest_m = 0.0;
    for (std::uint32_t k = 0; k < pair.count; ++k) {
        const PointLoad load = joint_point_step(pass, pair.points[k], joint, dash, energy);
        out.on_b_n[k] = load.on_b_n;
        out.torque_on_b_n_m[k] = load.on_b_n_m;
        out.torque_on_a_n_m[k] = load.on_a_n_m;
        deepest_m = std::max(deepest_m, pair.points[k].overlap_m);
    }
    if (points > 2) energy = interior_points_law(b, pair, stored, dt_s, *sub, joint, reduced_mass, end_share, energy, out);
    energy.deepest_overlap_ratio = deepest_m / std::min(b.least_width_m[ia], b.least_width_m[ib]);
    return energy;
}

// joint_pair_law out of line, for pair_law: kept apart from it so that the per-point law's loop
// is what it was.
[[gnu::noinline]] ContactEnergy joint_pair_law_apart(PairContact& pair, const Bodies& b, const ContactParameters& stored,
                                                     double rounding_m, std::uint32_t sub_contacts, SubContacts* sub,
                                                     double dt_s, std::uint32_t mass_sharing_points, PairForces& out) {
    return joint_pair_law(pair, b, stored, rounding_m, sub_contacts, sub, dt_s, mass_sharing_points, out);
}

// The law at every point of one pair: updates the points' forces and history, and writes what
// they add to the two bodies into the pair's own slot (no shared sums: parallel.hpp, rule 1).
// Returns the pair's share of the ledger: this step's dissipation and the springs' energy now.
ContactEnergy pair_law(PairContact& pair, const Bodies& b, const MaterialPairs& contact, SubContacts* sub, double dt_s,
                       std::uint32_t mass_sharing_points, PairForces& out) {
    ContactEnergy energy;
    out.count = pair.count;
    if (pair.count == 0) return energy;
    const std::uint32_t ia = pair.a;
    const std::uint32_t ib = pair.b;
    const ContactParameters& stored = contact.at(b.material[ia], b.material[ib]);
    if (stored.stiffness == StiffnessBasis::per_length)
        return joint_pair_law_apart(pair, b, stored, contact.rounding_m, contact.sub_contacts, sub, dt_s, mass_sharing_points, out);
    const ContactParameters params = softened(stored, pair.stiffness_scale);
    const double reduced_mass = 1.0 / (b.inv_mass_1_kg[ia] + b.inv_mass_1_kg[ib]);
    const DashpotCoefficients dash = dashpot_coefficients(params, reduced_mass / mass_sharing_points);
    const Vec2 n = pair.normal;
    const Vec2 t = perp(n);
    double deepest_m = 0.0;
    for (std::uint32_t k = 0; k < pair.count; ++k) {
        ContactPoint& point = pair.points[k];
        const Vec2 ra = point.point_m - b.position_m[ia];
        const Vec2 rb = point.point_m - b.position_m[ib];
        const Vec2 relative = (b.velocity_m_s[ib] + cross(b.angular_velocity_rad_s[ib], rb)) -
                              (b.velocity_m_s[ia] + cross(b.angular_velocity_rad_s[ia], ra));
        const ContactKinematics kin{point.overlap_m, dot(relative, n), dot(relative, t)};
        const ContactForce f = linear_spring_dashpot(params, dash, kin, point.history(), dt_s);
        point.normal_force_n = f.normal_n;
        point.shear_spring_n = f.shear_spring_n;
        point.shear_force_n = f.shear_n;
        point.normal_dashpot_n = f.normal_dashpot_n;
        point.shear_dashpot_n = f.shear_dashpot_n;
        point.sliding = f.sliding;
        const Vec2 on_b = f.normal_n * n + f.shear_n * t;
        out.on_b_n[k] = on_b;
        out.torque_on_b_n_m[k] = cross(rb, on_b);
        out.torque_on_a_n_m[k] = cross(ra, on_b);
        energy.normal_dashpot_j += f.normal_dashpot_work_j;
        energy.shear_dashpot_j += f.shear_dashpot_work_j;
        energy.friction_j += f.friction_work_j;
        energy.elastic_j += contact_elastic_energy(params, point.overlap_m, point.shear_spring_n);
        deepest_m = std::max(deepest_m, point.overlap_m);
    }
    energy.deepest_overlap_ratio = deepest_m / std::min(b.least_width_m[ia], b.least_width_m[ib]);
    return energy;
}

// The work of the dashpots of points that opened since the last step, over the interval that
// ends now. The law books a dashpot's work by the trapezoid: at each step, the mean of last
// step's force and this one's times the speed of the interval between them. Summed over a
// contact's life, that is every force times the mean speed around it, short of the last
// force's second half: -F_last v dt / 2 over the interval after the last step, whose speed
// (v(t - dt/2) now) is only known once the point has opened. Without it the ledger misses
// C v^2 dt / 2 an opening: for a no-tension point the dashpot force at its last step is the
// spring's K x with x below one step's travel, (w dt)^2 of the impact's energy; for a
// zero-overlap point it is the full C v of the rebound, 2 h w dt e^2 of the impact's energy,
// percents an impact at a usual dt.
ContactEnergy opened_points_work(const World& w, const PairContact& pair, const OpenedPoints& opened) {
    ContactEnergy energy;
    const Bodies& b = w.bodies;
    const Vec2 n{opened.normal_x, opened.normal_y};
    const Vec2 t = perp(n);
    for (std::uint32_t k = 0; k < opened.count; ++k) {
        const OpenedPoint& point = opened.points[k];
        const Vec2 ra = Vec2{point.x_m, point.y_m} - b.position_m[pair.a];
        const Vec2 rb = Vec2{point.x_m, point.y_m} - b.position_m[pair.b];
        const Vec2 relative = (b.velocity_m_s[pair.b] + cross(b.angular_velocity_rad_s[pair.b], rb)) -
                              (b.velocity_m_s[pair.a] + cross(b.angular_velocity_rad_s[pair.a], ra));
        energy.normal_dashpot_j -= 0.5 * point.normal_dashpot_n * dot(relative, n) * w.dt_s;
        energy.shear_dashpot_j -= 0.5 * point.shear_dashpot_n * dot(relative, t) * w.dt_s;
    }
    return energy;
}

}  // namespace

JointPoint joint_point_of(const Bodies& b, const PairContact& pair, const ContactParameters& p, double rounding_m,
                          std::uint32_t points) {
    return end_joint_point(b, pair, p, rounding_m, points);
}

void index_pairs_by_body(World& w) {
    const std::size_t n = w.bodies.size();
    w.body_pair_start.assign(n + 1, 0);
    for (const PairContact& pair : w.contacts) {
        ++w.body_pair_start[pair.a + 1];
        ++w.body_pair_start[pair.b + 1];
    }
    for (std::size_t i = 0; i < n; ++i) w.body_pair_start[i + 1] += w.body_pair_start[i];
    w.body_pair_entries.resize(w.body_pair_start[n]);
    // Filled in table order, so every body's list is in table order too.
    w.contacts_fill.assign(w.body_pair_start.begin(), w.body_pair_start.end() - 1);
    for (std::uint32_t p = 0; p < w.contacts.size(); ++p) {
        w.body_pair_entries[w.contacts_fill[w.contacts[p].a]++] = 2 * p;
        w.body_pair_entries[w.contacts_fill[w.contacts[p].b]++] = 2 * p + 1;
    }
    w.pair_forces.resize(w.contacts.size());
}

void prepare_pair_forces(World& w) {
    if (w.pair_forces.size() != w.contacts.size() || w.body_pair_start.size() != w.bodies.size() + 1)
        index_pairs_by_body(w);
}

void count_body_pair_points(World& w) {
    const std::size_t pairs = w.contacts.size();
    w.body_pair_points.resize(pairs);
    if (w.points_by_body.size() != w.bodies.size()) w.points_by_body.assign(w.bodies.size(), 0);
    // The table is sorted by part a, and a body's parts have consecutive ids, so each body's
    // entries as body a are one run. Per run: sum the points per body b, read the sums back,
    // clear them. One linear pass (a pairwise search within a run read the table entries again
    // and again: a third slower step on the keyed wall).
    for (std::size_t first = 0; first < pairs;) {
        std::size_t last = first;
        while (last < pairs && w.contacts[last].a == w.contacts[first].a) ++last;
        for (std::size_t p = first; p < last; ++p) w.points_by_body[w.contacts[p].b] += w.contacts[p].count;
        for (std::size_t p = first; p < last; ++p) w.body_pair_points[p] = w.points_by_body[w.contacts[p].b];
        for (std::size_t p = first; p < last; ++p) w.points_by_body[w.contacts[p].b] = 0;
        first = last;
    }
}

namespace {

// apply_pair_law's body, inline: the contact pass below runs it after the narrow phase in one
// body of code per pair.
[[gnu::always_inline]] inline ContactEnergy pair_law_and_openings(World& w, std::size_t p, std::uint32_t mass_sharing_points,
                                                                  const OpenedPoints& opened) {
    PairContact& pair = w.contacts[p];
    SubContacts* sub = p < w.sub_contacts.size() ? &w.sub_contacts[p] : nullptr;
    ContactEnergy energy = pair_law(pair, w.bodies, w.contact, sub, w.dt_s, mass_sharing_points, w.pair_forces[p]);
    // Interior points exist only while the pair has its two ends (contact/sub_contacts.hpp).
    if (sub != nullptr && sub->count > 0 && pair.count != 2) [[unlikely]]
        energy += dropped_sub_points_work(w.bodies, pair, sub->normal, drop_sub_points(*sub), w.dt_s);
    if (opened.count > 0) energy += opened_points_work(w, pair, opened);
    energy.deepest_pair = static_cast<std::uint32_t>(p);
    return energy;
}

// apply_joint_pair_law's body, inline for the contact pass as pair_law_and_openings.
[[gnu::always_inline]] inline ContactEnergy joint_pair_law_and_openings(World& w, std::size_t p,
                                                                        std::uint32_t mass_sharing_points,
                                                                        const OpenedPoints& opened) {
    PairContact& pair = w.contacts[p];
    // (Empty first: the size is a division by the entry's size, at every pair of every step.)
    SubContacts* sub = !w.sub_contacts.empty() && p < w.sub_contacts.size() ? &w.sub_contacts[p] : nullptr;
    PairForces& out = w.pair_forces[p];
    out.count = pair.count;
    ContactEnergy energy;
    if (pair.count > 0) {
        const ContactParameters& stored = w.contact.at(w.bodies.material[pair.a], w.bodies.material[pair.b]);
        // (No interior points: joint_pair_law's own count of points is the pair's.)
        const bool ends_only = sub == nullptr || pair.count != 2 || w.contact.sub_contacts == 2;
        if (ends_only && stored.tan_dilation == 0.0) [[likely]]
            joint_ends_law(pair, w.bodies, stored, w.contact.rounding_m, w.dt_s, mass_sharing_points, out, energy);
        else
            energy = joint_pair_law(pair, w.bodies, stored, w.contact.rounding_m, w.contact.sub_contacts, sub, w.dt_s,
                                    mass_sharing_points, out);
    }
    // (The rest as apply_pair_law.)
    if (sub != nullptr && sub->count > 0 && pair.count != 2) [[unlikely]]
        energy += dropped_sub_points_work(w.bodies, pair, sub->normal, drop_sub_points(*sub), w.dt_s);
    if (opened.count > 0) energy += opened_points_work(w, pair, opened);
    energy.deepest_pair = static_cast<std::uint32_t>(p);
    return energy;
}

// One pair of a world of convex bodies: its narrow phase, then its law (the joint law's own path
// with joints_only), its own points sharing its reduced mass. Not flattened: the joint law's
// rarely taken paths (sub-contacts, dilation, openings), inlined too, crowded the registers and
// took back nearly all of what the fusion saved (docs/performance.md).
template <bool joints_only>
[[gnu::always_inline]] inline ContactEnergy convex_pair_step(World& w, std::size_t p) {
    const OpenedPoints opened = narrow_phase_detail::pair_contact<joints_only>(w, p);
    if constexpr (joints_only)
        return joint_pair_law_and_openings(w, p, w.contacts[p].count, opened);
    else
        return pair_law_and_openings(w, p, w.contacts[p].count, opened);
}

}  // namespace

ContactEnergy apply_pair_law(World& w, std::size_t p, std::uint32_t mass_sharing_points, const OpenedPoints& opened) {
    return pair_law_and_openings(w, p, mass_sharing_points, opened);
}

bool every_pair_per_length(const MaterialPairs& contact) {
    for (const ContactParameters& params : contact.parameters)
        if (params.stiffness != StiffnessBasis::per_length) return false;
    return !contact.parameters.empty();
}

// apply_pair_law with pair_law's per-length branch taken, in one body of code (flattened).
[[gnu::flatten]] ContactEnergy apply_joint_pair_law(World& w, std::size_t p, std::uint32_t mass_sharing_points,
                                                    const OpenedPoints& opened) {
    return joint_pair_law_and_openings(w, p, mass_sharing_points, opened);
}

// (Each pair's body inlined in the chunk sum itself: a call per pair from the sum, with its
// ContactEnergy returned through memory, cost the rounded per-length wall 2.6 % of its step.)
ContactEnergy update_convex_contacts_and_forces(World& w) {
    const auto pairs = static_cast<std::ptrdiff_t>(w.contacts.size());
    if (every_pair_per_length(w.contact))
        return deterministic_sum(pairs, [&](std::ptrdiff_t p) __attribute__((always_inline)) {
            return convex_pair_step<true>(w, static_cast<std::size_t>(p));
        });
    return deterministic_sum(pairs, [&](std::ptrdiff_t p) __attribute__((always_inline)) {
        return convex_pair_step<false>(w, static_cast<std::size_t>(p));
    });
}

// Body i's force and torque: gravity, then its pair slots in table order (parallel.hpp, rule 2).
void sum_body_force(World& w, std::size_t i) {
    Bodies& b = w.bodies;
    // Summed in locals (the slots could alias the body arrays as far as the compiler knows).
    const double gravity_share = b.kind[i] == BodyKind::dynamic ? 1.0 : 0.0;
    Vec2 force_n{w.gravity_now_m_s2.x * b.mass_kg[i] * gravity_share, w.gravity_now_m_s2.y * b.mass_kg[i] * gravity_share};
    double torque_n_m = 0.0;
    for (std::uint32_t e = w.body_pair_start[i]; e < w.body_pair_start[i + 1]; ++e) {
        const std::uint32_t p = w.body_pair_entries[e] >> 1;
        const bool is_b = (w.body_pair_entries[e] & 1u) != 0;
        const PairForces& f = w.pair_forces[p];
        for (std::uint32_t k = 0; k < f.count; ++k) {
            if (is_b) {
                force_n += f.on_b_n[k];
                torque_n_m += f.torque_on_b_n_m[k];
            } else {
                force_n -= f.on_b_n[k];
                torque_n_m -= f.torque_on_a_n_m[k];
            }
        }
    }
    b.force_n[i] = force_n;
    b.torque_n_m[i] = torque_n_m;
}

double contact_elastic_energy(const World& w) {
    return deterministic_sum(static_cast<std::ptrdiff_t>(w.contacts.size()), [&](std::ptrdiff_t p) {
        const PairContact& pair = w.contacts[p];
        if (pair.count == 0) return 0.0;
        const ContactParameters& stored = w.contact.at(w.bodies.material[pair.a], w.bodies.material[pair.b]);
        double energy = 0.0;
        if (stored.stiffness == StiffnessBasis::per_length) {
            const SubContacts* sub = static_cast<std::size_t>(p) < w.sub_contacts.size() && pair.count == 2
                                         ? &w.sub_contacts[p] : nullptr;
            const std::uint32_t interior = sub != nullptr ? sub->count : 0;
            const JointPoint joint = joint_point_of(w.bodies, pair, stored, w.contact.rounding_m, pair.count + interior);
            for (std::uint32_t k = 0; k < pair.count; ++k)
                energy += joint_elastic_energy(joint, pair.points[k].overlap_m, pair.points[k].shear_spring_n,
                                               pair.points[k].bond, pair.points[k].dilation_m);
            const JointPoint inner{2.0 * joint.kn_N_m, 2.0 * joint.ks_N_m, 2.0 * joint.area_m2};
            for (std::uint32_t k = 0; k < interior; ++k)
                energy += joint_elastic_energy(inner, sub->points[k].overlap_m, sub->points[k].shear_spring_n,
                                               sub->points[k].bond, sub->points[k].dilation_m);
            return energy;
        }
        const ContactParameters params = softened(stored, pair.stiffness_scale);
        for (std::uint32_t k = 0; k < pair.count; ++k)
            energy += contact_elastic_energy(params, pair.points[k].overlap_m, pair.points[k].shear_spring_n);
        return energy;
    });
}

}  // namespace blockdem
