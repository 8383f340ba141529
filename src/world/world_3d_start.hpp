#pragma once
// What a 3-D run checks before its first step, as build_world does in 2-D (world/world.cpp):
// no two bodies overlap at t = 0, and the time step is below the stable bound of the contacts the
// model starts with (dynamics/critical_time_step_3d.hpp).
//
// Bodies placed touching (drums stacked face on face, a box on the table) have no contact point
// at t = 0: the narrow phase makes points only where the overlap is positive. So the bound is
// taken from a probe: a copy of the world stepped three times under gravity with a step small
// against every dynamic body's own period on one point (0.1 sqrt(m / kn)), after which every
// touching pair carries its points: the probe's bodies are grown by a touch tolerance (1e-9 of
// their size, the start check's), so that faces placed touching overlap from its first step and
// a tall stack's upper courses count as its lowest do. The springs are linear, so the bound does
// not depend on how far they are compressed, only on which points exist. The probe sees every
// touching face closed at once, so its bound is on the safe side of the loaded model's (a wall's
// head and collar joints, some open at any moment once settled: docs/3d.md). A model that starts with no body on another (a drop from a height) has
// no bound at the start, and the time step must then be given, as in 2-D.
#include <optional>
#include <vector>

#include "dynamics/critical_time_step_3d.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// Throws ModelError naming the two bodies when a contact point at t = 0 overlaps by more than
/// round-off (1e-9 of the smaller body's size).
void check_no_initial_overlap_3d(const World3d& w);

/// The stable bound at the start, from the probe above (dt_s infinite: no point at the start).
CriticalTimeStep3d start_time_step_3d(const World3d& w);

/// The probe's contact points (above): those the loaded model at rest carries, with each point's
/// share of its pair's reduced mass (empty: no dynamic body). For `blockdem check`.
std::vector<ContactPoint3d> start_contacts_3d(const World3d& w);

/// Sets w.dt_s: the given dt, refused (ModelError, naming the body of the bound) above the bound;
/// or dt_safety times the bound, rounded down to a whole number of steps per output interval.
/// Returns the bound.
CriticalTimeStep3d set_time_step_3d(World3d& w, std::optional<double> dt_s, double dt_safety,
                                    double output_interval_s);

}  // namespace blockdem
