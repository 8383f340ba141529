#include "run/scenario_run_3d.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "io/energy_writer.hpp"
#include "io/history_3d_writer.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/output_folder.hpp"
#include "io/run_checks.hpp"
#include "io/run_restart.hpp"
#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "io/state_file_3d.hpp"
#include "io/summary_writer.hpp"
#include "io/toml_format.hpp"
#include "io/vtk_3d_writer.hpp"
#include "run/run_files.hpp"
#include "world/run_checks_3d.hpp"
#include "world/simulation.hpp"

namespace blockdem {
namespace {


namespace fs = std::filesystem;

const char* kind_name(BodyKind3d k) {
    return k == BodyKind3d::dynamic ? "dynamic" : k == BodyKind3d::fixed ? "fixed" : "driven";
}

nlohmann::json vec(Vec3 v) { return {v.x, v.y, v.z}; }

nlohmann::json time_or_null(double t_s) { return t_s >= 0.0 ? nlohmann::json(t_s) : nlohmann::json(nullptr); }

// The outcome (world/outcome.hpp) of a dynamic body and what decided it, as in 2-D.
void add_outcome_3d(nlohmann::json& j, const World3d& w, std::size_t i, const BodyResponse3d& r, const BodyRecord& record,
                    const ClassifiedOutcome& o) {
    j["outcome"] = to_string(o.outcome);
    j["outcome_time_s"] = time_or_null(o.time_s);
    j["failed"] = is_failure(o.outcome);
    j["peak_base_slip_m"] = r.peak_base_slip_m;
    nlohmann::json supporters = nlohmann::json::array();
    for (std::uint32_t s : record.supporters) supporters.push_back(w.bodies[s].name);
    j["supporters"] = supporters;
    j["touches_a_supporter"] = record.touches_a_supporter;
    j["support_lost_time_s"] = time_or_null(record.support_lost_time_s);
    j["final_drop_m"] = record.drop_m;
    if (o.outcome == Outcome::fell) j["fell"] = {{"came_to_rest", o.at_rest}, {"position_m", vec(position_now_m(w, i))}};
    if (o.outcome == Outcome::left_model)
        for (const BodyLeftModel3d& l : w.domain.left)
            if (l.body == i) j["left_model"] = {{"time_s", l.time_s}, {"position_m", vec(l.position_m)}};
}

// The model's extent and the bodies that left it (world/model_domain_3d.hpp), as 2-D's "domain".
nlohmann::json domain_3d(const World3d& w) {
    const ModelDomain3d& d = w.domain;
    nlohmann::json left = nlohmann::json::array();
    for (const BodyLeftModel3d& l : d.left)
        left.push_back({{"body", w.bodies[l.body].name}, {"time_s", l.time_s}, {"position_m", vec(l.position_m)},
                        {"velocity_m_s", vec(l.velocity_m_s)}});
    const auto corner = [&](Vec3 p) { return nlohmann::json::array({p.x, p.y, finite_or_null(p.z)}); };
    return {{"from", d.from_scenario ? "scenario" : "derived"},
            {"lo_m", corner(d.box_m.lo)},
            {"hi_m", corner(d.box_m.hi)},
            {"margin_m", d.margin_m},
            {"left", left}};
}

nlohmann::json thresholds_3d(const OutcomeThresholds& t) {
    return {{"rocking_ratio", t.rocking_ratio},     {"slip_ratio", t.slip_ratio},
            {"fall_drop_ratio", t.fall_drop_ratio}, {"displaced_ratio", t.displaced_ratio},
            {"rest_speed_m_s", t.rest_speed_m_s},   {"support_window_s", t.support_window_s},
            {"elastic_slip_factor", elastic_slip_factor},
            {"slid_rule", "slid: a contact point on a supporter slid, and the resting face's lowest corner moved over the "
                          "supporter by more than max(slip_ratio x the face's least width, elastic_slip_factor x the largest "
                          "elastic shear stretch there); rocked: peak tilt relative to the first supporter >= rocking_ratio x "
                          "overturning_angle_rad"}};
}

nlohmann::json summary_of(const LoadedScenario3d& s, const std::string& scenario, const World3d& w,
                          const ResponseMonitor3d& monitor, const std::string& status, const std::string& error) {
    const std::vector<BodyRecord> records = monitor.records(w);
    const std::vector<ClassifiedOutcome> outcomes = classify_outcomes(records, monitor.thresholds());
    nlohmann::json bodies = nlohmann::json::array();
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const RigidBody3d& b = w.bodies[i];
        const BodyResponse3d& r = monitor.bodies()[i];
        const Vec3 slip = slip_m(w, r, i);
        bodies.push_back({{"name", b.name},
                          {"kind", kind_name(w.kinds[i])},
                          {"mass_kg", b.mass_kg},
                          {"position_m", vec(position_now_m(w, i))},
                          {"rotation_vector_rad", vec(rotation_vector(turn_since_start(w, r, i)))},
                          {"peak_tilt_rad", r.peak_tilt_rad},
                          {"peak_tilt_time_s", r.peak_tilt_time_s},
                          {"peak_tilt_axis", vec(r.peak_tilt_axis)},
                          {"overturning_angle_rad", r.overturning_angle_rad},
                          {"overturned", monitor.overturned(w, i)},
                          {"overturning_time_s", monitor.overturned(w, i) && r.last_crossing_s >= 0.0
                                                     ? nlohmann::json(r.last_crossing_s)
                                                     : nlohmann::json(nullptr)},
                          {"slip_m", {slip.x, slip.y}},
                          {"peak_slip_m", r.peak_slip_m}});
        if (w.kinds[i] == BodyKind3d::dynamic) add_outcome_3d(bodies.back(), w, i, r, records[i], outcomes[i]);
    }
    const EnergyLedger& e = w.ledger;
    nlohmann::json summary = {
        {"status", status},
        {"scenario", scenario},
        {"dimension", 3},
        {"time_s", w.time_s},
        {"end_time_s", w.duration_s},
        {"steps", w.steps},
        {"dt_s", w.dt_s},
        {"critical_dt_s", finite_or_null(s.critical_dt_s)},
        {"contact_points", w.contacts.size()},
        {"bodies", bodies},
        {"energy_j",
         {{"kinetic", e.kinetic_j},
          {"gravitational_change", e.gravitational_j - e.initial_gravitational_j},
          {"elastic", e.elastic_j},
          {"normal_dashpot", e.normal_dashpot_j},
          {"shear_dashpot", e.shear_dashpot_j},
          {"friction", e.friction_j},
          {"table_work", e.table_work_j},
          {"removed_with_bodies_leaving", e.removed_j},
          {"residual", e.residual_j()},
          {"balance_error_relative", e.balance_error()}}},
        // The 2-D run's "checks" object and warnings (io/run_checks.hpp), for the 3-D watches.
        {"checks", run_checks_3d(w, s.critical_dt_s, s.max_overlap_ratio, s.max_energy_error)}};
    std::vector<std::string> names;
    for (const RigidBody3d& b : w.bodies) names.push_back(b.name);
    for (const std::string& warning : run_warnings_3d(w)) summary["warnings"].push_back(warning);
    for (const std::string& warning : untouched_body_warnings(records, names, w.time_s)) summary["warnings"].push_back(warning);
    summary["settling"] = settling_summary(s.settled);
    summary["collapse"] = collapse_json(summarize_collapse_by_group(w.assembly, records, outcomes, monitor.thresholds()), names);
    summary["outcome_thresholds"] = thresholds_3d(monitor.thresholds());
    if (!s.assembly_notes.empty()) summary["assemblies"] = s.assembly_notes;
    summary["domain"] = domain_3d(w);
    if (!error.empty()) summary["error"] = error;
    return summary;
}

// The scenario as run, its file names made absolute so that the copy in the output folder still
// finds the records it names.
std::string scenario_as_run_3d(toml::table root, const fs::path& scenario) {
    for (const char* key : {"table_motion.record.file", "table_motion.x.file", "table_motion.y.file", "table_motion.z.file",
                            "simulation.initial_state"}) {
        toml::node* file = root.at_path(key).node();
        if (!file || !file->is_string()) continue;
        const fs::path path = *file->value<std::string>();
        if (path.is_relative())
            *file->as_string() = fs::absolute(scenario.parent_path() / path).lexically_normal().string();
    }
    return toml_text(root);
}

// The 3-D writers as the run loop's recorders (called at the output times).
class History3dRecorder : public Recorder3d {
public:
    History3dRecorder(const fs::path& file, const World3d& w, const ResponseMonitor3d& monitor, OutputFile::Mode mode)
        : writer_(file, w, mode), monitor_(monitor) {}
    void record(const World3d& w) override { writer_.record(w, monitor_); }
    void finish(const World3d&) override { writer_.finish(); }
    void flush() { writer_.flush(); }

private:
    History3dWriter writer_;
    const ResponseMonitor3d& monitor_;
};

class Energy3dRecorder : public Recorder3d {
public:
    Energy3dRecorder(const fs::path& file, OutputFile::Mode mode) : out_(file, mode) {
        if (mode == OutputFile::Mode::replace) out_.append(energy_csv_header);
    }
    void record(const World3d& w) override { out_.append(energy_csv_row(w.time_s, w.ledger)); }
    void finish(const World3d&) override { out_.close(); }
    void flush() { out_.flush(); }

private:
    OutputFile out_;
};

class Vtk3dRecorder : public Recorder3d {
public:
    Vtk3dRecorder(const fs::path& dir, const OutputSettings& output, const ResponseMonitor3d& monitor)
        : writer(dir, output.vtk_interval_s, output.vtk_contacts), monitor_(monitor) {}
    void record(const World3d& w) override { writer.record(w, monitor_); }
    void finish(const World3d&) override { writer.finish(); }
    Vtk3dWriter writer;

private:
    const ResponseMonitor3d& monitor_;
};

}  // namespace

