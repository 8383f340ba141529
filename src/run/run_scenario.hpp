#pragma once
// One scenario, end to end, as `blockdem run` does it: build the run (run/scenario_run.hpp),
// step it to the end, finish it.
#include <nlohmann/json.hpp>

#include "run/run_request.hpp"

namespace blockdem {

/// Runs the scenario. Throws InputError for bad input (a state file that is missing, damaged or
/// of another scenario included), a run that would not fit the machine, or an output folder
/// that holds another run (nothing is written). A run that fails once started (SimulationError:
/// unstable; OutputError: a write failed) writes summary.json with status "failed" where it can,
/// keeps what was written, and rethrows. A stop request ends the run after the current step
/// with status "interrupted", and writes a state file to go on from. Returns the summary, with
/// "run_folder" and "state_files" added (not written to summary.json).
nlohmann::json run_scenario(const RunRequest& request);

}  // namespace blockdem
