#pragma once
// One time step, written once, in one order (docs/architecture.md):
//   1. body geometry: corners and edge normals at t;
//   2. broad phase: candidate pairs, rebuilt only when a body has moved half the margin;
//   3. contacts, pair by pair in one pass: the narrow phase (contact points with feature ids,
//      matched with last step's for their history), then the contact law into the pair's slot;
//   4. bodies, one pass: each body's gravity plus its pairs' slots in table order
//      (deterministic), plus a caller's external loads if any (world/external_loads.hpp), its
//      velocity to t + dt/2, its energy at t; then the stability check;
//      [the state at t is complete here: recorders read it]
//   5. positions to t + dt (driven bodies exactly), and time advances.
#include "world/world.hpp"

namespace blockdem {

void update_body_geometry(World& w);
bool broad_phase_is_stale(const World& w);
void rebuild_candidate_pairs(World& w);
/// Every pair's narrow phase and then its contact law, in one pass (each body's force is then
/// summed by update_bodies); adds the contacts' terms to the energy ledger.
void update_contacts_and_forces(World& w);
/// Each body in one pass: its force (gravity plus its pairs' slots), acceleration and velocity
/// to t + dt/2, and its energy terms at t; returns false if some body's state is not finite.
bool update_bodies(World& w);
/// Sets the energies at t = 0 (before the first step).
void initialise_energy(World& w);
/// Throws SimulationError when the state is not finite (state_finite: what update_bodies
/// returned) or the energy balance has run away.
void check_stability(const World& w, bool state_finite);

/// First half of a step: everything at t (contacts, forces, accelerations, velocities to
/// t + dt/2 and their mean at t, energies at t). The world then holds a complete state at t.
void step_begin(World& w);
/// Second half: positions to t + dt, and time advances.
void step_end(World& w);
/// Advances the world from t to t + dt.
inline void step(World& w) {
    step_begin(w);
    step_end(w);
}

}  // namespace blockdem
