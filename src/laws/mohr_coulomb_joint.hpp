#pragma once
// The Mohr-Coulomb joint of masonry and rock (as UDEC's joint model with residual strength),
// for one contact point whose stiffness is given per unit area of joint (stiffness =
// "per_length"):
//   stiffness: kn = JKN L t, ks = JKS L t [N/m], with L the point's tributary length of the
//            contact [m] and t the out-of-plane thickness of the thinner body [m]; the point
//            stands for the area A = L t of joint;
//   bonded point (a joint bonded at the start: mortar, an intact rock bridge): the normal
//            spring also pulls, F_n = kn overlap - C_n v_n with overlap < 0 in tension, until
//            F_n < -sigma_t A (tensile failure); the shear spring holds up to
//            c A + mu F_n (shear failure beyond). The step on which either strength is
//            exceeded, the bond breaks for good: cohesion and tension fall to zero and
//            the point continues as a dry one with the residual friction;
//   dry point (never bonded, or broken): the linear spring-dashpot-slider of
//            laws/linear_spring_dashpot.hpp with no tension, friction mu (residual_mu once
//            broken);
//   dilation (as UDEC's joint dilation angle psi; dry points only): the point carries its
//            accumulated dilation u_d [m], and its normal spring and dashpot act on overlap + u_d.
//            A step on which the slider slips by du_p (the part of this step's shear
//            displacement that the spring does not take) adds tan(psi) du_p to u_d, and this
//            step's normal force already includes it: u_d, the normal force and the friction cap
//            are solved together (closed form: the cap rises with the slip), so the point ends
//            on its Coulomb cap. In steady sliding du_p is the whole shear increment, UDEC's
//            |du_s|. With dilation_zero_slip z, u_d stops at tan(psi) z. A confined joint's
//            normal force rises by kn du_d; a free one opens.
// Energy: a breaking bond releases what its springs stored beyond what the dry point keeps;
// that step's whole release (normal spring in tension, shear spring down to the residual cap)
// is booked as bond_breakage_j, so the ledger stays closed. A dilating step moves
// (F_n,last + F_n) du_d / 2 (the normal force's trapezoid over the dilation) from the slip's
// friction work into the normal spring and dashpot: the normal element then takes from the
// bodies what it stores and damps on overlap + u_d, and the ledger closes per step
// (docs/physics.md, "Dilation").
// Signs as in linear_spring_dashpot.hpp: n from a to b, t = n turned counter-clockwise, forces on b.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/vec2.hpp"

#include "laws/contact_parameters.hpp"
#include "laws/linear_spring_dashpot.hpp"

