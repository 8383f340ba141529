#pragma once
// Calibration of the normal damping ratio h_n from a coefficient of restitution e, in the two
// meanings a user may intend (docs/physics.md, "Damping"):
//
// * paper: Ohmachi and Arai's formula h_n = -ln e / sqrt(pi^2 + ln^2 e). It equates the energy
//   lost by a linear spring-dashpot over the half period that ends when the overlap returns to
//   zero with (1 - e^2) of the impact energy. A contact without tension separates earlier, when
//   the force (not the overlap) reaches zero, so the rebound it really produces is larger than e.
// * rebound: the h_n for which a no-tension linear spring-dashpot really rebounds with e
//   (Schwager and Poeschel 2007, Granular Matter 9:465, eqs. for the linear dashpot model with
//   the force criterion for separation). Asking for e = 0.4 then gives a measured rebound of 0.4.
//
// With termination = zero_overlap (the paper's own rule: the contact lasts until the overlap is
// zero, pulling while the dashpot acts) the paper's formula is the exact rebound, so there the
// two meanings give the same h_n.

#include "laws/contact_parameters.hpp"

namespace blockdem {

enum class RestitutionMeaning { paper, rebound };

/// The paper's damping ratio for restitution e (0 < e <= 1).
double damping_ratio_paper(double e);
/// The paper's inverse: the restitution e = exp(-pi h / sqrt(1 - h^2)), 0 <= h < 1.
double restitution_paper(double h_n);

/// The rebound ratio a no-tension linear spring-dashpot produces with damping ratio h_n >= 0.
double restitution_no_tension(double h_n);
/// The damping ratio for which a no-tension contact rebounds with e (0 < e <= 1), by bisection.
double damping_ratio_rebound(double e);

/// The damping ratio for e in the chosen meaning (for a no-tension contact).
double damping_ratio_for(double e, RestitutionMeaning meaning);
/// The damping ratio for e in the chosen meaning, for a contact that ends by the given rule.
double damping_ratio_for(double e, RestitutionMeaning meaning, ContactTermination termination);

/// The rebound ratio of a head-on impact on a linear spring-dashpot with damping ratio h_n >= 0
/// that ends by the given rule: restitution_no_tension(h_n), or for zero_overlap the paper's
/// exp(-pi h / sqrt(1 - h^2)) (0 for h_n >= 1: an overdamped overlap never returns to zero, it
/// creeps back with a speed that tends to zero).
double restitution_of(double h_n, ContactTermination termination);

}  // namespace blockdem
