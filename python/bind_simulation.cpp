// blockdem.Simulation: a run of a scenario (run/scenario_run.hpp) stepped from Python.
//   sim = blockdem.Simulation(scenario, threads=2, out_dir=None)
//   sim.step(n); sim.run(until=t, callback=f, every=dt); sim.t
// The state is read through numpy views of the world's own arrays (no copy): they are
// read-only, keep the simulation alive, and their data pointers stay the same from step to step
// (the world's arrays are sized once, when it is built). The GIL is released while stepping;
// the step's threads work as in the CLI (OpenMP, results independent of their number).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "io/input_error.hpp"
#include "io/scenario_3d.hpp"
#include "python/bindings.hpp"
#include "python/run_arrays.hpp"
#include "python/scenario_source.hpp"
#include "python/simulation_request.hpp"
#include "python/stepping.hpp"
#include "run/scenario_run.hpp"
#include "world/external_loads.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace blockdem::python {
namespace {

class Simulation {
public:
    Simulation(const ScenarioSource& scenario, int threads, std::optional<fs::path> out_dir, bool force, bool history,
               const std::vector<double>& save_state_s, std::optional<double> save_state_every_s)
        : threads_(threads) {
        if (scenario_dimension(scenario.parse(), scenario.file.string()) == 3)
            throw InputError({scenario.file.string(), "dimension", 0, 0},
                             "is 3: a 3-D scenario runs in blockdem.Simulation3d (the same step, t, positions, summary)");
        RunRequest request = simulation_request(threads, out_dir, force, save_state_s, save_state_every_s);
        request.scenario = scenario.file;
        LoadedScenario loaded = build_watching_signals(
            threads, settling_stop_, [&](const std::atomic<bool>* stop) { return scenario.load(true, stop); });
        run_ = std::make_unique<ScenarioRun>(std::move(loaded), request, history);
        writes_files_ = out_dir.has_value();
        step(0);  // the state at t = 0 complete (accelerations included) before anything reads it
    }

    // A run restarted from a state file, as `blockdem run --restart` (run/scenario_run.hpp):
    // the scenario is the state's run folder's scenario.toml unless given, the files go on in
    // that folder unless out_dir names another (then they are copied first), so that they end
    // byte for byte as a run that never stopped. Its rows are not kept in memory (history()).
    Simulation(const fs::path& state_file, std::optional<fs::path> scenario_file, int threads, std::optional<fs::path> out_dir,
               bool force, const std::vector<double>& save_state_s, std::optional<double> save_state_every_s)
        : threads_(threads) {
        const RunRequest request =
            restart_request(state_file, scenario_file, threads, out_dir, force, save_state_s, save_state_every_s);
        run_ = std::make_unique<ScenarioRun>(request);
        writes_files_ = true;
        step(0);
    }

    // A run with files that is dropped before finish() ends them as an interrupted run does
    // (rows flushed, summary.json written), so that no buffered row is lost.
    ~Simulation() {
        if (!writes_files_ || !run_ || run_->finished() || !failure_.empty()) return;
        try {
            run_->finish();
        } catch (const std::exception&) {
            // (A destructor cannot raise; a failed write was the disk's, as in the CLI's end.)
        }
    }
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    std::int64_t step(std::int64_t steps) {
        if (steps < 0) throw py::value_error(fmt::format("step(n) needs n >= 0, got {}", steps));
        const SteppingGuard guard(stepping_);  // (python/stepping.hpp)
        if (!failure_.empty())
            throw std::logic_error(fmt::format("the simulation stopped on an error at t = {:.6g} s and cannot go on: {}",
                                               world().time_s, failure_));
        if (run_->finished()) throw std::logic_error("the simulation is finished (finish() was called): it cannot go on");
        return step_in_chunks(steps, threads_, [&](std::int64_t chunk) {
            try {
                return run_->step(chunk);
            } catch (const std::exception& e) {
                failure_ = e.what();  // (kept: a failed run cannot be stepped again)
                throw;
            }
        });
    }

