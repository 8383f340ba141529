#pragma once
// The contact law of the source paper (Ohmachi and Arai, after Cundall 1971), for one contact
// point:
//   normal:  F_n = kn * overlap + C_n * (approach speed), and F_n >= 0 (no tension, the
//            default); with termination = zero_overlap (the paper's own rule) F_n may pull while
//            the dashpot acts, and the point ends when its overlap returns to zero (the narrow
//            phase drops it then);
//   shear:   the spring force is built incrementally, F_s,spring -= ks * (tangential slip
//            increment), carried across steps in the contact frame; the dashpot adds
//            -C_s * (tangential speed) while the contact sticks; |F_s| <= mu * F_n (Coulomb
//            slider), and while the spring force is at that cap the contact slides, the
//            dashpot is off and the excess spring displacement is dissipated by friction.
//            A pulling contact (F_n < 0) carries no shear: the cap is mu * max(0, F_n).
//   damping: C = 2 h sqrt(M k), with M the mass the pair shares among its contact points
//            (docs/physics.md, "Which mass the damping uses").
// Signs: n points from body a to body b; t is n turned counter-clockwise; forces are those on b.
// Defined here, inline: the law runs for every contact point at every step.
#include <algorithm>
#include <cmath>

#include "laws/contact_parameters.hpp"

