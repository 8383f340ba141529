#include "run/run_scenario_3d.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "io/energy_writer.hpp"
#include "io/history_3d_writer.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/output_folder.hpp"
#include "io/scenario_3d.hpp"
#include "io/toml_format.hpp"
#include "io/vtk_3d_writer.hpp"
#include "world/run_checks_3d.hpp"
#include "world/simulation_error.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

const char* kind_name(BodyKind3d k) {
    return k == BodyKind3d::dynamic ? "dynamic" : k == BodyKind3d::fixed ? "fixed" : "driven";
}

nlohmann::json vec(Vec3 v) { return {v.x, v.y, v.z}; }

nlohmann::json summary_of(const LoadedScenario3d& s, const World3d& w, const ResponseMonitor3d& monitor,
                          const std::string& status, const std::string& error) {
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
                          {"slip_m", {slip.x, slip.y}},
                          {"peak_slip_m", r.peak_slip_m}});
    }
    const EnergyLedger& e = w.ledger;
    nlohmann::json summary = {
        {"status", status},
        {"scenario", s.file.string()},
        {"dimension", 3},
        {"time_s", w.time_s},
        {"end_time_s", s.duration_s},
        {"steps", w.steps},
        {"dt_s", w.dt_s},
        {"critical_dt_s", std::isfinite(s.critical_dt_s) ? nlohmann::json(s.critical_dt_s) : nlohmann::json(nullptr)},
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
          {"residual", e.residual_j()},
          {"balance_error_relative", e.balance_error()}}}};
    if (!s.assembly_notes.empty()) summary["assemblies"] = s.assembly_notes;
    if (!error.empty()) summary["error"] = error;
    return summary;
}

// The scenario as run, its file names made absolute so that the copy in the output folder still
// finds the records it names.
std::string copy_text(const LoadedScenario3d& s) {
    toml::table root = s.root;
    for (const char* key : {"table_motion.record.file", "table_motion.x.file", "table_motion.y.file", "table_motion.z.file"}) {
        toml::node* file = root.at_path(key).node();
        if (!file || !file->is_string()) continue;
        const fs::path path = *file->value<std::string>();
        if (path.is_relative())
            *file->as_string() = fs::absolute(s.file.parent_path() / path).lexically_normal().string();
    }
    return toml_text(root);
}

// The writers of a run with a folder: opened on a folder made ready for the run (nothing is
// written before every check has passed), each row at the output times, closed at the end.
struct Writers {
    std::unique_ptr<History3dWriter> history;
    std::unique_ptr<OutputFile> energy;
    std::unique_ptr<Vtk3dWriter> vtk;
    std::int64_t rows = 0;

    Writers(const LoadedScenario3d& s, const RunRequest& request) {
        const fs::path& out = request.out_dir;
        prepare_output_folder(out, request.force);
        write_output_file(out / "scenario.toml", fmt::format("{} ({}, after --set)\n{}", scenario_copy_marker,
                                                             request.scenario.string(), copy_text(s)));
        history = std::make_unique<History3dWriter>(out / "history.csv", s.world);
        energy = std::make_unique<OutputFile>(out / "energy.csv");
        energy->append(energy_csv_header);
        // (The 2-D rule for "auto": frames times bodies below a limit.)
        if (vtk_enabled(s.output, s.world.bodies.size(), s.duration_s))
            vtk = std::make_unique<Vtk3dWriter>(out / "vtk", s.output.vtk_interval_s);
    }

    // Rows at whole multiples of the interval (times are sums of dt: half a step of slack).
    void record(const LoadedScenario3d& s, const ResponseMonitor3d& monitor) {
        const World3d& w = s.world;
        if (w.time_s >= static_cast<double>(rows) * s.output_interval_s - 0.5 * w.dt_s) {
            history->record(w, monitor);
            energy->append(energy_csv_row(w.time_s, w.ledger));
            ++rows;
        }
        if (vtk) vtk->record(w, monitor);
    }

    void finish(const fs::path& out, nlohmann::json& summary) {
        history->finish();
        energy->close();
        if (vtk) {
            vtk->finish();
            summary["vtk_frames"] = vtk->frames_written();
        }
        write_output_file(out / "summary.json", summary.dump(2) + "\n");
    }
};

}  // namespace

nlohmann::json run_scenario_3d(toml::table root, const RunRequest& request) {
    const auto started = std::chrono::steady_clock::now();
    const auto wall_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    if (!request.restart.empty() || !request.save_state_times_s.empty() || request.save_state_every_s > 0.0)
        throw InputError({request.scenario.string(), "dimension", 0, 0},
                         "state files (--save-state, --restart) are 2-D only so far: a 3-D run goes from t = 0 to the end");
    LoadedScenario3d s = load_scenario_3d(std::move(root), request.scenario, request.overrides);
    World3d& w = s.world;
    const fs::path& out = request.out_dir;
    std::optional<Writers> writers;
    if (!out.empty()) writers.emplace(s, request);
    ResponseMonitor3d monitor(w);
    const std::vector<double> widths_m = least_widths_m(w);
    const auto record = [&] {
        monitor.update(w);
        if (writers) writers->record(s, monitor);
    };
    const auto finish = [&](const std::string& status, const std::string& error) {
        nlohmann::json summary = summary_of(s, w, monitor, status, error);
        if (writers) writers->finish(out, summary);
        summary["run_folder"] = out.string();
        summary["wall_time_s"] = wall_s();
        summary["state_files"] = nlohmann::json::array();
        return summary;
    };
    std::string status = "completed";
    try {
        record();
        double last_progress_s = 0.0;
        while (w.time_s < s.duration_s - 0.5 * w.dt_s) {
            if (request.stop_requested && request.stop_requested->load()) {
                status = "interrupted";
                break;
            }
            step_3d(w);
            check_energy_balance_3d(w, s.max_energy_error, s.critical_dt_s);
            check_overlap_3d(w, widths_m, s.max_overlap_ratio);
            record();
            if (request.on_progress && wall_s() - last_progress_s >= 2.0) {
                last_progress_s = wall_s();
                request.on_progress({w.time_s, s.duration_s, w.steps, last_progress_s});
            }
        }
    } catch (const SimulationError& e) {
        finish("failed", e.what());
        throw;
    } catch (const OutputError& e) {
        finish("failed", e.what());
        throw;
    }
    return finish(status, "");
}

}  // namespace blockdem
