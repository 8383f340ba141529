// `blockdem motion FILE`: facts and response spectrum of a ground-motion record (issue 3).
#include "apps/blockdem/commands.hpp"

namespace blockdem::cli {

void add_motion_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("motion", "Describe a ground-motion record (being written)");
    cmd->callback([] { throw CLI::RuntimeError("'blockdem motion' is not available in this build", 1); });
}

}  // namespace blockdem::cli
