#pragma once
// What a run does around its loop (world/simulation.hpp), the same in both dimensions
// (run/scenario_run.cpp for 2-D, run/scenario_run_3d.cpp for 3-D): the steps of the state files
// asked for, the name of each, run_info.json, the scenario compared without its duration, a
// restart's VTK frames taken into a new folder, and a restart from a state of the other dimension
// refused.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "io/state_file.hpp"
#include "run/run_request.hpp"
#include "world/simulation.hpp"

namespace blockdem {

/// The steps of the state files asked for: --save-state times and --save-state-every. Throws
/// InputError for a time outside the run.
template <class W>
SavePoints save_points(const W& w, const RunRequest& request) {
    SavePoints points;
    for (double t_s : request.save_state_times_s) {
        if (!(t_s >= 0.0) || t_s > end_time_s(w) + 0.5 * w.dt_s)
            throw InputError({"--save-state", "", 0, 0}, fmt::format("{:g} s is outside the run (0 to {:g} s)", t_s, end_time_s(w)));
        points.steps.push_back(step_at_time(w, t_s));
    }
    if (request.save_state_every_s > 0.0)
        points.every_steps = std::max<std::int64_t>(1, std::llround(request.save_state_every_s / w.dt_s));
    return points;
}

/// [s] the time a state file is named by: the time asked for (the step nearest 0.3 s may be at
/// 0.2999994 s), the multiple of --save-state-every, or the step's time on a stop.
template <class W>
double state_file_time_s(const W& w, SaveReason reason, const RunRequest& request, const SavePoints& points) {
    if (reason == SaveReason::at_time)
        for (double t_s : request.save_state_times_s)
            if (step_at_time(w, t_s) == step_index(w)) return t_s;
    if (reason == SaveReason::every) return static_cast<double>(step_index(w) / points.every_steps) * request.save_state_every_s;
    return static_cast<double>(step_index(w)) * w.dt_s;
}

/// The state file's "reason" attribute.
inline const char* state_reason(SaveReason reason) {
    return reason == SaveReason::stopped ? "interrupted" : reason == SaveReason::every ? "save_state_every" : "save_state";
}

/// What differs from one invocation to the next (run_info.json), kept out of summary.json so that a
/// restarted run's summary is the uninterrupted run's, byte for byte.
struct RunInvocation {
    double wall_s = 0.0;                   ///< [s]
    double started_at_time_s = 0.0;        ///< [s] the restart's state time, else 0
    std::filesystem::path restarted_from;  ///< empty: a new run
    std::filesystem::path initial_state;   ///< empty: none
    std::vector<std::string> state_files;
};
nlohmann::json run_info_json(const std::string& status, const RunInvocation& run);

/// The scenario text without its duration (a restart may go on longer than the run it continues).
std::string without_duration(const std::string& scenario_toml);

/// A restart into a new folder takes the frames written before the state with it, so that the
/// folder is complete (the .pvd collections list them): files KIND_NNNNNN.vtp for each kind.
void copy_vtk_frames(const std::filesystem::path& from, const std::filesystem::path& to, std::int64_t frames,
                     const std::vector<std::string>& kinds);

/// Refuses a restart of a `dimension`-D run from a state of the other dimension, naming the file.
/// (`blockdem run --restart` picks the run by the state's dimension; the Python module's
/// Simulation and Simulation3d are told which state they were handed.)
void check_state_dimension(const StateFile& state, int dimension);

}  // namespace blockdem