namespace blockdem {

/// Kinematics of one contact point at this step.
struct ContactKinematics {
    double overlap_m = 0.0;           ///< [m] > 0 in compression
    double normal_speed_m_s = 0.0;    ///< [m/s] (v_b - v_a) . n at the point: > 0 when separating
    double tangential_speed_m_s = 0.0;///< [m/s] (v_b - v_a) . t at the point
};

/// What a contact point carries from one step to the next (all zero for a new contact).
struct ContactHistory {
    double shear_spring_n = 0.0;    ///< [N] shear spring force on b along t
    double normal_dashpot_n = 0.0;  ///< [N] last step's normal dashpot force on b along n
    double shear_dashpot_n = 0.0;   ///< [N] last step's shear dashpot force on b along t
};

/// This step's forces, the history to carry, and this step's dissipation.
struct ContactForce {
    double normal_n = 0.0;          ///< [N] on b along n (>= 0 unless termination = zero_overlap)
    double shear_spring_n = 0.0;    ///< [N] shear spring force on b along t: the history
    double shear_n = 0.0;           ///< [N] total shear force on b along t
    double normal_dashpot_n = 0.0;  ///< [N] the normal dashpot's part of normal_n
    double shear_dashpot_n = 0.0;   ///< [N] the shear dashpot's part of shear_n
    bool sliding = false;
    // Energy dissipated over the interval from the last step to this one [J], for the ledger.
    double normal_dashpot_work_j = 0.0;  ///< [J] dissipated by the normal dashpot
    double shear_dashpot_work_j = 0.0;   ///< [J] dissipated by the shear dashpot
    double friction_work_j = 0.0;        ///< [J] dissipated by sliding
};

/// Damping coefficients of one contact point [N s/m].
struct DashpotCoefficients {
    double cn_N_s_m = 0.0;  ///< [N s/m]
    double cs_N_s_m = 0.0;  ///< [N s/m]
};

/// C = 2 h sqrt(M k) for the normal and the shear dashpot; mass_kg is the point's share M.
inline DashpotCoefficients dashpot_coefficients(const ContactParameters& p, double mass_kg) {
    return {2.0 * p.h_n * std::sqrt(mass_kg * p.kn_N_m), 2.0 * p.h_s * std::sqrt(mass_kg * p.ks_N_m)};
}

/// The history a point carries to the next step.
inline ContactHistory history_of(const ContactForce& f) {
    return {f.shear_spring_n, f.normal_dashpot_n, f.shear_dashpot_n};
}

/// The shear half of the law: the Coulomb slider capped at limit_n [N] and the shear dashpot.
/// Sets f's shear forces, sliding, and the friction and shear dashpot work. (Shared with the
/// joint law, laws/mohr_coulomb_joint.hpp; inlined, so the point law costs what it did.)
[[gnu::always_inline]] inline void coulomb_slider(double ks_N_m, double cs_N_s_m, double limit_n,
                                                  double tangential_speed_m_s, const ContactHistory& previous,
                                                  double dt_s, ContactForce& f) {
    // Coulomb slider: if the cap fell below last step's spring force (the normal force
    // dropped), the spring first relaxes to the cap, then takes this step's slip increment.
    // (A pulling point holds nothing in shear: its spring relaxes to zero, the excess to friction.)
    const double last_n = previous.shear_spring_n;
    const double capped_last_n = std::clamp(last_n, -limit_n, limit_n);
    const double increment_m = tangential_speed_m_s * dt_s;
    const double trial_spring_n = capped_last_n - ks_N_m * increment_m;
    if (std::abs(trial_spring_n) > limit_n || capped_last_n != last_n) {
        f.sliding = true;
        f.shear_spring_n = std::clamp(trial_spring_n, -limit_n, limit_n);
        f.shear_n = f.shear_spring_n;
        // What the spring does not store of its trapezoidal work is lost to friction (>= 0:
        // the force stays on the side of the slip).
        const double work_on_bodies_j = 0.5 * (last_n + f.shear_spring_n) * increment_m;
        const double stored_change_j =
            ks_N_m > 0.0 ? 0.5 * (f.shear_spring_n * f.shear_spring_n - last_n * last_n) / ks_N_m : 0.0;
        f.friction_work_j = -work_on_bodies_j - stored_change_j;
    } else {
        f.shear_spring_n = trial_spring_n;
        const double dashpot_n = -cs_N_s_m * tangential_speed_m_s;
        f.shear_n = std::clamp(trial_spring_n + dashpot_n, -limit_n, limit_n);
        f.shear_dashpot_n = f.shear_n - trial_spring_n;
    }
    f.shear_dashpot_work_j = -0.5 * (previous.shear_dashpot_n + f.shear_dashpot_n) * tangential_speed_m_s * dt_s;
}

/// The normal half of the law: spring and dashpot, no tension unless termination = zero_overlap.
/// Sets f's normal force, its dashpot part and the dashpot's work over the last interval
/// (the trapezoid: see linear_spring_dashpot). The 3-D law takes this half alone, with its own
/// vector slider (laws/coulomb_slider_3d.hpp), so that no scalar shear is worked out for nothing.
[[gnu::always_inline]] inline void normal_spring_dashpot(double kn_N_m, double cn_N_s_m, ContactTermination termination,
                                                         double overlap_m, double normal_speed_m_s,
                                                         double previous_normal_dashpot_n, double dt_s,
                                                         ContactForce& f) {
    const double spring_n = kn_N_m * overlap_m;
    const double spring_and_dashpot_n = spring_n - cn_N_s_m * normal_speed_m_s;
    // No tension: the dashpot may only reduce the compressive force to zero. Zero overlap: the
    // dashpot acts in full while the overlap lasts, as in the paper's derivation of h_n.
    f.normal_n = termination == ContactTermination::zero_overlap ? spring_and_dashpot_n
                                                                 : std::max(0.0, spring_and_dashpot_n);
    f.normal_dashpot_n = f.normal_n - spring_n;
    f.normal_dashpot_work_j = -0.5 * (previous_normal_dashpot_n + f.normal_dashpot_n) * normal_speed_m_s * dt_s;
}

/// Advances one contact point by dt from its history (zero for a new contact). Returns the
/// forces on b and the dissipation over the interval that ends now.
///
/// Why the dissipation takes the mean of last step's force and this one's: the speeds here are
/// those of the interval from the last step to this one (v(t - dt/2)), and over that interval
/// the central-difference scheme moves the bodies under a force that is, to second order, the
/// mean of the forces at its two ends (its energy identity pairs F(t) with (x(t+dt) - x(t-dt)) / 2).
/// A dissipation taken as F(t) v(t - dt/2) dt instead is off by C v a dt^2 / 2 a step, which over
/// an impact adds up to a fraction h w dt of the impact's energy: first order in dt, and an
/// energy balance that drifts with every impact. The same trapezoid makes the shear spring's
/// energy and the friction exact: the spring's energy changes by minus its trapezoidal work.
inline ContactForce linear_spring_dashpot(const ContactParameters& p, const DashpotCoefficients& c,
                                          const ContactKinematics& k, const ContactHistory& previous, double dt_s) {
    ContactForce f;
    normal_spring_dashpot(p.kn_N_m, c.cn_N_s_m, p.termination, k.overlap_m, k.normal_speed_m_s,
                          previous.normal_dashpot_n, dt_s, f);
    coulomb_slider(p.ks_N_m, c.cs_N_s_m, p.mu * std::max(0.0, f.normal_n), k.tangential_speed_m_s, previous, dt_s, f);
    return f;
}

/// Elastic energy stored in one contact point's springs [J].
inline double contact_elastic_energy(const ContactParameters& p, double overlap_m, double shear_spring_n) {
    const double shear_energy = p.ks_N_m > 0.0 ? 0.5 * shear_spring_n * shear_spring_n / p.ks_N_m : 0.0;
    return 0.5 * p.kn_N_m * overlap_m * overlap_m + shear_energy;
}

}  // namespace blockdem
