#pragma once
// One scenario, end to end: load and validate, run, and write history.csv and summary.json
// into the output folder. Used by `blockdem run`, the tests and (later) sweeps.
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
    std::function<void(const RunProgress&)> on_progress;
};

/// Runs the scenario. Throws InputError for bad input (nothing is run). A run that fails once
/// started (unstable, or any other error) writes summary.json with status "failed", keeps
/// history.csv, and rethrows. Returns the summary.
nlohmann::json run_scenario(const RunRequest& request);

}  // namespace blockdem