    // Steps to `until` (default: the end), calling callback(sim) every `every` seconds of
    // simulated time; a callback that returns False stops there. At the end of the run the
    // outputs are finished and the summary returned.
    py::object run(py::object self, std::optional<double> until_s, std::optional<py::function> callback,
                   std::optional<double> every_s) {
        const World& w = world();
        const std::int64_t last = until_s ? step_at_time(w, *until_s) : total_steps(w);
        if (until_s && !(std::isfinite(*until_s) && *until_s >= 0.0))
            throw py::value_error(fmt::format("until must be a time >= 0 [s], got {}", *until_s));
        if (every_s && !(std::isfinite(*every_s) && *every_s > 0.0))
            throw py::value_error(fmt::format("every must be a time > 0 [s], got {}", *every_s));
        if (every_s && !callback) throw py::type_error("every is the interval of the callback: give callback= too");
        const std::int64_t chunk =
            every_s ? std::max<std::int64_t>(1, std::llround(*every_s / w.dt_s)) : std::numeric_limits<std::int64_t>::max();
        while (w.step_index < last && !run_->ended()) {
            if (step(std::min(chunk, last - w.step_index)) == 0) break;  // (a stop request)
            if (callback) {
                const py::object go_on = (*callback)(self);
                if (!go_on.is_none() && !go_on.cast<bool>()) return py::none();
            }
        }
        if (!until_s || run_->ended()) return finish();
        return py::none();
    }

    py::object finish() {
        if (!failure_.empty()) throw std::logic_error(fmt::format("the simulation stopped on an error: {}", failure_));
        return json_to_python(scenario_run().finish());
    }

    // A body by name or id; only a dynamic body takes loads and velocities.
    std::uint32_t dynamic_body(const py::handle& body) const {
        const Bodies& b = world().bodies;
        std::uint32_t i = 0;
        if (py::isinstance<py::str>(body)) {
            try {
                i = world().body_id(body.cast<std::string>());
            } catch (const std::out_of_range&) {
                throw py::key_error(fmt::format("no body is named '{}'", body.cast<std::string>()));
            }
        } else {
            const auto id = body.cast<std::int64_t>();
            if (id < 0 || static_cast<std::size_t>(id) >= b.size())
                throw py::index_error(fmt::format("body id {} is not in 0 to {}", id, b.size() - 1));
            i = static_cast<std::uint32_t>(id);
        }
        if (b.kind[i] != BodyKind::dynamic || b.is_static[i])
            throw py::value_error(fmt::format("body '{}' is not dynamic (or has left the model): it takes no loads", b.name[i]));
        return i;
    }

    void set_external_force(const py::handle& body, std::array<double, 2> force_n, double torque_n_m) {
        const std::uint32_t i = dynamic_body(body);
        if (!std::isfinite(force_n[0]) || !std::isfinite(force_n[1]) || !std::isfinite(torque_n_m))
            throw py::value_error("the force and torque must be finite numbers");
        set_external_load(scenario_run().world(), i, {force_n[0], force_n[1]}, torque_n_m);
    }

    void set_velocity(const py::handle& body, std::array<double, 2> velocity_m_s, double angular_velocity_rad_s) {
        const std::uint32_t i = dynamic_body(body);
        if (!std::isfinite(velocity_m_s[0]) || !std::isfinite(velocity_m_s[1]) || !std::isfinite(angular_velocity_rad_s))
            throw py::value_error("the velocity must be finite numbers");
        set_body_velocity(scenario_run().world(), i, {velocity_m_s[0], velocity_m_s[1]}, angular_velocity_rad_s);
    }

    void hold_velocity(const py::handle& body, std::array<double, 2> velocity_m_s, double angular_velocity_rad_s) {
        const std::uint32_t i = dynamic_body(body);
        if (!std::isfinite(velocity_m_s[0]) || !std::isfinite(velocity_m_s[1]) || !std::isfinite(angular_velocity_rad_s))
            throw py::value_error("the velocity must be finite numbers");
        hold_body_velocity(scenario_run().world(), i, {velocity_m_s[0], velocity_m_s[1]}, angular_velocity_rad_s);
    }