// A 3-D run, built in this order (the recorders refer to the world and the monitor, so nothing
// here moves once built): the scenario, a restart's state, the folder and its writers.
struct ScenarioRun3d::Parts {
    RunRequest request;
    fs::path scenario;              ///< the file run
    fs::path out_dir;               ///< empty: no files
    std::optional<StateFile> restart;
    fs::path run_folder;            ///< the restarted run's folder
    bool in_place = false;
    RunFolderLock folder_lock;      ///< held while the run writes (released after the writers close)
    LoadedScenario3d loaded;
    std::optional<ResponseMonitor3d> monitor;
    std::optional<History3dRecorder> history;
    std::optional<Energy3dRecorder> energy;
    std::optional<Vtk3dRecorder> vtk;
    std::optional<RunTrace3d> trace;
    std::optional<Monitor3dStatePart> monitor_state;
    std::optional<Vtk3dStatePart> vtk_state;
    std::optional<Settling3dStatePart> settling_state;
    SavePoints points;
    StateFileInfo state_info;
    std::vector<std::string> state_files;
    std::vector<double> least_widths;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

    double wall_s() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }

    Parts(std::optional<toml::table> root, const RunRequest& r, bool keep_trace)
        : request(r), scenario(r.scenario), out_dir(r.out_dir) {
        if (!request.restart.empty()) {
            restart.emplace(request.restart);
            check_state_dimension(*restart, 3);
            const RestartFolders folders = restart_folders(request.restart, restart->info(), scenario, out_dir);
            run_folder = folders.run_folder;
            scenario = folders.scenario;
            out_dir = folders.out_dir;
            std::error_code ec;
            in_place = fs::exists(out_dir) && fs::equivalent(out_dir, run_folder, ec);
        }
        if (!root) {
            root = load_toml_file(scenario);
            if (scenario_dimension(*root, scenario.string()) != 3)
                throw InputError({request.restart.string(), "", 0, 0},
                                 fmt::format("a 3-D state: scenario {} is not 3-D", scenario.string()));
        }
        // (A restart takes the settled state from its file: settling again would be wasted time.)
        loaded = load_scenario_3d(std::move(*root), scenario, request.overrides, !restart, request.stop_requested);
        World3d& w = loaded.world;
        monitor.emplace(w, loaded.outcomes);  // (at t = 0: a restart puts back its start poses and peaks below)
        least_widths = least_widths_m(w);
        points = save_points(w, request);
        state_info.scenario = restart ? restart->info().scenario : scenario.string();
        state_info.scenario_toml = scenario_as_run_3d(loaded.root, scenario);
        if (restart) start_from_restart();
        else if (!loaded.initial_state.empty()) start_from_initial_state();
        if (!out_dir.empty()) open_outputs();
        if (keep_trace) trace.emplace(loaded.world, *monitor);
    }

    void start_from_restart() {
        World3d& w = loaded.world;
        restore_world_3d(*restart, w, scenario);
        if (w.steps > total_steps(w))
            throw InputError({restart->path().string(), "", 0, 0},
                             fmt::format("the state is at t = {:g} s, after the end of the run (simulation.duration = {:g} "
                                         "s); give a longer duration with --set simulation.duration=...",
                                         w.time_s, w.duration_s));
        Monitor3dStatePart part(*monitor);
        restart->restore(part);
        Settling3dStatePart settled(loaded.settled);
        if (restart->has_group(settled.state_group())) restart->restore(settled);
        if (without_duration(restart->info().scenario_toml) != without_duration(state_info.scenario_toml) && request.on_warning)
            request.on_warning(fmt::format("scenario {} is not the one state {} was saved with: the run goes on from the "
                                           "state under the changed scenario",
                                           scenario.string(), request.restart.string()));
    }

    void start_from_initial_state() {
        try {
            const StateFile initial(loaded.initial_state);
            start_from_state_3d(initial, loaded.world, scenario);
        } catch (const InputError& e) {
            throw InputError(e.where(), fmt::format("{} (simulation.initial_state in {})", e.problem(), scenario.string()));
        }
        monitor.emplace(loaded.world, loaded.outcomes);  // its t = 0 is the state's poses
    }

    // Nothing is written before every check has passed.
    void open_outputs() {
        const World3d& w = loaded.world;
        const bool vtk_on = vtk_enabled(loaded.output, w.bodies.size(), w.duration_s);
        folder_lock = in_place ? RunFolderLock::take(out_dir) : prepare_output_folder(out_dir, request.force);
        const auto mode = restart ? OutputFile::Mode::append : OutputFile::Mode::replace;
        if (restart) {
            const std::int64_t rows = restart->info().output_rows;
            keep_first_rows(run_folder / "history.csv", out_dir / "history.csv", rows);
            keep_first_rows(run_folder / "energy.csv", out_dir / "energy.csv", rows);
        }
        if (!in_place || !request.scenario.empty())
            write_output_file(out_dir / "scenario.toml", fmt::format("{} ({}, after --set)\n{}", scenario_copy_marker,
                                                                     scenario.string(), state_info.scenario_toml));
        history.emplace(out_dir / "history.csv", w, *monitor, mode);
        energy.emplace(out_dir / "energy.csv", mode);
        monitor_state.emplace(*monitor);
        if (vtk_on) {
            vtk.emplace(out_dir / "vtk", loaded.output, *monitor);
            vtk_state.emplace(vtk->writer, w);
            if (restart && restart->has_group(vtk_state->state_group())) restart->restore(*vtk_state);
            if (restart && !in_place)
                copy_vtk_frames(run_folder / "vtk", out_dir / "vtk", static_cast<std::int64_t>(vtk->writer.frames_written()),
                                loaded.output.vtk_contacts ? std::vector<std::string>{"bodies", "contacts"}
                                                           : std::vector<std::string>{"bodies"});
        }
        state_info.run_folder = fs::absolute(out_dir).lexically_normal().string();
    }

    RunOptions3d run_options() {
        RunOptions3d options;
        if (history) options.recorders = {&*history, &*energy};
        if (vtk) options.recorders.push_back(&*vtk);
        if (trace) options.recorders.push_back(&*trace);
        // The guards and the monitor read the state at t; the watch keeps its findings in the
        // world, so that a state file carries them (the loop hands the world as const).
        options.on_step = [this](const World3d&) {
            World3d& w = loaded.world;
            watch_live_time_step_3d(w);
            check_energy_balance_3d(w, loaded.max_energy_error, loaded.critical_dt_s);
            watch_overlap_3d(w, least_widths, loaded.max_overlap_ratio);
            monitor->update(w);
        };
        options.on_progress = request.on_progress;
        options.stop_requested = request.stop_requested;
        options.save_points = points;
        if (history) options.on_save_point = [this](const World3d& w, SaveReason reason) { save_state(w, reason); };
        return options;
    }

    void save_state(const World3d& w, SaveReason reason) {
        // The rows the state counts must be on disk with it.
        history->flush();
        energy->flush();
        state_info.reason = state_reason(reason);
        state_info.output_rows = output_rows_before(w, w.steps);
        const fs::path file = state_file_of(out_dir, w);
        std::vector<const StatePart*> parts = {&*monitor_state};
        if (vtk_state) parts.push_back(&*vtk_state);
        settling_state.emplace(loaded.settled);
        if (loaded.settled) parts.push_back(&*settling_state);
        write_state_file(file, 3, w.time_s, w.steps, state_info, [&](StateGroup& root) { write_world_3d(root, w); }, parts);
        state_files.push_back(file.string());
        if (request.on_state_saved) request.on_state_saved(file);
    }

    nlohmann::json finish(const std::string& status, const std::string& error) {
        nlohmann::json summary = summary_of(loaded, state_info.scenario, loaded.world, *monitor, status, error);
        if (vtk) summary["vtk_frames"] = vtk->writer.frames_written();
        // What was written (as 2-D's summary says; `report` asks the tool for report.html).
        summary["outputs"] = {{"history", "history.csv"},
                              {"energy", "energy.csv"},
                              {"vtk", vtk ? nlohmann::json("vtk/bodies.pvd") : nlohmann::json(nullptr)},
                              {"vtk_contacts", vtk && loaded.output.vtk_contacts ? nlohmann::json("vtk/contacts.pvd")
                                                                                : nlohmann::json(nullptr)},
                              {"report", loaded.output.report}};
        if (!out_dir.empty()) {
            write_summary(out_dir / "summary.json", summary);
            RunInvocation run;
            run.wall_s = wall_s();
            if (restart) {
                run.started_at_time_s = restart->time_s();
                run.restarted_from = request.restart;
            }
            run.state_files = state_files;
            if (!restart && !loaded.initial_state.empty()) run.initial_state = loaded.initial_state;
            write_summary(out_dir / "run_info.json", run_info_json(status, run));
        }
        folder_lock = RunFolderLock();  // (written: a caller's next run may take the folder)
        summary["run_folder"] = out_dir.string();
        summary["wall_time_s"] = wall_s();
        summary["state_files"] = state_files;
        return summary;
    }
};


