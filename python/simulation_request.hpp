#pragma once
// The RunRequest (run/run_request.hpp) of a blockdem.Simulation or Simulation3d, built from the
// keyword arguments both share (threads, out_dir, force, save_state, save_state_every), so that
// both check them alike and say the same when they refuse them (ValueError).
#include <filesystem>
#include <optional>
#include <vector>

#include "run/run_request.hpp"

namespace blockdem::python {

/// The request of a new run, or of a run restarted from a state file (restart: its state files
/// go into the restarted run's folder, so out_dir may be left out). A run's warnings (a large
/// output, a restart under a changed scenario) become Python UserWarnings.
RunRequest simulation_request(int threads, const std::optional<std::filesystem::path>& out_dir, bool force,
                              const std::vector<double>& save_state_s, std::optional<double> save_state_every_s,
                              bool restart = false);

/// The request of from_state: a run restarted from state_file, with the scenario of the state's
/// run folder unless scenario_file is given, and the files continued in that folder unless
/// out_dir names another.
RunRequest restart_request(const std::filesystem::path& state_file, const std::optional<std::filesystem::path>& scenario_file,
                           int threads, const std::optional<std::filesystem::path>& out_dir, bool force,
                           const std::vector<double>& save_state_s, std::optional<double> save_state_every_s);

}  // namespace blockdem::python
