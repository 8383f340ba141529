#pragma once
// The 3-D time step, written once, in the 2-D step's order (world/step.cpp, docs/architecture.md):
//   1. the table's motion at t: driven bodies placed and given its velocity;
//   2. every body posed: world vertices, face normals and edge directions, bounding boxes;
//   3. broad phase (broad_phase/skin_pair_list.hpp over the grid): candidate pairs;
//   4. narrow phase (geometry/polyhedron_contact_3d.hpp): points keyed by features, and the
//      history of last step's points carried by key (contact/contact_table_3d.hpp);
//   5. forces: the contact law at every point (laws/linear_spring_dashpot.hpp for the normal,
//      laws/coulomb_slider_3d.hpp for the shear vector) and gravity, summed in the table's
//      order, so the result is the same bytes whatever the thread count (world/parallel.hpp's
//      rules: loops write their own slots, totals go by fixed chunks);
//   6. the kick, the energy ledger at t, the drift (dynamics/rigid_rotation_3d.hpp), and time.
#include "world/world_3d.hpp"

namespace blockdem {

/// First half of a step, 1 to 6 up to the drift: the world then holds a complete state at t
/// (contacts, forces, velocities at t and to t + dt/2, the ledger at t), which the run's
/// monitors and writers read (world/simulation.hpp, as the 2-D step_begin).
void step_begin(World3d& w);
/// Second half: the drift to t + dt, and time advances. Between step_end and the next
/// step_begin the state is whole for a state file (io/state_file_3d.hpp). The drift starts from
/// the pose's rotation matrices (WorldScratch3d::rotations): nothing may turn a body between
/// step_begin and step_end.
void step_end(World3d& w);

/// Advances the world by one step of w.dt_s.
inline void step_3d(World3d& w) {
    step_begin(w);
    step_end(w);
}

}  // namespace blockdem
