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
DashpotCoefficients dashpot_coefficients(const ContactParameters& p, double mass_kg);

/// Advances one contact point by dt: previous_shear_spring_n is last step's shear history
/// (0 for a new contact). Returns the forces on b and this step's dissipation.
ContactForce linear_spring_dashpot(const ContactParameters& p, const DashpotCoefficients& c,
                                   const ContactKinematics& k, double previous_shear_spring_n, double dt_s);

/// Elastic energy stored in one contact point's springs [J].
double contact_elastic_energy(const ContactParameters& p, double overlap_m, double shear_spring_n);

}  // namespace blockdem
