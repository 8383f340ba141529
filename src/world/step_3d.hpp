#pragma once
// The 3-D time step, written once, in the 2-D step's order (world/step.cpp, docs/architecture.md):
//   1. the table's motion at t: driven bodies placed and given its velocity;
//   2. every body posed: world vertices, face normals and edge directions, bounding boxes;
//   3. broad phase (broad_phase/grid_broad_phase_3d.hpp): candidate pairs;
//   4. narrow phase (geometry/polyhedron_contact_3d.hpp): points keyed by features, and the
//      history of last step's points carried by key (contact/contact_table_3d.hpp);
//   5. forces: the contact law at every point (laws/linear_spring_dashpot.hpp for the normal,
//      laws/coulomb_slider_3d.hpp for the shear vector) and gravity, summed in the table's
//      order, so the result is the same bytes whatever the thread count (world/parallel.hpp's
//      rules: loops write their own slots, totals go by fixed chunks);
//   6. the kick, the energy ledger at t, the drift (dynamics/rigid_rotation_3d.hpp), and time.
#include "world/world_3d.hpp"

namespace blockdem {

/// Advances the world by one step of w.dt_s.
void step_3d(World3d& w);

}  // namespace blockdem