ScenarioRun3d::ScenarioRun3d(const RunRequest& request, std::optional<toml::table> root, bool keep_trace)
    : parts_(std::make_unique<Parts>(std::move(root), request, keep_trace)) {
    loop_.emplace(parts_->loaded.world, parts_->run_options());
}

ScenarioRun3d::~ScenarioRun3d() = default;

std::int64_t ScenarioRun3d::step(std::int64_t steps) {
    if (finished_) throw std::logic_error("the run is finished: it cannot go on");
    if (loop_->failed()) throw std::logic_error("the run failed earlier: it cannot go on");
    try {
        return loop_->advance(steps);
    } catch (const std::exception& e) {
        write_failed_summary(e.what());
        throw;
    }
}

void ScenarioRun3d::write_failed_summary(const std::string& error) {
    // (The loop has finished its recorders; the disk that stopped the run may refuse the
    // summary too: the first error is the news.)
    try {
        parts_->finish("failed", error);
    } catch (const OutputError&) {
    }
}

nlohmann::json ScenarioRun3d::finish() {
    if (finished_) throw std::logic_error("the run is finished already");
    if (loop_->failed()) throw std::logic_error("the run failed: its summary was written when it failed");
    finished_ = true;
    try {
        if (!loop_->ended()) loop_->stop();
        loop_->finish();
    } catch (const std::exception& e) {
        write_failed_summary(e.what());
        throw;
    }
    return parts_->finish(status(), "");
}

std::string ScenarioRun3d::status() const {
    if (loop_->failed()) return "failed";
    if (!loop_->ended()) return "running";
    return loop_->end() == RunEnd::stopped ? "interrupted" : "completed";
}

nlohmann::json ScenarioRun3d::summary(const std::string& status) const {
    return summary_of(parts_->loaded, parts_->state_info.scenario, parts_->loaded.world, *parts_->monitor, status, "");
}
const World3d& ScenarioRun3d::world() const { return parts_->loaded.world; }
World3d& ScenarioRun3d::world() { return parts_->loaded.world; }
const LoadedScenario3d& ScenarioRun3d::scenario() const { return parts_->loaded; }
const ResponseMonitor3d& ScenarioRun3d::monitor() const { return *parts_->monitor; }
const RunTrace3d* ScenarioRun3d::trace() const { return parts_->trace ? &*parts_->trace : nullptr; }
bool ScenarioRun3d::ended() const { return loop_->ended(); }
bool ScenarioRun3d::failed() const { return loop_->failed(); }

}  // namespace blockdem