namespace blockdem {

/// A contact point's bond.
enum class BondState : std::uint8_t {
    none,             ///< never bonded: a dry joint
    intact,           ///< bonded: carries cohesion and tension
    broken_tension,   ///< the bond failed in tension: dry, residual friction
    broken_shear,     ///< the bond failed in shear: dry, residual friction
};

/// True for either broken state.
inline bool is_broken(BondState s) { return s == BondState::broken_tension || s == BondState::broken_shear; }

/// A one-point (corner-to-edge) contact stands for this fraction of the least width of the
/// thinner body of its pair (docs/physics.md, "Joint stiffness per unit length").
inline constexpr double corner_length_fraction = 0.1;

/// An edge-to-edge contact of a per-length joint keeps its open end, carrying nothing, while
/// that end is apart by less than this fraction of the thinner body's least width
/// (contact/narrow_phase.cpp, joint_face_gap_m), so that its points' stiffness does not flicker.
inline constexpr double joint_face_keep_fraction = 1e-3;

/// The stiffness of one point of a per-length joint, and the joint area it stands for.
struct JointPoint {
    double kn_N_m = 0.0;   ///< [N/m] JKN L t
    double ks_N_m = 0.0;   ///< [N/m] JKS L t
    double area_m2 = 0.0;  ///< [m^2] L t
};

/// JKN L t, JKS L t and L t for a tributary length L [m] and thickness t [m].
inline JointPoint joint_point(const ContactParameters& p, double tributary_length_m, double thickness_m);

/// The tributary length of each point of a contact [m]: half the distance between the two
/// points of an edge-to-edge contact each; for a one-point contact, the larger of the rounding
/// radius rounding_m [m] (an arc pressed on a face: docs/physics.md) and corner_length_fraction
/// times least_width_m.
inline double tributary_length_m(std::uint32_t points, Vec2 first_m, Vec2 second_m, double least_width_m,
                          double rounding_m = 0.0);

/// This step's forces and dissipation at one point, and its bond state after the step.
struct JointForce {
    ContactForce force;
    BondState bond = BondState::none;
    double bond_breakage_j = 0.0;  ///< [J] released by a bond that broke this step
    double dilation_m = 0.0;       ///< [m] the point's accumulated dilation u_d after the step
};

/// What a dilating point carries from the last step besides ContactHistory.
struct DilationHistory {
    double dilation_m = 0.0;      ///< [m] accumulated dilation u_d before the step
    double normal_force_n = 0.0;  ///< [N] last step's normal force (spring and dashpot), for the dilation's work
};

/// Advances one point of a per-length joint by dt (laws as in the header comment). p: the
/// pair's parameters (friction, strengths); point: its stiffness and area; bond: its state
/// before the step; dilation: u_d and last step's normal force (read only where p.tan_dilation > 0).
inline JointForce mohr_coulomb_joint(const ContactParameters& p, const JointPoint& point, const DashpotCoefficients& c,
                              const ContactKinematics& k, const ContactHistory& previous, BondState bond, double dt_s,
                              const DilationHistory& dilation = {});

/// Elastic energy stored in one joint point's springs [J]: the normal spring (on overlap +
/// dilation_m) only in compression unless the bond is intact.
inline double joint_elastic_energy(const JointPoint& point, double overlap_m, double shear_spring_n, BondState bond,
                            double dilation_m = 0.0);

/// The opening [m] at which an intact bond's spring alone reaches the tensile strength,
/// sigma_t / JKN (the narrow phase keeps bonded points open by up to twice that).
inline double bond_opening_m(const ContactParameters& p);

// Definitions. Inline: the per-point loop of a joint (contact/contact_forces.cpp) inlines them
// as it does the dry law (a header); a call per point cost a bonded wall a third of its step
// (docs/performance.md, "Joints").


inline JointPoint joint_point(const ContactParameters& p, double tributary_length_m, double thickness_m) {
    const double area_m2 = tributary_length_m * thickness_m;
    return {p.kn_pa_m * area_m2, p.ks_pa_m * area_m2, area_m2};
}

inline double tributary_length_m(std::uint32_t points, Vec2 first_m, Vec2 second_m, double least_width_m, double rounding_m) {
    if (points == 2) return 0.5 * length(second_m - first_m);
    // (std::max: the sharp rule's length for a rounding below it: docs/physics.md.)
    return std::max(rounding_m, corner_length_fraction * least_width_m);
}

namespace joint_detail {

// The dry point: no tension, the given friction (linear_spring_dashpot.hpp with the point's
// own stiffness; the spring pushes only while the overlap lasts).
inline ContactForce dry_point(const ContactParameters& p, double friction, const JointPoint& point, const DashpotCoefficients& c,
                       const ContactKinematics& k, const ContactHistory& previous, double dt_s) {
    ContactParameters dry = p;
    dry.kn_N_m = point.kn_N_m;
    dry.ks_N_m = point.ks_N_m;
    dry.mu = friction;
    ContactKinematics closed = k;
    closed.overlap_m = std::max(0.0, k.overlap_m);
    return linear_spring_dashpot(dry, c, closed, previous, dt_s);
}

// The dry point with dilation (header comment). Its trial is the point on s = overlap + u_d
// with no new dilation, spring and dashpot linear (no clamp: the trial is no state). If last
// step's spring force plus this step's increment is past the trial's cap by excess_n, the
// slider slips by du_p and the point dilates by tan(psi) du_p, which raises the normal force by
// (kn + C_n / dt) tan(psi) du_p (spring and dashpot both act on s) and the cap by friction
// times that; the spring ends on the cap when
//   excess_n - ks du_p = friction (kn + C_n / dt) tan(psi) du_p,
// which gives du_p: the slip of the faces less what the spring takes up, as in an elastic-
// plastic return to the cap. Why the trial is linear and counts from last step's force: in
// steady sliding a free joint's faces open in a step by what the point dilated in the last
// one, so the trial's s falls by about that (and below zero once the step's dilation passes
// the joint's elastic closure), and its dashpot sees that opening rate; the step's dilation
// restores both. Clamping the trial, or relaxing the spring to the trial's cap first, counts
// that dip as no slip: the point then stopped dilating, or dilated by only
// ks / (ks + friction kn tan(psi)) of tan(psi) times its slip. The forces are then the dry
// point's on the dilated s, with the dashpot on ds/dt: a free joint opening by its own dilation
// is no impact (on the geometric rate, the dashpot held a sliding block down by
// C_n tan(psi) v_s). A point that does not dilate is the dry point on s; one open (s <= 0), which
// the narrow phase keeps while it may close again by dilating, carries nothing, its dashpot
// included.
inline JointForce dilating_dry_point(const ContactParameters& p, double friction, const JointPoint& point,
                              const DashpotCoefficients& c, const ContactKinematics& k, const ContactHistory& previous,
                              double dt_s, const DilationHistory& h) {
    JointForce out;
    out.dilation_m = h.dilation_m;
    ContactKinematics dilated = k;
    dilated.overlap_m = k.overlap_m + h.dilation_m;
    const double linear_normal_n = point.kn_N_m * dilated.overlap_m - c.cn_N_s_m * k.normal_speed_m_s;
    const double trial_n = previous.shear_spring_n - point.ks_N_m * k.tangential_speed_m_s * dt_s;
    const double excess_n = std::abs(trial_n) - friction * linear_normal_n;
    if (excess_n > 0.0) {
        const double stiffening_n_m = point.kn_N_m + c.cn_N_s_m / dt_s;
        const double slip_m = excess_n / (point.ks_N_m + friction * p.tan_dilation * stiffening_n_m);
        double increment_m = p.tan_dilation * slip_m;
        if (p.dilation_zero_slip_m > 0.0)
            increment_m = std::min(increment_m, std::max(0.0, p.tan_dilation * p.dilation_zero_slip_m - h.dilation_m));
        // (Dilating, the point must end closed and pushing; else it does not dilate.)
        if (increment_m > 0.0 && dilated.overlap_m + increment_m > 0.0 &&
            linear_normal_n + stiffening_n_m * increment_m > 0.0) {
            dilated.overlap_m += increment_m;
            dilated.normal_speed_m_s -= increment_m / dt_s;
            out.force = dry_point(p, friction, point, c, dilated, previous, dt_s);
            out.dilation_m = h.dilation_m + increment_m;
            // The normal element took (F_n,last + F_n) du_d / 2 more than the bodies' normal
            // motion gave it: that work came from the slip (docs/physics.md, "Dilation").
            out.force.friction_work_j -= 0.5 * (h.normal_force_n + out.force.normal_n) * increment_m;
            return out;
        }
    }
    out.force = dry_point(p, friction, point, dilated.overlap_m > 0.0 ? c : DashpotCoefficients{}, dilated, previous, dt_s);
    return out;
}

}  // namespace joint_detail

inline JointForce mohr_coulomb_joint(const ContactParameters& p, const JointPoint& point, const DashpotCoefficients& c,
                              const ContactKinematics& k, const ContactHistory& previous, BondState bond, double dt_s,
                              const DilationHistory& dilation) {
    JointForce out;
    out.bond = bond;
    if (bond != BondState::intact) {
        const double friction = bond == BondState::none ? p.mu : residual_friction(p);
        if (p.tan_dilation > 0.0) [[unlikely]] {
            out = joint_detail::dilating_dry_point(p, friction, point, c, k, previous, dt_s, dilation);
            out.bond = bond;
            return out;
        }
        out.force = joint_detail::dry_point(p, friction, point, c, k, previous, dt_s);
        return out;
    }
    ContactForce& f = out.force;
    const double spring_n = point.kn_N_m * k.overlap_m;
    f.normal_n = spring_n - c.cn_N_s_m * k.normal_speed_m_s;  // a bond pulls
    f.normal_dashpot_n = f.normal_n - spring_n;
    f.normal_dashpot_work_j = -0.5 * (previous.normal_dashpot_n + f.normal_dashpot_n) * k.normal_speed_m_s * dt_s;
    const bool tension_failure = f.normal_n < -p.tensile_strength_pa * point.area_m2;
    if (!tension_failure) {
        const double strength_n = std::max(0.0, p.cohesion_pa * point.area_m2 + p.mu * f.normal_n);
        coulomb_slider(point.ks_N_m, c.cs_N_s_m, strength_n, k.tangential_speed_m_s, previous, dt_s, f);
        if (!f.sliding) return out;  // the bond holds
    }
    // The bond breaks: this step the point is already the dry one with the residual friction.
    // Released: the normal spring's tension energy (the dry point keeps none) and all that the
    // dry slider dissipates this step (the shear spring dropping from last step's force to the
    // residual cap); booked once, as breakage, not as friction.
    out.bond = tension_failure ? BondState::broken_tension : BondState::broken_shear;
    const ContactForce dry = joint_detail::dry_point(p, residual_friction(p), point, c, k, previous, dt_s);
    const double closed_m = std::max(0.0, k.overlap_m);
    const double normal_release_j = 0.5 * point.kn_N_m * (k.overlap_m * k.overlap_m - closed_m * closed_m);
    out.bond_breakage_j = normal_release_j + dry.friction_work_j;
    f = dry;
    f.friction_work_j = 0.0;
    return out;
}

inline double joint_elastic_energy(const JointPoint& point, double overlap_m, double shear_spring_n, BondState bond,
                            double dilation_m) {
    const double normal_m = bond == BondState::intact ? overlap_m : std::max(0.0, overlap_m + dilation_m);
    const double shear_j = point.ks_N_m > 0.0 ? 0.5 * shear_spring_n * shear_spring_n / point.ks_N_m : 0.0;
    return 0.5 * point.kn_N_m * normal_m * normal_m + shear_j;
}

inline double bond_opening_m(const ContactParameters& p) {
    return p.kn_pa_m > 0.0 ? p.tensile_strength_pa / p.kn_pa_m : 0.0;
}

}  // namespace blockdem
