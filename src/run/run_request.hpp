#pragma once
// What a caller asks of a run (`blockdem run`'s options, the convergence study, the Python
// module): the scenario, the output folder, state files and the callbacks through which the
// run reports (the library never prints).
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "world/simulation.hpp"

namespace blockdem {

/// The most threads a run or a study takes (the CLI's --threads, the Python module's threads=):
/// more is a mistake, and the per-thread buffers of 1e9 threads do not fit in memory.
inline constexpr int max_threads = 4096;

struct RunRequest {
    /// The scenario file; may be empty with restart: the state's run folder's scenario.toml.
    std::filesystem::path scenario;
    std::vector<std::string> overrides;   ///< --set key=value
    /// The output folder; may be empty with restart: the state's run folder, continued in place.
    /// Empty without restart: no file is written (the Python module without out_dir).
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

}  // namespace blockdem
