#pragma once
// The 2-D run's stops (world/step.cpp) for the 3-D world, checked after every step: a ledger
// that no longer closes (unstable or mis-set: the results mean nothing) and bodies sinking into
// each other (a contact too soft for its load: the rigid-block model no longer holds).
#include <vector>

#include "world/world_3d.hpp"

namespace blockdem {

/// Throws SimulationError naming the error, the time, the fastest body, dt and the live stable
/// bound when the balance error exceeds max_error (after the first 10 steps, whose terms are
/// all near zero).
void check_energy_balance_3d(const World3d& w, double max_error, double start_bound_s);

/// [m] each body's least width: the least extent over its face normals (exact for boxes and
/// prisms; an upper bound otherwise).
std::vector<double> least_widths_m(const World3d& w);

/// Throws SimulationError naming the two bodies when a point's overlap exceeds max_ratio times
/// the least width of the thinner body of its pair, with the kn that would bring it near 1%.
void check_overlap_3d(const World3d& w, const std::vector<double>& least_widths_m, double max_ratio);

}  // namespace blockdem
