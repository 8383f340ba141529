#include "run/scenario_run.hpp"

#include <chrono>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "io/bodies_json_writer.hpp"
#include "io/energy_writer.hpp"
#include "io/history_writer.hpp"
#include "io/input_error.hpp"
#include "io/interfaces_writer.hpp"
#include "io/measurement_state_parts.hpp"
#include "io/output_file.hpp"
#include "io/output_folder.hpp"
#include "io/run_budget.hpp"
#include "io/run_restart.hpp"
#include "io/run_state_parts.hpp"
#include "io/run_checks.hpp"
#include "io/scenario.hpp"
#include "io/state_file.hpp"
#include "io/sensors_writer.hpp"
#include "io/summary_writer.hpp"
#include "io/toml_format.hpp"
#include "io/vtk_writer.hpp"
#include "run/run_files.hpp"
#include "world/response_monitor.hpp"
#include "world/simulation_error.hpp"
#include "world/world_state.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

// The copy in the output folder must still find the files the scenario names (records, CSV
// motions, the initial state), which are relative to the original scenario's folder: make them
// absolute.
void make_file_keys_absolute(toml::table& root, const fs::path& scenario_dir) {
    std::vector<std::string> keys = {"table_motion.horizontal.file", "table_motion.vertical.file", "simulation.initial_state"};
    if (const toml::array* drawings = root["geometry"].as_array())  // [[geometry]] file (io/geometry_keys.hpp)
        for (std::size_t i = 0; i < drawings->size(); ++i) keys.push_back(fmt::format("geometry[{}].file", i));
    for (const std::string& key : keys) {
        toml::node* file = root.at_path(key).node();
        if (!file || !file->is_string()) continue;
        const fs::path path = *file->value<std::string>();
        if (path.is_relative()) *file->as_string() = fs::absolute(scenario_dir / path).lexically_normal().string();
    }
}

// The scenario as run (after --set, file names absolute), as the copy in the folder holds it.
std::string scenario_as_run(toml::table root, const fs::path& scenario) {
    make_file_keys_absolute(root, scenario.parent_path());
    return toml_text(root);
}

void write_scenario_copy(const toml::table& root, const fs::path& scenario, const fs::path& out_dir) {
    write_output_file(out_dir / "scenario.toml", fmt::format("{} ({}, after --set)\n{}", scenario_copy_marker,
                                                             scenario.string(), scenario_as_run(root, scenario)));
}

// Everything that can refuse the run, before anything is written: whether the run fits the
// machine, and the output folder (not when a restart continues its own folder), which the run
// then holds (lock). Returns whether VTK frames will be written.
bool check_before_run(const LoadedScenario& loaded, const RunRequest& request, const fs::path& out_dir, bool in_place,
                      RunFolderLock& lock) {
    check_step_count(loaded);
    if (out_dir.empty()) return false;  // (no files)
    const World& world = loaded.world;
    const bool vtk_on = vtk_enabled(loaded.output, world.bodies.size(), world.settings.duration_s);
    for (const std::string& warning : check_run_budget(loaded, estimate_run_budget(loaded, vtk_on), out_dir))
        if (request.on_warning) request.on_warning(warning);
    lock = in_place ? RunFolderLock::take(out_dir) : prepare_output_folder(out_dir, request.force);
    return vtk_on;
}

// Where a run starts from: nothing, a state it continues, or a state it starts anew from.
struct StartingState {
    std::optional<StateFile> restart;   ///< --restart
    fs::path run_folder;                ///< the restarted run's folder
    std::optional<StateFile> initial;   ///< [simulation] initial_state
};

// A state file named by the scenario: its problems name the scenario's key too.
StateFile open_initial_state(const LoadedScenario& loaded) {
    try {
        return StateFile(loaded.initial_state);
    } catch (const InputError& e) {
        throw InputError(e.where(), fmt::format("{} (simulation.initial_state in {})", e.problem(), loaded.file.string()));
    }
}

