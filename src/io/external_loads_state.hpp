#pragma once
// A caller's external loads and held velocities in a state file (world/external_loads.hpp,
// world/external_loads_3d.hpp): the group /external_loads of a 2-D file, /external_loads3d of a
// 3-D one, so that a run steered from Python and restarted goes on with the loads it had, bit
// for bit. The group is there only while the world has loads (ExternalLoads::any()): files of
// runs without loads stay as they were, and a file without the group (any earlier file, every
// CLI run's) reads as no loads.
//
// One row per body that carries anything (a load, a held velocity, or the last holding force of
// a held body, which external_force() reports), in body order:
//   body                         body index, from 0, increasing
//   force_n                      [N] at the centroid (m x 2, or m x 3 in the world frame)
//   torque_n_m                   [N m] (m; m x 3 in the world frame)
//   held                         1 while the body's velocity is held
//   held_velocity_m_s            [m/s] (m x 2, or m x 3)
//   held_angular_velocity_rad_s  [rad/s] (m; m x 3 in the world frame)
// Every other body's row is zero. Rows are written by bits (a -0.0 is a row too), so that the
// restored loads are the saved ones to the bit.
#include <cstddef>

#include "io/state_file.hpp"
#include "world/external_loads.hpp"
#include "world/external_loads_3d.hpp"

namespace blockdem {

void write_external_loads(StateGroup group, const ExternalLoads& loads);
void write_external_loads(StateGroup group, const ExternalLoads3d& loads);

/// The loads of a world of body_count bodies. Throws InputError naming the file and the dataset
/// for a missing or misshapen dataset, a body index out of range or out of order, a held flag
/// other than 0 or 1, or a value that is not finite.
ExternalLoads read_external_loads(const StateGroup& group, std::size_t body_count);
ExternalLoads3d read_external_loads_3d(const StateGroup& group, std::size_t body_count);

}  // namespace blockdem
