#pragma once
// The 2-D run's stop on an energy balance gone wrong (world/step.cpp), for the 3-D world: a run
// whose ledger no longer closes is unstable or mis-set, and its results mean nothing.
#include "world/world_3d.hpp"

namespace blockdem {

/// Throws SimulationError naming the error, the time, the fastest body, dt and the live stable
/// bound when the balance error exceeds max_error (after the first 10 steps, whose terms are
/// all near zero).
void check_energy_balance_3d(const World3d& w, double max_error, double start_bound_s);

}  // namespace blockdem
