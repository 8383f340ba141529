#include "run/run_scenario.hpp"

#include <limits>

#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "run/run_scenario_3d.hpp"
#include "run/scenario_run.hpp"

namespace blockdem {

nlohmann::json run_scenario(const RunRequest& request) {
    // dimension = 3 goes to the 3-D run (a restart is of a 2-D run: its own file is read there).
    if (request.restart.empty()) {
        toml::table root = load_toml_file(request.scenario);
        if (scenario_dimension(root, request.scenario.string()) == 3) return run_scenario_3d(std::move(root), request);
    }
    ScenarioRun run(request);
    run.step(std::numeric_limits<std::int64_t>::max());
    return run.finish();
}

}  // namespace blockdem
