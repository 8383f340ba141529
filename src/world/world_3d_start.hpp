#pragma once
// What a 3-D run checks before its first step, as build_world does in 2-D (world/world.cpp):
// no two bodies overlap at t = 0, and the time step is below the stable limit of the contacts the
// model starts with (dynamics/critical_time_step_3d.hpp: the highest mode's limit, and the proven
// bound below it).
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
// head and collar joints, some open at any moment once settled: docs/3d.md). A dynamic body that
// touches nothing in the probe (dropped from a height) is taken as landing flat on its lowest face
// on a fixed or driven body, as 2-D's landing, and its points join the start's. A model with
// neither a resting body nor one to land on has no limit, and dt must then be given.
#include <optional>
#include <vector>

#include "dynamics/critical_time_step_3d.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// Throws ModelError naming the two bodies when a contact point at t = 0 overlaps by more than
/// round-off (1e-9 of the smaller body's size).
void check_no_initial_overlap_3d(const World3d& w);

/// The stable limits at the start, from the probe above: the proven bound and the highest mode's
/// limit (dt_s infinite: no point at the start).
StartTimeStep3d start_time_step_3d(const World3d& w);

/// The probe's contact points (above): those the loaded model at rest carries, with each point's
/// share of its pair's reduced mass (empty: no dynamic body). For `blockdem check`.
std::vector<ContactPoint3d> start_contacts_3d(const World3d& w);

/// The live watch's start (world/run_checks_3d.hpp): the proven bound of the start contacts and the
/// ratio of their highest mode's limit to it (none: estimated on the live contacts when they exist).
void start_live_watch_3d(StabilityWatch3d& watch, const StartTimeStep3d& start);

/// Sets w.dt_s: the given dt, refused (ModelError, naming the body of the mode) above the start's
/// highest-mode limit; or dt_safety times that limit, rounded down to a whole number of steps per
/// output interval. Starts the live watch from the limits (world/run_checks_3d.hpp). Returns the
/// limits.
StartTimeStep3d set_time_step_3d(World3d& w, std::optional<double> dt_s, double dt_safety,
                                    double output_interval_s);

}  // namespace blockdem
