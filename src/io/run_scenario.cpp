#include "io/run_scenario.hpp"

#include <chrono>
#include <optional>
#include <sstream>

#include "io/bodies_json_writer.hpp"
#include "io/energy_writer.hpp"
#include "io/history_writer.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/output_folder.hpp"
#include "io/run_budget.hpp"
#include "io/run_checks.hpp"
#include "io/scenario.hpp"
#include "io/summary_writer.hpp"
#include "io/toml_format.hpp"
#include "io/vtk_writer.hpp"
#include "world/response_monitor.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {
namespace {

// The copy in the output folder must still find the files the scenario names (records, CSV
// motions), which are relative to the original scenario's folder: make them absolute.
void make_file_keys_absolute(toml::table& root, const std::filesystem::path& scenario_dir) {
    for (const char* component : {"horizontal", "vertical"}) {
        toml::node* file = root.at_path(std::string("table_motion.") + component + ".file").node();
        if (!file || !file->is_string()) continue;
        const std::filesystem::path path = *file->value<std::string>();
        if (path.is_relative())
            *file->as_string() = std::filesystem::absolute(scenario_dir / path).lexically_normal().string();
    }
}

void write_scenario_copy(toml::table root, const std::filesystem::path& scenario, const std::filesystem::path& out_dir) {
    make_file_keys_absolute(root, scenario.parent_path());
    std::ostringstream text;
    text << scenario_copy_marker << " (" << scenario.string() << ", after --set)\n" << toml_text(root);
    write_output_file(out_dir / "scenario.toml", text.str());
}

// Everything that can refuse the run, before anything is written: whether the run fits the
// machine, and the output folder. Returns whether VTK frames will be written.
bool check_before_run(const LoadedScenario& loaded, const RunRequest& request) {
    check_step_count(loaded);
    const World& world = loaded.world;
    const bool vtk_on = vtk_enabled(loaded.output, world.bodies.size(), world.settings.duration_s);
    for (const std::string& warning : check_run_budget(loaded, estimate_run_budget(loaded, vtk_on), request.out_dir))
        if (request.on_warning) request.on_warning(warning);
    prepare_output_folder(request.out_dir, request.force);
    return vtk_on;
}

}  // namespace

nlohmann::json run_scenario(const RunRequest& request) {
    LoadedScenario loaded = load_scenario(request.scenario, request.overrides);
    World& world = loaded.world;
    const bool vtk_on = check_before_run(loaded, request);
    // The scenario as run (after --set), so that the folder documents itself.
    write_scenario_copy(loaded.root, request.scenario, request.out_dir);
    HistoryWriter history(request.out_dir / "history.csv", world);
    EnergyWriter energy(request.out_dir / "energy.csv");
    write_bodies_json(request.out_dir / "bodies.json", world);
    ResponseMonitor monitor(world);
    RunOptions options;
    options.recorders = {&history, &energy};
    std::optional<VtkWriter> vtk;
    if (vtk_on) {
        vtk.emplace(request.out_dir / "vtk", VtkSettings{loaded.output.vtk_interval_s, loaded.output.vtk_contacts});
        options.recorders.push_back(&*vtk);
    }
    // What was written besides history.csv and summary.json; `blockdem run` reads "report".
    auto outputs = [&] {
        return nlohmann::json{{"energy", "energy.csv"}, {"bodies", "bodies.json"},
                              {"vtk", vtk ? nlohmann::json("vtk/bodies.pvd") : nlohmann::json(nullptr)},
                              {"vtk_frames", vtk ? vtk->frames_written() : 0},
                              {"report", loaded.output.report}};
    };
    options.on_step = [&monitor](const World& w) { monitor.observe(w); };
    options.on_progress = request.on_progress;
    options.stop_requested = request.stop_requested;

    const auto started = std::chrono::steady_clock::now();
    RunInfo info;
    info.scenario = request.scenario.string();
    auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    auto summary_with = [&](const std::string& status, const std::string& error) {
        info.status = status;
        info.error = error;
        info.wall_s = wall();
        nlohmann::json summary = make_summary(world, monitor, info);
        for (const std::string& warning : input_warnings(loaded.root, world)) summary["warnings"].push_back(warning);
        summary["end_time_s"] = world.settings.duration_s;  // time_s below it: failed or interrupted
        summary["outputs"] = outputs();
        return summary;
    };
    RunEnd end = RunEnd::completed;
    try {
        end = run_simulation(world, options);
    } catch (const std::exception& e) {
        try {
            write_summary(request.out_dir / "summary.json", summary_with("failed", e.what()));
        } catch (const OutputError&) {
            // The disk that stopped the run may refuse the summary too: the first error is the news.
        }
        throw;
    }
    nlohmann::json summary = summary_with(end == RunEnd::stopped ? "interrupted" : "completed", "");
    write_summary(request.out_dir / "summary.json", summary);
    return summary;
}

}  // namespace blockdem