    const World& world() const { return run_->world(); }
    // What reads more than the body arrays, or changes the world, waits for no thread: it
    // refuses while another thread steps (the contact table and the rows change then).
    ScenarioRun& scenario_run() {
        if (stepping_) throw std::logic_error("the simulation is being stepped in another thread: wait for step() to return");
        return *run_;
    }
    bool failed() const { return !failure_.empty(); }

private:
    std::atomic<bool> settling_stop_{false};  ///< set by Ctrl-C while the model settles (build_watching_signals); before run_, which keeps a pointer to it
    std::unique_ptr<ScenarioRun> run_;
    int threads_ = 1;
    std::string failure_;   ///< what stopped the run; empty while it may go on
    std::atomic<bool> stepping_{false};   ///< a thread is in step() with the GIL released
    bool writes_files_ = false;           ///< out_dir was given
};

}  // namespace

void bind_simulation(py::module_& m) {
    py::class_<Simulation>(m, "Simulation", "A run of a scenario, stepped from Python (docs/python.md).")
        .def(py::init<const ScenarioSource&, int, std::optional<fs::path>, bool, bool, const std::vector<double>&,
                      std::optional<double>>(),
             py::arg("scenario"), py::arg("threads") = 2, py::arg("out_dir") = py::none(), py::arg("force") = false,
             py::arg("history") = true, py::kw_only(), py::arg("save_state") = std::vector<double>{},
             py::arg("save_state_every") = py::none(),
             "Builds the world (settling it if the scenario asks). out_dir: write the CLI's files there; history: "
             "keep the output rows in memory (history()); save_state: times [s] to write state files at, "
             "save_state_every: an interval [s] (as --save-state, --save-state-every: into out_dir/state/; finish() "
             "before the end writes one too).")
        .def_static(
            "from_state",
            [](const fs::path& state_file, std::optional<fs::path> scenario, int threads, std::optional<fs::path> out_dir,
               bool force, const std::vector<double>& save_state_s, std::optional<double> save_state_every_s) {
                return std::make_unique<Simulation>(state_file, scenario, threads, out_dir, force, save_state_s, save_state_every_s);
            },
            py::arg("state_file"), py::kw_only(), py::arg("scenario") = py::none(), py::arg("threads") = 2,
            py::arg("out_dir") = py::none(), py::arg("force") = false, py::arg("save_state") = std::vector<double>{},
            py::arg("save_state_every") = py::none(),
            "A run restarted from a state file, as `blockdem run --restart`: the scenario of the state's run folder "
            "(or `scenario`, a file), its files continued there (or copied to out_dir first).")
        .def("step", &Simulation::step, py::arg("n") = 1, "Takes n steps (fewer at the end); returns the steps taken.")
        .def(
            "run",
            [](py::object self, std::optional<double> until_s, std::optional<py::function> callback, std::optional<double> every_s) {
                return self.cast<Simulation&>().run(self, until_s, callback, every_s);
            },
            py::kw_only(), py::arg("until") = py::none(),
             py::arg("callback") = py::none(), py::arg("every") = py::none(),
             "Steps to `until` [s] (default: the end, then finish() and return the summary), calling callback(sim) "
             "every `every` [s]; a callback returning False stops the run there.")
        .def("finish", &Simulation::finish, "Finishes the outputs (summary.json with out_dir); returns the summary.")
        .def_property_readonly("t", [](const Simulation& s) { return s.world().time_s; }, "[s] time of the state")
        .def_property_readonly("step_index", [](const Simulation& s) { return s.world().step_index; })
        .def_property_readonly("dt", [](const Simulation& s) { return s.world().dt_s; }, "[s]")
        .def_property_readonly("duration", [](const Simulation& s) { return s.world().settings.duration_s; }, "[s]")
        .def_property_readonly("done", [](Simulation& s) { return s.scenario_run().ended(); })
        .def_property_readonly("failed", &Simulation::failed)
        .def_property_readonly("body_names", [](const Simulation& s) { return s.world().bodies.name; })
        .def("body_id", [](const Simulation& s, const std::string& name) {
            try {
                return s.world().body_id(name);
            } catch (const std::out_of_range&) {
                throw py::key_error(fmt::format("no body is named '{}'", name));
            }
        })
        .def_property_readonly("positions", [](py::object self) { return vec2_view(self.cast<Simulation&>().world().bodies.position_m, self); },
                               "[m] N x 2 centroids at t (read-only view)")
        .def_property_readonly("rotations", [](py::object self) { return scalar_view(self.cast<Simulation&>().world().bodies.rotation_rad, self); },
                               "[rad] N, counter-clockwise from the start")
        .def_property_readonly("velocities", [](py::object self) { return vec2_view(self.cast<Simulation&>().world().bodies.velocity_at_t_m_s, self); },
                               "[m/s] N x 2 at t")
        .def_property_readonly("angular_velocities",
                               [](py::object self) { return scalar_view(self.cast<Simulation&>().world().bodies.angular_velocity_at_t_rad_s, self); },
                               "[rad/s] N at t")
        .def_property_readonly("accelerations", [](py::object self) { return vec2_view(self.cast<Simulation&>().world().bodies.acceleration_m_s2, self); },
                               "[m/s^2] N x 2 at t")
        .def_property_readonly("angular_accelerations",
                               [](py::object self) { return scalar_view(self.cast<Simulation&>().world().bodies.angular_acceleration_rad_s2, self); },
                               "[rad/s^2] N at t")
        .def_property_readonly("masses", [](py::object self) { return scalar_view(self.cast<Simulation&>().world().bodies.mass_kg, self); }, "[kg] N")
        .def_property_readonly("inertias", [](py::object self) { return scalar_view(self.cast<Simulation&>().world().bodies.inertia_kg_m2, self); },
                               "[kg m^2] N, about the centroid")
        .def("set_external_force", &Simulation::set_external_force, py::arg("body"), py::arg("force"),
             py::arg("torque") = 0.0,
             "Applies a force [N] (fx, fy) at a dynamic body's centroid and a torque [N m] from the next step on, until "
             "changed; its work is booked in the energy balance (external_work_J). body: name or id.")
        .def("clear_external_forces", [](Simulation& s) { clear_external_loads(s.scenario_run().world()); })
        .def("set_velocity", &Simulation::set_velocity, py::arg("body"), py::arg("velocity"),
             py::arg("angular_velocity") = 0.0,
             "Sets a dynamic body's velocity [m/s] and angular velocity [rad/s] for the next step; the kinetic "
             "energy it adds is booked as external work.")
        .def("hold_velocity", &Simulation::hold_velocity, py::arg("body"), py::arg("velocity"),
             py::arg("angular_velocity") = 0.0,
             "Drives a dynamic body at the velocity [m/s] and angular velocity [rad/s] from the next step on, until "
             "release_velocity(body): each step the force and torque that hold it are its external load (replacing "
             "set_external_force's), their work booked as external_work_J. body: name or id.")
        .def(
            "release_velocity", [](Simulation& s, const py::handle& body) {
                release_body_velocity(s.scenario_run().world(), s.dynamic_body(body));
            },
            py::arg("body"), "Ends hold_velocity: the body moves freely from the next step on, with no external load.")
        .def("external_force", [](Simulation& s, const py::handle& body) {
                const World& w = s.scenario_run().world();
                const std::uint32_t i = s.dynamic_body(body);
                if (!w.external_loads.any()) return py::make_tuple(0.0, 0.0, 0.0);
                return py::make_tuple(w.external_loads.force_n[i].x, w.external_loads.force_n[i].y, w.external_loads.torque_n_m[i]);
            },
            py::arg("body"), "The external load (fx, fy [N], torque [N m]) of the last step: a held body's is the force that held it.")
        .def("contacts", [](Simulation& s) { return contacts_array(s.scenario_run().world()); },
             "The contact points at t as a structured array (a copy): body_a, body_b, x, y [m], nx, ny (from a to b), "
             "normal_force, shear_force [N] (on b), overlap [m], sliding, bond.")
        .def("energy", [](Simulation& s) { return energy_dict(s.scenario_run().world().energy); },
             "The energy balance at t [J] and its relative error.")
        .def("history", [](Simulation& s) { return history_dict(s.scenario_run()); },
             "The output rows so far as numpy arrays (rows x recorded bodies), without CSV.")
        .def("summary", [](Simulation& s) { return json_to_python(s.scenario_run().summary(s.scenario_run().status())); },
             "The summary of the state now (as summary.json, nothing written), its status \"running\" until the "
             "run ends, then \"completed\", \"interrupted\" or \"failed\" as finish() says.");
}

}  // namespace blockdem::python
