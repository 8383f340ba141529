#pragma once
// The settling stage: a generated assembly (bricks laid exactly touching, blocks cut from a
// rock mass) is not yet in equilibrium: its contacts carry no load. Before the shaking starts it
// is stepped under gravity with the table at rest until it is still, and then the clock is set
// back to zero, keeping the contacts and their shear history.
//
// Criterion: the kinetic energy stays below kinetic_ratio times the assembly's potential energy
// E_p = sum m g (y - y_low) (y_low: the lowest corner of any dynamic body when settling starts)
// over a whole window of window_s. A window, not one sample: an oscillating contact passes
// through zero kinetic energy twice a period.
#include <cstdint>

#include "world/world.hpp"

namespace blockdem {

struct SettlingReport {
    bool settled = false;            ///< the criterion was met before max_time_s
    double time_s = 0.0;             ///< [s] of simulated settling
    std::int64_t steps = 0;
    double kinetic_ratio = 0.0;      ///< [-] largest kinetic / potential energy over the last window
};

/// Settles the world in place (table at rest), then restarts the clock at t = 0: time, step
/// count and energy ledger are reset and the settled positions become the initial positions.
SettlingReport settle(World& w, const SettlingSettings& settings);

}  // namespace blockdem
