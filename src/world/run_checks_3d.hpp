#pragma once
// The 2-D run's stops (world/step.cpp) for the 3-D world, checked on the state at t of every
// step: a ledger that no longer closes (unstable or mis-set: the results mean nothing) and bodies
// sinking into each other (a contact too soft for its load: the rigid-block model no longer
// holds); and, as the 2-D StabilityWatch, the stable step of the live contacts, re-evaluated
// every 32 steps: a body landing on a lighter one, or a stack gaining points, may need a smaller
// dt than the start's contacts did. The live limit is the live contacts' proven bound times the
// ratio of the highest mode's limit to that bound, estimated at the start and again on the live
// contacts when their layout has changed (dynamics/critical_time_step_3d.hpp). Going above it
// does not stop the run (the highest mode's limit is an estimate); it is a warning in
// summary.json, and the energy stop names it. What they found is reported by io/run_checks.hpp (run_checks_3d,
// run_warnings_3d), as the 2-D run's.
#include <cstdint>
#include <string>
#include <vector>

#include "world/world_3d.hpp"

namespace blockdem {

/// Throws SimulationError naming the error, the time, the fastest body, dt and the stable limits
/// (start_limit_s at the start, the live one now) when the balance error exceeds max_error (after
/// the first 10 steps, whose terms are all near zero).
void check_energy_balance_3d(const World3d& w, double max_error, double start_limit_s);


/// Every this many steps the live bound is evaluated (as in 2-D: a contact configuration lasts
/// far longer than 32 steps; one bound costs about half a step: 1.7 % of the brick wall example).
inline constexpr std::int64_t live_limit_every_3d = 32;

/// Every this many looks the bodies' own blocks are tested too (dynamics/critical_time_step_3d.hpp,
/// body_block_limit_3d): a body above its own limit, which the single ratio can miss.
inline constexpr std::int64_t own_blocks_every = 4;

/// At every live_limit_every_3d-th step: the limit of w's contacts (their proven bound times the
/// watch's ratio, estimated afresh as the header says) into w.stability, its least value and when
/// dt first went above it.
void watch_live_time_step_3d(World3d& w);

/// [m] each body's least width: the least extent over its face normals (exact for boxes and
/// prisms; an upper bound otherwise).
std::vector<double> least_widths_m(const World3d& w);

/// The deepest overlap of this step's points, as a fraction of the least width of the thinner
/// body of its pair, kept in w.stability when it is the run's deepest (summary.json's
/// checks.overlap; above overlap_warning_ratio a warning). Throws SimulationError naming the two
/// bodies when it exceeds max_ratio, with the kn that would bring it near 1%.
void watch_overlap_3d(World3d& w, const std::vector<double>& least_widths_m, double max_ratio);

}  // namespace blockdem
