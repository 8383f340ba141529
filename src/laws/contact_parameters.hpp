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

struct ContactParameters {
    double kn_N_m = 0.0;  ///< [N/m] normal stiffness of one contact point
    double ks_N_m = 0.0;  ///< [N/m] shear stiffness of one contact point
    double mu = 0.0;      ///< [-] Coulomb friction coefficient
    double h_n = 0.0;     ///< [-] normal damping ratio
    double h_s = 0.0;     ///< [-] shear damping ratio
    ContactTermination termination = ContactTermination::no_tension;
};

/// The scenario's name of a termination rule ("no_tension", "zero_overlap").
inline const char* to_string(ContactTermination t) {
    return t == ContactTermination::zero_overlap ? "zero_overlap" : "no_tension";
}

}  // namespace blockdem