void check_state_fits(const World& w, const StateFile& state, const fs::path& scenario) {
    if (auto mismatch = state_mismatch(w, state.world()))
        throw InputError({state.path().string(), "", 0, 0},
                         fmt::format("the state does not belong to scenario {}: {}", scenario.string(), *mismatch));
}

// The checks only a restart needs: the same bodies' masses, the same time step, and a state
// within the run.
void check_restart(const World& w, const StateFile& state, const fs::path& scenario) {
    check_state_fits(w, state, scenario);
    const WorldState& s = state.world();
    if (auto mismatch = mass_mismatch(w, s))
        throw InputError({state.path().string(), "", 0, 0}, restart_body_change(scenario, *mismatch));
    if (s.dt_s != w.dt_s)
        throw InputError({state.path().string(), "", 0, 0},
                         fmt::format("the state was saved with dt = {:.17g} s, scenario {} gives dt = {:.17g} s: a "
                                     "restart keeps the time step",
                                     s.dt_s, scenario.string(), w.dt_s));
    if (s.step_index > total_steps(w))
        throw InputError({state.path().string(), "", 0, 0},
                         fmt::format("the state is at t = {:g} s, after the end of the run (simulation.duration = {:g} "
                                     "s); give a longer duration with --set simulation.duration=...",
                                     s.time_s, w.settings.duration_s));
}

}  // namespace

// Everything a run holds, in the order it is built (the writers refer to the world and the
// monitor, so nothing here moves once built).
struct ScenarioRun::Parts {
    RunRequest request;
    fs::path scenario;   ///< the file run (or the name of a scenario given as text)
    fs::path out_dir;    ///< empty: no files
    bool in_place = false;
    RunFolderLock folder_lock;   ///< held while the run writes (released after the writers close)
    StartingState start;
    LoadedScenario loaded;
    SavePoints points;
    std::optional<HistoryWriter> history;
    std::optional<EnergyWriter> energy;
    std::optional<ResponseMonitor> monitor;
    std::optional<MonitorStatePart> monitor_state;
    std::vector<StatePart*> state_parts;
    std::optional<VtkWriter> vtk;
    std::optional<VtkStatePart> vtk_state;
    // Sensors and interfaces: nothing at all when not configured.
    std::optional<SensorsWriter> sensors;
    std::optional<InterfacesWriter> interfaces;
    std::optional<SensorsStatePart> sensors_state;
    std::optional<InterfacesStatePart> interfaces_state;
    std::optional<RunTrace> trace;
    StateFileInfo state_info;
    std::vector<std::string> state_files;
    std::string original_scenario;
    std::chrono::steady_clock::time_point started;
    std::optional<RunLoop> loop;
    bool finished = false;

    void start_from_restart_or_initial_state();
    void open_outputs(bool keep_trace);
    RunOptions run_options();
    void save_state(const World& w, SaveReason reason);
    double wall_s() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }
    nlohmann::json outputs() const;
    nlohmann::json summary_with(const std::string& status, const std::string& error) const;
    nlohmann::json run_info(const std::string& status) const;
    void write_failed_summary(const std::string& error);
};

void ScenarioRun::Parts::start_from_restart_or_initial_state() {
    World& world = loaded.world;
    if (start.restart) {
        check_restart(world, *start.restart, scenario);
        restore_state(world, start.restart->world());
        if (without_duration(start.restart->info().scenario_toml) != without_duration(scenario_as_run(loaded.root, scenario)) &&
            request.on_warning)
            request.on_warning(fmt::format("scenario {} is not the one state {} was saved with: the run goes on from the "
                                           "state under the changed scenario",
                                           scenario.string(), request.restart.string()));
    } else if (!loaded.initial_state.empty()) {
        start.initial.emplace(open_initial_state(loaded));
        check_state_fits(world, *start.initial, scenario);
        start_from_state(world, start.initial->world());
    }
}

