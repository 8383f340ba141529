#include "run/run_scenario_3d.hpp"

#include <limits>

#include "run/scenario_run_3d.hpp"

namespace blockdem {

nlohmann::json run_scenario_3d(std::optional<toml::table> root, const RunRequest& request) {
    ScenarioRun3d run(request, std::move(root));
    run.step(std::numeric_limits<std::int64_t>::max());
    return run.finish();
}

}  // namespace blockdem
