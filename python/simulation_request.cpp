#include "python/simulation_request.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <pybind11/pybind11.h>

namespace py = pybind11;

namespace blockdem::python {

RunRequest simulation_request(int threads, const std::optional<std::filesystem::path>& out_dir, bool force,
                              const std::vector<double>& save_state_s, std::optional<double> save_state_every_s,
                              bool restart) {
    // (As the CLI's --threads: 1e9 threads ran out of memory, MemoryError, instead.)
    if (threads < 1 || threads > max_threads)
        throw py::value_error(fmt::format("threads must be 1 to {}, got {}", max_threads, threads));
    // State files belong to a run's folder: their restart continues its files.
    if (!out_dir && !restart && (!save_state_s.empty() || save_state_every_s))
        throw py::value_error("save_state and save_state_every write state files into the run's folder: give out_dir too");
    for (double t_s : save_state_s)
        if (!(std::isfinite(t_s) && t_s >= 0.0)) throw py::value_error(fmt::format("save_state: {} is not a time >= 0 [s]", t_s));
    if (save_state_every_s && !(std::isfinite(*save_state_every_s) && *save_state_every_s > 0.0))
        throw py::value_error(fmt::format("save_state_every must be a time > 0 [s], got {}", *save_state_every_s));
    RunRequest request;
    if (out_dir) request.out_dir = *out_dir;
    request.force = force;
    request.save_state_times_s = save_state_s;
    request.save_state_every_s = save_state_every_s.value_or(0.0);
    // (Called on the thread that builds the run, which may not hold the GIL: a 3-D run is built
    // on a second thread while this one watches for Ctrl-C, python/stepping.hpp.)
    request.on_warning = [](const std::string& text) {
        py::gil_scoped_acquire gil;
        if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) != 0) throw py::error_already_set();
    };
    return request;
}

RunRequest restart_request(const std::filesystem::path& state_file, const std::optional<std::filesystem::path>& scenario_file,
                           int threads, const std::optional<std::filesystem::path>& out_dir, bool force,
                           const std::vector<double>& save_state_s, std::optional<double> save_state_every_s) {
    RunRequest request = simulation_request(threads, out_dir, force, save_state_s, save_state_every_s, true);
    request.restart = state_file;
    if (scenario_file) request.scenario = *scenario_file;
    return request;
}

}  // namespace blockdem::python
