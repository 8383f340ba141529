#pragma once
// A 3-D scenario, end to end, as `blockdem run` does it (run/run_scenario.cpp dispatches here on
// `dimension = 3`): load it (io/scenario_3d.hpp), step the world (world/step_3d.hpp) to the end,
// and write history.csv, energy.csv, VTK frames and summary.json (docs/3d.md, "Outputs").
//
// The 2-D ScenarioRun's loop is not shared: it is built around World, its recorders, state files
// and restarts. What the two share is below it (the step's order, the ledger, energy.csv's rows,
// the output folder's rules) and the request and its callbacks. State files and restarts are 2-D
// only for now, and refused here.
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "run/run_request.hpp"

namespace blockdem {

/// Runs the scenario already parsed from request.scenario. Throws InputError for bad input or an
/// output folder that holds another run (nothing written). A run that fails once started
/// (SimulationError, OutputError) writes summary.json with status "failed" and rethrows; a stop
/// request ends it after the current step with status "interrupted". Returns the summary with
/// "run_folder", "wall_time_s" and "state_files" (empty) added.
nlohmann::json run_scenario_3d(toml::table root, const RunRequest& request);

}  // namespace blockdem
