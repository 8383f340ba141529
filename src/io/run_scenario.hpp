#pragma once
// One scenario, end to end: load and validate, check that the run fits the machine, prepare
// the output folder, run, and write history.csv, energy.csv, bodies.json, VTK frames and
// summary.json into it. Used by `blockdem run` and the tests.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/simulation.hpp"

namespace blockdem {

struct RunRequest {
    std::filesystem::path scenario;
    std::vector<std::string> overrides;   ///< --set key=value
    std::filesystem::path out_dir;
    bool force = false;                    ///< --force: replace the run already in out_dir
    std::function<void(const RunProgress&)> on_progress;
    std::function<void(const std::string&)> on_warning;   ///< a large output, before the run
    const std::atomic<bool>* stop_requested = nullptr;    ///< set by SIGINT/SIGTERM in the app
};

/// Runs the scenario. Throws InputError for bad input, a run that would not fit the machine, or
/// an output folder that holds another run (nothing is written). A run that fails once started
/// (SimulationError: unstable; OutputError: a write failed) writes summary.json with status
/// "failed" where it can, keeps what was written, and rethrows. A stop request ends the run
/// after the current step with status "interrupted". Returns the summary.
nlohmann::json run_scenario(const RunRequest& request);

}  // namespace blockdem
