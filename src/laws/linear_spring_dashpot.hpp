#pragma once
// The contact law of the source paper (Ohmachi and Arai, after Cundall 1971), for one contact
// point:
//   normal:  F_n = kn * overlap + C_n * (approach speed), and F_n >= 0 (no tension);
//   shear:   the spring force is built incrementally, F_s,spring -= ks * (tangential slip
//            increment), carried across steps in the contact frame; the dashpot adds
//            -C_s * (tangential speed) while the contact sticks; |F_s| <= mu * F_n (Coulomb
//            slider), and while the spring force is at that cap the contact slides, the
//            dashpot is off and the excess spring displacement is dissipated by friction.
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

/// The state a contact point carries from step to step, and this step's result.
struct ContactForce {
    double normal_n = 0.0;          ///< [N] on b along n (>= 0)
    double shear_spring_n = 0.0;    ///< [N] shear spring force on b along t: the history
    double shear_n = 0.0;           ///< [N] total shear force on b along t
    bool sliding = false;
    // Energy of this step [J], for the ledger.
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

/// Advances one contact point by dt: previous_shear_spring_n is last step's shear history
/// (0 for a new contact). Returns the forces on b and this step's dissipation.
inline ContactForce linear_spring_dashpot(const ContactParameters& p, const DashpotCoefficients& c,
                                          const ContactKinematics& k, double previous_shear_spring_n, double dt_s) {
    ContactForce f;
    const double spring_n = p.kn_N_m * k.overlap_m;
    // No tension: the dashpot may only reduce the compressive force to zero.
    f.normal_n = std::max(0.0, spring_n - c.cn_N_s_m * k.normal_speed_m_s);
    const double normal_dashpot_n = f.normal_n - spring_n;
    f.normal_dashpot_work_j = -normal_dashpot_n * k.normal_speed_m_s * dt_s;

    // The slider's dissipation has two parts: if the cap fell below last step's spring force
    // (the normal force dropped), the excess spring energy is released at once; then the slip
    // beyond the cap, (|trial| - limit) / ks, happens against the force mu F_n.
    const double limit_n = p.mu * f.normal_n;
    const double previous_n = std::clamp(previous_shear_spring_n, -limit_n, limit_n);
    const double released_j =
        0.5 * (previous_shear_spring_n * previous_shear_spring_n - previous_n * previous_n) / p.ks_N_m;
    const double trial_spring_n = previous_n - p.ks_N_m * k.tangential_speed_m_s * dt_s;
    if (std::abs(trial_spring_n) > limit_n || released_j > 0.0) {
        f.sliding = true;
        f.shear_spring_n = std::clamp(trial_spring_n, -limit_n, limit_n);
        f.shear_n = f.shear_spring_n;
        f.friction_work_j = released_j + limit_n * std::max(0.0, std::abs(trial_spring_n) - limit_n) / p.ks_N_m;
    } else {
        f.shear_spring_n = trial_spring_n;
        const double dashpot_n = -c.cs_N_s_m * k.tangential_speed_m_s;
        f.shear_n = std::clamp(trial_spring_n + dashpot_n, -limit_n, limit_n);
        f.shear_dashpot_work_j = -(f.shear_n - trial_spring_n) * k.tangential_speed_m_s * dt_s;
    }
    return f;
}

/// Elastic energy stored in one contact point's springs [J].
inline double contact_elastic_energy(const ContactParameters& p, double overlap_m, double shear_spring_n) {
    const double shear_energy = p.ks_N_m > 0.0 ? 0.5 * shear_spring_n * shear_spring_n / p.ks_N_m : 0.0;
    return 0.5 * p.kn_N_m * overlap_m * overlap_m + shear_energy;
}

}  // namespace blockdem
