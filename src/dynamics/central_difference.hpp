#pragma once
// Time integration (Cundall's explicit central-difference scheme, second order):
//   v(t + dt/2) = v(t - dt/2) + a(t) dt,    x(t + dt) = x(t) + v(t + dt/2) dt,
// for translation and rotation of dynamic bodies, split in its two halves so that the state at
// t (positions, accelerations, and velocities averaged to t) can be recorded between them.
// Driven bodies are placed exactly where the table motion puts them at t + dt; their half-step
// velocity is the displacement difference over dt, so that the slip a block on the table sees
// is the table's exact displacement.
#include "world/world.hpp"

namespace blockdem {

/// Accelerations at t from the forces, and velocities to t + dt/2 (and their mean at t).
void update_velocities(World& w);

/// Positions to t + dt; returns the work [J] that driven bodies did on the rest in this step.
double update_positions(World& w);

/// Places driven bodies at their prescribed position and velocity for time t_s (used at t = 0).
void place_driven_bodies(World& w, double t_s);

}  // namespace blockdem
