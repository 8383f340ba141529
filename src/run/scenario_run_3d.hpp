#pragma once
// One run of a 3-D scenario, built, stepped and finished by its caller, as the 2-D ScenarioRun
// (run/scenario_run.hpp): `blockdem run` steps it to the end (run/run_scenario_3d.hpp); the
// Python module steps it n steps at a time and reads the world in between.
//
// Building it loads the scenario (or, with request.restart, the state's run folder's
// scenario.toml and the state: io/state_file_3d.hpp), prepares the output folder and opens the
// writers (history.csv, energy.csv, VTK frames). Stepping goes through the run loop both
// dimensions share (world/simulation.hpp, RunLoopOf<World3d>): the stops (energy balance,
// overlap) and the live stable step (world/run_checks_3d.hpp) on every step, the monitor, the
// rows at the output times, state files at the save points and on a stop request. Finishing it
// writes summary.json and run_info.json. Without an output folder nothing is written.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "io/scenario_3d.hpp"
#include "run/run_request.hpp"
#include "run/run_trace_3d.hpp"
#include "world/response_monitor_3d.hpp"
#include "world/simulation.hpp"

namespace blockdem {

class ScenarioRun3d {
public:
    /// root: the scenario already parsed from request.scenario; nullopt: read it (with a restart,
    /// the run folder's scenario.toml unless request.scenario names one). Throws InputError for
    /// bad input, a state that does not fit, or an output folder that holds another run
    /// (nothing is written then).
    /// keep_trace: keep the output rows in memory (trace()).
    explicit ScenarioRun3d(const RunRequest& request, std::optional<toml::table> root = std::nullopt,
                           bool keep_trace = false);
    ~ScenarioRun3d();
    ScenarioRun3d(const ScenarioRun3d&) = delete;
    ScenarioRun3d& operator=(const ScenarioRun3d&) = delete;

    /// Takes up to `steps` steps, fewer at the end or on a stop request; returns the steps taken.
    /// The world is then at a complete state at its time. A failure (SimulationError,
    /// OutputError) writes summary.json with status "failed" and propagates; stepping again
    /// then throws std::logic_error.
    std::int64_t step(std::int64_t steps);
    /// Ends the run (before its end: as a stop request, "interrupted", with a state file to go
    /// on from), writes summary.json and run_info.json, and returns the summary with
    /// "run_folder", "wall_time_s" and "state_files" added.
    nlohmann::json finish();

    /// The summary as it would be written now, with this status.
    nlohmann::json summary(const std::string& status) const;
    /// The run's status now, as its summary says it: "running" (it may go on), "completed" (at
    /// its end), "interrupted" (stopped before it: a stop request, finish() early), "failed".
    std::string status() const;
    const World3d& world() const;
    /// The world to change between steps (a caller's loads and velocities, world/external_loads_3d.hpp).
    World3d& world();
    const LoadedScenario3d& scenario() const;
    const ResponseMonitor3d& monitor() const;
    /// The rows kept in memory, or null when the run keeps none.
    const RunTrace3d* trace() const;
    bool ended() const;
    bool failed() const;
    bool finished() const { return finished_; }

private:
    struct Parts;
    void write_failed_summary(const std::string& error);
    std::unique_ptr<Parts> parts_;
    std::optional<RunLoop3d> loop_;
    bool finished_ = false;
};

}  // namespace blockdem