void ScenarioRun::Parts::open_outputs(bool keep_trace) {
    World& world = loaded.world;
    points = save_points(world, request);
    const bool vtk_on = check_before_run(loaded, request, out_dir, in_place, folder_lock);
    monitor.emplace(world);
    monitor_state.emplace(*monitor);
    state_parts = {&*monitor_state};
    if (keep_trace) trace.emplace(world);
    if (out_dir.empty()) return;
    const auto mode = start.restart ? OutputFile::Mode::append : OutputFile::Mode::replace;
    if (start.restart) {
        const std::int64_t rows = start.restart->info().output_rows;
        keep_first_rows(start.run_folder / "history.csv", out_dir / "history.csv", rows);
        keep_first_rows(start.run_folder / "energy.csv", out_dir / "energy.csv", rows);
    }
    // Sensors and interfaces (io/sensor_keys.hpp) go on likewise when the state has their groups
    // (io/measurement_state_parts.hpp); else they start afresh at the state's time.
    const bool sensors_go_on = start.restart && start.restart->has_group("sensors") && !loaded.measurements.sensors.empty();
    const bool interfaces_go_on =
        start.restart && start.restart->has_group("interfaces") && loaded.measurements.interfaces.any();
    if (sensors_go_on)
        keep_rows_after_comments(start.run_folder / "sensors.csv", out_dir / "sensors.csv", start.restart->info().output_rows);
    if (interfaces_go_on)
        keep_rows_after_comments(start.run_folder / "interfaces.csv", out_dir / "interfaces.csv",
                                 interfaces_csv_rows(*start.restart));
    // The scenario as run (after --set), so that the folder documents itself.
    if (!in_place || !request.scenario.empty()) write_scenario_copy(loaded.root, scenario, out_dir);
    history.emplace(out_dir / "history.csv", world, mode);
    energy.emplace(out_dir / "energy.csv", mode);
    write_bodies_json(out_dir / "bodies.json", world);
    if (vtk_on) {
        vtk.emplace(out_dir / "vtk", VtkSettings{loaded.output.vtk_interval_s, loaded.output.vtk_contacts});
        vtk_state.emplace(*vtk, world);
        state_parts.push_back(&*vtk_state);
    }
    auto mode_if = [](bool goes_on) { return goes_on ? OutputFile::Mode::append : OutputFile::Mode::replace; };
    if (!loaded.measurements.sensors.empty())
        state_parts.push_back(&sensors_state.emplace(
            sensors.emplace(out_dir / "sensors.csv", world, loaded.measurements.sensors, mode_if(sensors_go_on))));
    if (loaded.measurements.interfaces.any())
        state_parts.push_back(&interfaces_state.emplace(
            interfaces.emplace(out_dir / "interfaces.csv", loaded.measurements.interfaces, mode_if(interfaces_go_on)),
            world));
    if (start.restart)
        for (StatePart* part : state_parts)
            // The monitor's group is required; a part the state lacks (VTK frames that the saved
            // run did not write) starts afresh.
            if (part == &*monitor_state || start.restart->has_group(part->state_group())) start.restart->restore(*part);
    if (start.restart && !in_place && vtk) copy_vtk_frames(start.run_folder / "vtk", out_dir / "vtk", vtk->frames_written(), {"bodies", "contacts"});
}

RunOptions ScenarioRun::Parts::run_options() {
    RunOptions options;
    if (history) options.recorders = {&*history, &*energy};
    if (vtk) options.recorders.push_back(&*vtk);
    if (sensors) options.recorders.push_back(&*sensors);
    if (interfaces) options.recorders.push_back(&*interfaces);
    if (trace) options.recorders.push_back(&*trace);
    options.on_step = [this](const World& w) {
        monitor->observe(w);
        if (sensors) sensors->observe(w);
        if (interfaces) interfaces->observe(w);
    };
    options.on_progress = request.on_progress;
    options.stop_requested = request.stop_requested;
    options.save_points = points;
    if (!out_dir.empty()) options.on_save_point = [this](const World& w, SaveReason reason) { save_state(w, reason); };
    return options;
}

