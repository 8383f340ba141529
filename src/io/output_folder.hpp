#pragma once
// The --out folder of `blockdem run`. A folder that already holds a run is refused, so that a
// new run never mixes its files with the stale ones of another (VTK frames, report, summary);
// --force first removes blockdem's own files from it, and nothing else. A folder is a run
// folder when its summary.json is a run summary or its scenario.toml carries the line blockdem
// writes at its top (scenario_copy_marker). A folder that holds no run may hold anything else,
// as long as no file there has a name blockdem writes (that file would be overwritten).
#include <filesystem>
#include <string>

namespace blockdem {

/// The first line of the scenario.toml that `blockdem run` writes into its folder.
inline constexpr const char* scenario_copy_marker = "# written by blockdem run: the scenario as run";

/// Creates dir, or makes an existing one ready for a new run (see above). Throws InputError
/// naming the folder and the file when it refuses.
void prepare_output_folder(const std::filesystem::path& dir, bool force);

/// Whether dir holds a run of blockdem (its summary.json or scenario.toml).
bool holds_run(const std::filesystem::path& dir);

}  // namespace blockdem
