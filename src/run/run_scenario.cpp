#include "run/run_scenario.hpp"

#include <limits>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "io/state_file.hpp"
#include "run/run_scenario_3d.hpp"
#include "run/scenario_run.hpp"

namespace blockdem {

nlohmann::json run_scenario(const RunRequest& request) {
    // dimension = 3 goes to the 3-D run; a restart goes by its state file's dimension.
    if (request.restart.empty()) {
        toml::table root = load_toml_file(request.scenario);
        if (scenario_dimension(root, request.scenario.string()) == 3) return run_scenario_3d(std::move(root), request);
    } else if (StateFile(request.restart).dimension() == 3) {
        return run_scenario_3d(std::nullopt, request);
    } else if (!request.scenario.empty() &&
               scenario_dimension(load_toml_file(request.scenario), request.scenario.string()) == 3) {
        throw InputError({request.restart.string(), "", 0, 0},
                         fmt::format("a 2-D state: scenario {} is 3-D", request.scenario.string()));
    }
    ScenarioRun run(request);
    run.step(std::numeric_limits<std::int64_t>::max());
    return run.finish();
}

}  // namespace blockdem
