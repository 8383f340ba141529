#pragma once
// One run of a scenario, built, stepped and finished by its caller: `blockdem run` builds it,
// steps it to the end and finishes it (run/run_scenario.hpp); the Python module steps it n steps
// at a time and reads the world in between.
//
// Building it loads and validates the scenario (or takes one already loaded), applies a restart
// or an initial state, checks that the run fits the machine, prepares the output folder and
// opens the writers (history.csv, energy.csv, bodies.json, VTK frames, sensors, interfaces).
// Finishing it writes summary.json and run_info.json. Without an output folder (the module's
// default) nothing is written; the monitor and, on request, the rows in memory (RunTrace) run
// all the same.
//
// State files (io/state_file.hpp): saved at the times asked for, every so often, and when a
// stop request ends the run; a run restarted from one continues the files of the run it was
// saved in (io/run_restart.hpp), so that they end byte for byte as those of a run that never
// stopped; a scenario's [simulation] initial_state starts a new run from one.
#include <cstdint>
#include <memory>

#include <nlohmann/json.hpp>

#include "io/scenario.hpp"
#include "run/run_request.hpp"
#include "run/run_trace.hpp"
#include "world/response_monitor.hpp"

namespace blockdem {

class ScenarioRun {
public:
    /// Loads request.scenario (or the restarted run's), and everything above. Throws InputError
    /// for bad input, a run that would not fit the machine or an output folder that holds
    /// another run (nothing is written then).
    explicit ScenarioRun(const RunRequest& request);
    /// From a scenario already loaded and settled (no restart: request.restart must be empty);
    /// request.scenario names it in messages and in the copy in the output folder.
    /// keep_trace: keep the output rows in memory (trace()).
    ScenarioRun(LoadedScenario loaded, const RunRequest& request, bool keep_trace = false);
    ~ScenarioRun();
    ScenarioRun(const ScenarioRun&) = delete;
    ScenarioRun& operator=(const ScenarioRun&) = delete;

    /// Takes up to `steps` steps, fewer at the end or on a stop request; returns the steps
    /// taken. The world is then at a complete state at its time (world/simulation.hpp, RunLoop).
    /// A failure (SimulationError, OutputError) writes summary.json with status "failed" where it
    /// can and propagates; stepping again then throws std::logic_error.
    std::int64_t step(std::int64_t steps);
    /// Ends the run at the time reached, as a stop request does (status "interrupted").
    void stop();
    /// Finishes the outputs and writes summary.json and run_info.json (when there is a folder);
    /// a run not at its end is stopped first. Returns the summary, with "run_folder",
    /// "wall_time_s" and "state_files" added. Once only.
    nlohmann::json finish();
    /// The summary of the state now, as finish() would write it with this status (nothing is
    /// written).
    nlohmann::json summary(const std::string& status) const;
    /// The run's status now, as its summary says it: "running" (it may go on), "completed" (at
    /// its end), "interrupted" (stopped before it: a stop request, stop(), finish() early), "failed".
    std::string status() const;

    World& world();
    const World& world() const;
    const LoadedScenario& scenario() const;
    const ResponseMonitor& monitor() const;
    const RunTrace* trace() const;   ///< null unless keep_trace
    bool ended() const;
    bool failed() const;
    bool finished() const;

private:
    void begin();
    struct Parts;
    std::unique_ptr<Parts> parts_;
};

}  // namespace blockdem
