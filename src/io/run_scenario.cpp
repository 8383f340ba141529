#include "io/run_scenario.hpp"

#include <chrono>
#include <fstream>
#include <optional>

#include "io/bodies_json_writer.hpp"
#include "io/energy_writer.hpp"
#include "io/history_writer.hpp"
#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "io/summary_writer.hpp"
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
    std::ofstream copy(out_dir / "scenario.toml");
    copy << root << '\n';
}

}  // namespace

nlohmann::json run_scenario(const RunRequest& request) {
    LoadedScenario loaded = load_scenario(request.scenario, request.overrides);
    std::error_code ec;
    std::filesystem::create_directories(request.out_dir, ec);
    if (ec) throw InputError({request.out_dir.string(), "", 0, 0}, "cannot create the output folder: " + ec.message());
    // The scenario as run (after --set), so that the folder documents itself.
    write_scenario_copy(loaded.root, request.scenario, request.out_dir);
    World& world = loaded.world;
    HistoryWriter history(request.out_dir / "history.csv", world);
    EnergyWriter energy(request.out_dir / "energy.csv");
    write_bodies_json(request.out_dir / "bodies.json", world);
    ResponseMonitor monitor(world);
    RunOptions options;
    options.recorders = {&history, &energy};
    std::optional<VtkWriter> vtk;
    if (vtk_enabled(loaded.output, world.bodies.size(), world.settings.duration_s)) {
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

    const auto started = std::chrono::steady_clock::now();
    RunInfo info;
    info.scenario = request.scenario.string();
    auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    try {
        run_simulation(world, options);
    } catch (const std::exception& e) {
        info.status = "failed";
        info.error = e.what();
        info.wall_s = wall();
        nlohmann::json summary = make_summary(world, monitor, info);
        summary["outputs"] = outputs();
        write_summary(request.out_dir / "summary.json", summary);
        throw;
    }
    info.status = "completed";
    info.wall_s = wall();
    nlohmann::json summary = make_summary(world, monitor, info);
    summary["outputs"] = outputs();
    write_summary(request.out_dir / "summary.json", summary);
    return summary;
}

}  // namespace blockdem
