#pragma once
// A 3-D scenario, end to end, as `blockdem run` does it (run/run_scenario.cpp dispatches here on
// `dimension = 3`, or on a 3-D state file given to --restart): load it (io/scenario_3d.hpp), step
// the world to the end in the run loop both dimensions share (world/simulation.hpp, RunLoopOf),
// and write history.csv, energy.csv, VTK frames, summary.json and run_info.json (docs/3d.md,
// "Outputs"). What is 3-D here is only what the world is: its writers, its guards
// (world/run_checks_3d.hpp) and its state (io/state_file_3d.hpp); the stop request, progress,
// save points, state file names, restarts' cut files and run_info.json are the 2-D run's
// (run/run_files.hpp, io/run_restart.hpp).
#include <optional>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "run/run_request.hpp"

namespace blockdem {

/// Runs the scenario (root: already parsed from request.scenario; nullopt: read it, or with a
/// restart the run folder's scenario.toml). Throws InputError for bad input, a state file that
/// does not fit, or an output folder that holds another run (nothing written). A run that fails
/// once started (SimulationError, OutputError) writes summary.json with status "failed" and
/// rethrows; a stop request ends it after the current step with status "interrupted" and a
/// state file to go on from. Returns the summary with "run_folder", "wall_time_s" and
/// "state_files" added.
nlohmann::json run_scenario_3d(std::optional<toml::table> root, const RunRequest& request);

}  // namespace blockdem