void ScenarioRun::Parts::save_state(const World& w, SaveReason reason) {
    // The rows the state counts must be on disk with it.
    history->flush();
    energy->flush();
    if (sensors) sensors->flush();
    if (interfaces) interfaces->flush();
    state_info.reason = state_reason(reason);
    state_info.output_rows = output_rows_before(w, w.step_index);
    const fs::path file = state_file_of(out_dir, w);
    std::vector<const StatePart*> const_parts(state_parts.begin(), state_parts.end());
    write_state_file(file, w, state_info, const_parts);
    state_files.push_back(file.string());
    if (request.on_state_saved) request.on_state_saved(file);
}

// What was written besides history.csv and summary.json; `blockdem run` reads "report".
nlohmann::json ScenarioRun::Parts::outputs() const {
    return nlohmann::json{{"energy", "energy.csv"}, {"bodies", "bodies.json"},
                          {"vtk", vtk ? nlohmann::json("vtk/bodies.pvd") : nlohmann::json(nullptr)},
                          {"vtk_frames", vtk ? vtk->frames_written() : 0},
                          {"report", loaded.output.report},
                          {"sensors", sensors ? nlohmann::json("sensors.csv") : nlohmann::json(nullptr)},
                          {"interfaces", interfaces ? nlohmann::json("interfaces.csv") : nlohmann::json(nullptr)}};
}

nlohmann::json ScenarioRun::Parts::summary_with(const std::string& status, const std::string& error) const {
    const World& world = loaded.world;
    RunInfo info;
    info.scenario = original_scenario;
    info.status = status;
    info.error = error;
    nlohmann::json summary = make_summary(world, *monitor, info);
    for (const std::string& warning : input_warnings(loaded.root, world)) summary["warnings"].push_back(warning);
    summary["end_time_s"] = world.settings.duration_s;  // time_s below it: failed or interrupted
    summary["outputs"] = outputs();
    if (interfaces) summary["interfaces"] = interfaces_summary(world, interfaces->monitor());
    return summary;
}

// What differs from one invocation to the next, kept out of summary.json so that a restarted
// run's summary is the uninterrupted run's, byte for byte.
nlohmann::json ScenarioRun::Parts::run_info(const std::string& status) const {
    RunInvocation run;
    run.wall_s = wall_s();
    if (start.restart) {
        run.started_at_time_s = start.restart->world().time_s;
        run.restarted_from = request.restart;
    }
    if (start.initial) run.initial_state = loaded.initial_state;
    run.state_files = state_files;
    return run_info_json(status, run);
}

void ScenarioRun::Parts::write_failed_summary(const std::string& error) {
    if (out_dir.empty()) return;
    try {
        write_summary(out_dir / "summary.json", summary_with("failed", error));
        write_summary(out_dir / "run_info.json", run_info("failed"));
    } catch (const OutputError&) {
        // The disk that stopped the run may refuse the summary too: the first error is the news.
    }
    folder_lock = RunFolderLock();  // (the run cannot go on: a caller's next run may take the folder)
}

ScenarioRun::ScenarioRun(const RunRequest& request) : parts_(std::make_unique<Parts>()) {
    Parts& p = *parts_;
    p.request = request;
    p.scenario = request.scenario;
    p.out_dir = request.out_dir;
    if (!request.restart.empty()) {
        p.start.restart.emplace(request.restart);
        check_state_dimension(*p.start.restart, 2);
        const RestartFolders folders = restart_folders(request.restart, p.start.restart->info(), p.scenario, p.out_dir);
        p.start.run_folder = folders.run_folder;
        p.scenario = folders.scenario;
        p.out_dir = folders.out_dir;
    }
    std::error_code ec;
    p.in_place = p.start.restart && fs::exists(p.out_dir) && fs::equivalent(p.out_dir, p.start.run_folder, ec);
    // (A restart takes the settled state from its file: settling again would be wasted time.)
    p.loaded = load_scenario(p.scenario, request.overrides, !p.start.restart, request.stop_requested);
    p.start_from_restart_or_initial_state();
    p.open_outputs(false);
    begin();
}

