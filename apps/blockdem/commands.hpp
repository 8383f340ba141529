#pragma once
// The subcommands of the blockdem tool, one file each. Each adds itself to the CLI11 app and
// runs through its callback; errors are thrown and reported by main().
#include <CLI/CLI.hpp>

namespace blockdem::cli {

void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_motion_command(CLI::App& app);

}  // namespace blockdem::cli
