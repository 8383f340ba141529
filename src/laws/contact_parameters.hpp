#pragma once
// Parameters of the linear spring-dashpot-slider contact (Cundall 1971) for one pair of
// materials, after calibration: what the time step uses.
#include <cstdint>

namespace blockdem {

/// When a contact point stops pushing (docs/physics.md, "When a contact ends").
enum class ContactTermination : std::uint8_t {
    /// The normal force never pulls: F_n = max(0, K_n d - C_n v_n). The point separates in effect
    /// when the force reaches zero, before the overlap does (today's rule, the default).
    no_tension,
    /// Ohmachi and Arai's rule: the point acts until the overlap returns to zero, and while the
    /// dashpot acts the force may pull (F_n < 0). A head-on impact then rebounds with exactly the
    /// e of the paper's h_n formula.
    zero_overlap,
};

/// What kn and ks are given per (docs/physics.md, "Joint stiffness per unit length").
enum class StiffnessBasis : std::uint8_t {
    /// kn, ks [N/m] of one contact point (today's rule, the default).
    per_point,
    /// kn, ks [Pa/m] per unit area of joint (UDEC's JKN, JKS): a point carries its tributary
    /// length of the contact times the out-of-plane thickness (laws/mohr_coulomb_joint.hpp).
    per_length,
};

struct ContactParameters {
    double kn_N_m = 0.0;  ///< [N/m] normal stiffness of one contact point (per_point)
    double ks_N_m = 0.0;  ///< [N/m] shear stiffness of one contact point (per_point)
    double mu = 0.0;      ///< [-] Coulomb friction coefficient
    double h_n = 0.0;     ///< [-] normal damping ratio
    double h_s = 0.0;     ///< [-] shear damping ratio
    ContactTermination termination = ContactTermination::no_tension;
    StiffnessBasis stiffness = StiffnessBasis::per_point;
    // The joint (per_length only; laws/mohr_coulomb_joint.hpp). Cohesion and tension act only
    // at bonded points, and only until the bond breaks.
    double kn_pa_m = 0.0;              ///< [Pa/m] normal stiffness per unit area of joint (JKN)
    double ks_pa_m = 0.0;              ///< [Pa/m] shear stiffness per unit area of joint (JKS)
    double cohesion_pa = 0.0;          ///< [Pa] c of an intact bond
    double tensile_strength_pa = 0.0;  ///< [Pa] sigma_t of an intact bond
    double residual_mu = -1.0;         ///< [-] friction after the bond broke; < 0: mu
    double tan_dilation = 0.0;         ///< [-] tan(psi): a sliding dry joint point opens by this per unit of slip
    double dilation_zero_slip_m = 0.0;  ///< [m] dilatant slip after which a point stops dilating (its u_d <= tan(psi) x this); 0: none
};

/// The friction of a point whose bond broke: residual_mu, or mu when none was given.
inline double residual_friction(const ContactParameters& p) { return p.residual_mu >= 0.0 ? p.residual_mu : p.mu; }

/// The scenario's name of a stiffness basis ("per_point", "per_length").
inline const char* to_string(StiffnessBasis s) { return s == StiffnessBasis::per_length ? "per_length" : "per_point"; }

/// The scenario's name of a termination rule ("no_tension", "zero_overlap").
inline const char* to_string(ContactTermination t) {
    return t == ContactTermination::zero_overlap ? "zero_overlap" : "no_tension";
}

}  // namespace blockdem
