#pragma once
// The settling stage in 3-D: the 2-D stage (world/settling.hpp) on the 3-D world, with the same
// [settling] keys, criterion (every dynamic body's kinetic energy below kinetic_ratio x m g L
// over a whole window, L its largest centroid-to-corner distance), friction rule ("held": mu
// raised to held_friction_mu while settling, the scenario's mu from t = 0) and report. The table
// is at rest while settling. At the end the clock is set back to zero and the bodies start from
// rest where they settled, keeping their contacts and the contacts' shear history: the first step
// is then the half step from an initial state, as for a scenario that did not settle (the
// kinetic energy dropped is below kinetic_ratio x m g L of each body).
#include <atomic>

#include "world/settling.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// Settles the world in place (table at rest), then restarts the clock at t = 0. A stop request
/// (stop_requested set, checked between steps) ends it with report.stopped.
SettlingReport settle_3d(World3d& w, const SettlingSettings& settings, const std::atomic<bool>* stop_requested = nullptr);

}  // namespace blockdem
