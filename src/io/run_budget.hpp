#pragma once
// What a run will need, estimated before it starts: steps, output rows, VTK frames, bytes on
// disk and in memory. A run that cannot fit (a duration of 1e300 s, frames that would fill the
// disk or the memory) is refused before anything is written, with the figure and the key; a
// large output is announced (warnings) so that a user can stop and thin it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/scenario.hpp"

namespace blockdem {

/// A warning when a run will write more than this many bytes or files.
inline constexpr double large_output_bytes = 1.0e9;
inline constexpr std::int64_t large_output_files = 10'000;
/// Beyond 2^53 steps, t = n dt no longer counts whole steps in a double.
inline constexpr double max_steps = 9007199254740992.0;

struct RunBudget {
    double steps = 0.0;               ///< [-] time steps (a double: it may be absurdly large)
    double rows = 0.0;                ///< [-] rows of history.csv and energy.csv
    double vtk_frames = 0.0;          ///< [-] 0 when VTK is off
    double history_bytes = 0.0;       ///< [B]
    double energy_bytes = 0.0;        ///< [B]
    double vtk_bytes = 0.0;           ///< [B]
    double files = 0.0;               ///< [-] files written
    double memory_bytes = 0.0;        ///< [B] held while running
    double output_bytes() const { return history_bytes + energy_bytes + vtk_bytes; }
};

/// Throws InputError naming simulation.duration (output.vtk_interval) when the run has more
/// steps (VTK frames) than can be counted. Call it before anything counts them in integers.
void check_step_count(const LoadedScenario& s);

/// Estimates the budget of running the loaded scenario (vtk: whether frames will be written).
RunBudget estimate_run_budget(const LoadedScenario& s, bool vtk);

/// Throws InputError (naming the scenario file and the key) when the run needs more memory than
/// is available, or more disk than is free where out_dir is.
/// Returns the warnings for a large output (empty when none).
std::vector<std::string> check_run_budget(const LoadedScenario& s, const RunBudget& budget,
                                          const std::filesystem::path& out_dir);

/// "3.2 GB", "410 kB": bytes for people.
std::string byte_text(double bytes);

}  // namespace blockdem
