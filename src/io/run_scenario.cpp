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

nlohmann::json run_scenario(const RunRequest& request) {
    LoadedScenario loaded = load_scenario(request.scenario, request.overrides);
    std::error_code ec;
    std::filesystem::create_directories(request.out_dir, ec);
    if (ec) throw InputError({request.out_dir.string(), "", 0, 0}, "cannot create the output folder: " + ec.message());
    {
        // The scenario as run (after --set), so that the folder documents itself.
        std::ofstream copy(request.out_dir / "scenario.toml");
        copy << loaded.root << '\n';
    }
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
