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

/// The steps between two state files of --save-state-every DT: DT in whole time steps. A DT
/// below dt is refused (a state can be saved once a step at most, and a name below dt's
/// resolution would be written over); a DT that is not a whole number of steps is rounded to
/// the nearest, with a warning when that moves it by more than 1 %.
inline std::int64_t save_every_steps(const RunRequest& request, double dt_s) {
    const double every_s = request.save_state_every_s;
    // (0.999: a dt copied from a message with 6 digits is dt.)
    if (every_s < 0.999 * dt_s)
        throw InputError({"--save-state-every", "", 0, 0},
                         fmt::format("{:g} s is below the time step dt = {:g} s: a state is saved at most once a step; give "
                                     "dt or more",
                                     every_s, dt_s));
    const std::int64_t steps = std::max<std::int64_t>(1, std::llround(every_s / dt_s));
    const double used_s = static_cast<double>(steps) * dt_s;
    if (std::abs(used_s - every_s) > 0.01 * every_s && request.on_warning)
        request.on_warning(fmt::format("--save-state-every {:g} s is not a whole number of time steps (dt = {:g} s): a "
                                       "state is saved every {} ({:g} s), each file named by the time it holds",
                                       every_s, dt_s, steps == 1 ? std::string("step") : fmt::format("{} steps", steps),
                                       used_s));
    return steps;
}

/// The steps of the state files asked for: --save-state times and --save-state-every. Throws
/// InputError for a time outside the run, or a DT below the time step.
template <class W>
SavePoints save_points(const W& w, const RunRequest& request) {
    SavePoints points;
    for (double t_s : request.save_state_times_s) {
        if (!(t_s >= 0.0) || t_s > end_time_s(w) + 0.5 * w.dt_s)
            throw InputError({"--save-state", "", 0, 0}, fmt::format("{:g} s is outside the run (0 to {:g} s)", t_s, end_time_s(w)));
        points.steps.push_back(step_at_time(w, t_s));
    }
    if (request.save_state_every_s > 0.0) points.every_steps = save_every_steps(request, w.dt_s);
    return points;
}

/// The state file of w's step in run_dir: named by the time it holds (io/state_file.hpp).
template <class W>
std::filesystem::path state_file_of(const std::filesystem::path& run_dir, const W& w) {
    return state_file_name(run_dir, step_index(w), w.dt_s);
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