ScenarioRun::ScenarioRun(LoadedScenario loaded, const RunRequest& request, bool keep_trace)
    : parts_(std::make_unique<Parts>()) {
    if (!request.restart.empty()) throw std::invalid_argument("ScenarioRun: a restart is built from its request alone");
    Parts& p = *parts_;
    p.request = request;
    p.scenario = request.scenario.empty() ? loaded.file : request.scenario;
    p.out_dir = request.out_dir;
    p.loaded = std::move(loaded);
    p.start_from_restart_or_initial_state();
    p.open_outputs(keep_trace);
    begin();
}

void ScenarioRun::begin() {
    Parts& p = *parts_;
    p.original_scenario = p.start.restart ? p.start.restart->info().scenario : p.scenario.string();
    p.state_info.scenario = p.original_scenario;
    p.state_info.scenario_toml = scenario_as_run(p.loaded.root, p.scenario);
    p.state_info.run_folder = p.out_dir.empty() ? std::string() : fs::absolute(p.out_dir).lexically_normal().string();
    p.started = std::chrono::steady_clock::now();
    p.loop.emplace(p.loaded.world, p.run_options());
}

ScenarioRun::~ScenarioRun() = default;

std::int64_t ScenarioRun::step(std::int64_t steps) {
    if (parts_->finished) throw std::logic_error("the run is finished: it cannot go on");
    if (parts_->loop->failed()) throw std::logic_error("the run failed earlier: it cannot go on");
    try {
        return parts_->loop->advance(steps);
    } catch (const std::exception& e) {
        parts_->write_failed_summary(e.what());
        throw;
    }
}

void ScenarioRun::stop() {
    try {
        parts_->loop->stop();
    } catch (const std::exception& e) {
        parts_->write_failed_summary(e.what());
        throw;
    }
}

nlohmann::json ScenarioRun::finish() {
    Parts& p = *parts_;
    if (p.finished) throw std::logic_error("the run is finished already");
    if (p.loop->failed()) throw std::logic_error("the run failed: its summary was written when it failed");
    if (!p.loop->ended()) stop();
    p.finished = true;
    try {
        p.loop->finish();
    } catch (const std::exception& e) {
        p.write_failed_summary(e.what());
        throw;
    }
    const std::string status = this->status();
    nlohmann::json summary = p.summary_with(status, "");
    if (!p.out_dir.empty()) {
        write_summary(p.out_dir / "summary.json", summary);
        write_summary(p.out_dir / "run_info.json", p.run_info(status));
    }
    p.folder_lock = RunFolderLock();  // (written: a caller's next run may take the folder)
    summary["run_folder"] = p.out_dir.string();
    summary["wall_time_s"] = p.wall_s();  // (for the callers that time their runs: converge)
    summary["state_files"] = p.state_files;
    return summary;
}

nlohmann::json ScenarioRun::summary(const std::string& status) const { return parts_->summary_with(status, ""); }
World& ScenarioRun::world() { return parts_->loaded.world; }
const World& ScenarioRun::world() const { return parts_->loaded.world; }
const LoadedScenario& ScenarioRun::scenario() const { return parts_->loaded; }
const ResponseMonitor& ScenarioRun::monitor() const { return *parts_->monitor; }
const RunTrace* ScenarioRun::trace() const { return parts_->trace ? &*parts_->trace : nullptr; }
bool ScenarioRun::ended() const { return parts_->loop->ended(); }
bool ScenarioRun::failed() const { return parts_->loop->failed(); }
bool ScenarioRun::finished() const { return parts_->finished; }

std::string ScenarioRun::status() const {
    const RunLoop& loop = *parts_->loop;
    if (loop.failed()) return "failed";
    if (!loop.ended()) return "running";
    return loop.end() == RunEnd::stopped ? "interrupted" : "completed";
}

}  // namespace blockdem
