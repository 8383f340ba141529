#include "run/run_scenario.hpp"

#include <limits>

#include "run/scenario_run.hpp"

namespace blockdem {

nlohmann::json run_scenario(const RunRequest& request) {
    ScenarioRun run(request);
    run.step(std::numeric_limits<std::int64_t>::max());
    return run.finish();
}

}  // namespace blockdem
