#pragma once
// One scenario, end to end: load and validate, check that the run fits the machine, prepare
// the output folder, run, and write history.csv, energy.csv, bodies.json, VTK frames,
// summary.json and run_info.json into it. Used by `blockdem run` and the tests.
//
// State files (io/state_file.hpp): saved at the times asked for, every so often, and when a
// stop request ends the run; a run restarted from one continues the files of the run it was
// saved in (io/run_restart.hpp), so that they end byte for byte as those of a run that never
// stopped; a scenario's [simulation] initial_state starts a new run from one.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/simulation.hpp"

namespace blockdem {

struct RunRequest {
    /// The scenario file; may be empty with restart: the state's run folder's scenario.toml.
    std::filesystem::path scenario;
    std::vector<std::string> overrides;   ///< --set key=value
    /// The output folder; may be empty with restart: the state's run folder, continued in place.
    std::filesystem::path out_dir;
    bool force = false;                    ///< --force: replace the run already in out_dir
    std::vector<double> save_state_times_s;   ///< --save-state [s]
    double save_state_every_s = 0.0;          ///< --save-state-every [s]; 0: never
    std::filesystem::path restart;            ///< --restart STATE.h5; empty: a new run
    std::function<void(const RunProgress&)> on_progress;
    std::function<void(const std::string&)> on_warning;   ///< a large output, before the run
    std::function<void(const std::filesystem::path&)> on_state_saved;  ///< each state file written
    const std::atomic<bool>* stop_requested = nullptr;    ///< set by SIGINT/SIGTERM in the app
};

/// Runs the scenario. Throws InputError for bad input (a state file that is missing, damaged or
/// of another scenario included), a run that would not fit the machine, or an output folder
/// that holds another run (nothing is written). A run that fails once started (SimulationError:
/// unstable; OutputError: a write failed) writes summary.json with status "failed" where it can,
/// keeps what was written, and rethrows. A stop request ends the run after the current step
/// with status "interrupted", and writes a state file to go on from. Returns the summary, with
/// "run_folder" and "state_files" added (not written to summary.json).
nlohmann::json run_scenario(const RunRequest& request);

}  // namespace blockdem
