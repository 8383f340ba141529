#include "io/run_scenario.hpp"

#include <chrono>
#include <fstream>

#include "io/history_writer.hpp"
#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "io/summary_writer.hpp"
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
    ResponseMonitor monitor(world);
    RunOptions options;
    options.recorders = {&history};
    options.on_step = [&monitor](const World& w) { monitor.observe(w); };
    options.on_progress = request.on_progress;

    const auto started = std::chrono::steady_clock::now();
    RunInfo info;
    info.scenario = request.scenario.string();
    auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    try {
        run_simulation(world, options);
    } catch (const SimulationError& e) {
        info.status = "failed";
        info.error = e.what();
        info.wall_s = wall();
        write_summary(request.out_dir / "summary.json", make_summary(world, monitor, info));
        throw;
    }
    info.status = "completed";
    info.wall_s = wall();
    nlohmann::json summary = make_summary(world, monitor, info);
    write_summary(request.out_dir / "summary.json", summary);
    return summary;
}

}  // namespace blockdem
