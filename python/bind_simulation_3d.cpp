// blockdem.Simulation3d: a run of a 3-D scenario (run/scenario_run_3d.hpp) stepped from Python,
// with the 2-D Simulation's API where the concept is the same (python/bind_simulation.cpp):
//   sim = blockdem.Simulation3d(scenario, threads=2, out_dir=None)
//   sim.step(n); sim.t; sim.positions (N x 3); sim.quaternions (N x 4); sim.summary(); sim.finish()
//   sim.set_external_force(body, force, torque); sim.hold_velocity(body, velocity, angular_velocity) ...
//   Simulation3d(scenario, out_dir=d, save_state=[t]); Simulation3d.from_state(d / "state/t_....h5")
// A 3-D body is a struct of its own (dynamics/rigid_body_3d.hpp), not an array per quantity, so
// the state comes as numpy copies taken when read, not as views. The GIL is released while
// stepping, and Ctrl-C (KeyboardInterrupt) is seen between chunks of steps, as in 2-D.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
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
#include "run/scenario_run_3d.hpp"
#include "world/external_loads_3d.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace blockdem::python {
namespace {

// A 2-D scenario is refused by name, as Simulation refuses a 3-D one (the 3-D reader would
// call its 2-D keys unknown).
void refuse_2d(const toml::table& root, const std::string& file) {
    if (scenario_dimension(root, file) == 3) return;
    const toml::node* d = root.get("dimension");
    const std::string what = d ? "is 2" : "is not given, so the scenario is 2-D";
    throw InputError({file, "dimension", d ? static_cast<int>(d->source().begin.line) : 0, 0},
                     what + ": a 2-D scenario runs in blockdem.Simulation (the same step, t, positions, summary); "
                            "a 3-D one has dimension = 3");
}

class Simulation3d {
public:
    Simulation3d(const ScenarioSource& scenario, int threads, std::optional<fs::path> out_dir, bool force, bool history,
                 const std::vector<double>& save_state_s, std::optional<double> save_state_every_s)
        : threads_(threads) {
        RunRequest request = simulation_request(threads, out_dir, force, save_state_s, save_state_every_s);
        request.scenario = scenario.file;
        toml::table root = scenario.parse();
        refuse_2d(root, scenario.file.string());
        run_ = build_watching_signals(threads, settling_stop_, [&](const std::atomic<bool>* stop) {
            request.stop_requested = stop;
            return std::make_unique<ScenarioRun3d>(request, std::move(root), history);
        });
        writes_files_ = out_dir.has_value();
        step(0);  // the state at t = 0 complete before anything reads it
    }

    // A run restarted from a state file, as `blockdem run --restart` and the 2-D
    // Simulation.from_state: the scenario is the state's run folder's scenario.toml unless given,
    // the files go on in that folder unless out_dir names another (then they are copied first),
    // so that they end byte for byte as a run that never stopped. A restart does not settle, so
    // it is built here, not on a second thread. Its rows are not kept in memory (history()):
    // they would start at the state's time.
    Simulation3d(const fs::path& state_file, std::optional<fs::path> scenario_file, int threads,
                 std::optional<fs::path> out_dir, bool force, const std::vector<double>& save_state_s,
                 std::optional<double> save_state_every_s)
        : threads_(threads) {
        const RunRequest request =
            restart_request(state_file, scenario_file, threads, out_dir, force, save_state_s, save_state_every_s);
        run_ = std::make_unique<ScenarioRun3d>(request);
        writes_files_ = true;
        step(0);
    }

    // As the 2-D Simulation: a run with files dropped before finish() ends as an interrupted one.
    ~Simulation3d() {
        if (!writes_files_ || !run_ || run_->finished() || run_->failed()) return;
        try {
            run_->finish();
        } catch (const std::exception&) {
            // (A destructor cannot raise; a failed write was the disk's.)
        }
    }
    Simulation3d(const Simulation3d&) = delete;
    Simulation3d& operator=(const Simulation3d&) = delete;

    std::int64_t step(std::int64_t steps) {
        if (steps < 0) throw py::value_error(fmt::format("step(n) needs n >= 0, got {}", steps));
        const SteppingGuard guard(stepping_);
        return step_in_chunks(steps, threads_, [&](std::int64_t chunk) { return run_->step(chunk); });
    }

    py::object finish() { return json_to_python(run().finish()); }

    const World3d& world() const { return run_->world(); }
    // What changes the world waits for no thread: it refuses while another thread steps.
    World3d& world_to_change() {
        run();
        return run_->world();
    }

    // A body by name or id; only a dynamic body (not taken out of the model) takes loads and velocities.
    std::uint32_t dynamic_body(const py::handle& body) const {
        const World3d& w = world();
        std::uint32_t i = 0;
        if (py::isinstance<py::str>(body)) {
            const auto name = body.cast<std::string>();
            const auto found = std::find_if(w.bodies.begin(), w.bodies.end(), [&](const RigidBody3d& b) { return b.name == name; });
            if (found == w.bodies.end()) throw py::key_error(fmt::format("no body is named '{}'", name));
            i = static_cast<std::uint32_t>(found - w.bodies.begin());
        } else {
            const auto id = body.cast<std::int64_t>();
            if (id < 0 || static_cast<std::size_t>(id) >= w.bodies.size())
                throw py::index_error(fmt::format("body id {} is not in 0 to {}", id, w.bodies.size() - 1));
            i = static_cast<std::uint32_t>(id);
        }
        if (w.kinds[i] != BodyKind3d::dynamic || is_taken_out(w.domain, i))
            throw py::value_error(fmt::format("body '{}' is not dynamic (or has left the model): it takes no loads", w.bodies[i].name));
        return i;
    }

    void set_external_force(const py::handle& body, const std::vector<double>& force_n, const std::vector<double>& torque_n_m) {
        const std::uint32_t i = dynamic_body(body);
        set_external_load(world_to_change(), i, finite_vector(force_n, "force"), finite_vector(torque_n_m, "torque"));
    }

    void set_velocity(const py::handle& body, const std::vector<double>& velocity_m_s, const std::vector<double>& angular_velocity_rad_s) {
        const std::uint32_t i = dynamic_body(body);
        set_body_velocity(world_to_change(), i, finite_vector(velocity_m_s, "velocity"),
                          finite_vector(angular_velocity_rad_s, "angular_velocity"));
    }

    void hold_velocity(const py::handle& body, const std::vector<double>& velocity_m_s, const std::vector<double>& angular_velocity_rad_s) {
        const std::uint32_t i = dynamic_body(body);
        hold_body_velocity(world_to_change(), i, finite_vector(velocity_m_s, "velocity"),
                           finite_vector(angular_velocity_rad_s, "angular_velocity"));
    }

    // (A vector of any other length is refused by name, not cut or padded.)
    static Vec3 finite_vector(const std::vector<double>& v, const char* what) {
        if (v.size() != 3) throw py::value_error(fmt::format("{} must have 3 components (x, y, z), got {}", what, v.size()));
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            throw py::value_error(fmt::format("{} must be finite numbers", what));
        return {v[0], v[1], v[2]};
    }
    ScenarioRun3d& run() {
        if (stepping_) throw std::logic_error("the simulation is being stepped in another thread: wait for step() to return");
        return *run_;
    }

    // N x columns, one row a body, from a body's row function.
    template <class Row>
    py::array_t<double> rows(std::size_t columns, Row row) const {
        const std::size_t n = world().bodies.size();
        py::array_t<double> out({n, columns});
        auto view = out.mutable_unchecked<2>();
        for (std::size_t i = 0; i < n; ++i) {
            const std::vector<double> values = row(i);
            for (std::size_t k = 0; k < columns; ++k) view(i, k) = values[k];
        }
        return out;
    }

private:
    std::atomic<bool> settling_stop_{false};  ///< set by Ctrl-C while the model settles (build_watching_signals); before run_, which keeps a pointer to it
    std::unique_ptr<ScenarioRun3d> run_;
    int threads_ = 1;
    bool writes_files_ = false;
    std::atomic<bool> stepping_{false};
};

std::vector<double> xyz(Vec3 v) { return {v.x, v.y, v.z}; }

}  // namespace

void bind_simulation_3d(py::module_& m) {
    py::class_<Simulation3d>(m, "Simulation3d",
                             "A run of a 3-D scenario (dimension = 3), stepped from Python (docs/python.md, docs/3d.md).")
        .def(py::init<const ScenarioSource&, int, std::optional<fs::path>, bool, bool, const std::vector<double>&,
                      std::optional<double>>(),
             py::arg("scenario"), py::arg("threads") = 2, py::arg("out_dir") = py::none(), py::arg("force") = false,
             py::arg("history") = true, py::kw_only(), py::arg("save_state") = std::vector<double>{},
             py::arg("save_state_every") = py::none(),
             "Builds the world (settling it if the scenario asks). out_dir: write the CLI's files there (history.csv, "
             "energy.csv, summary.json, VTK); history: keep the output rows in memory (history()); save_state: times "
             "[s] to write state files at, save_state_every: an interval [s] (as --save-state, --save-state-every: "
             "into out_dir/state/; finish() before the end writes one too).")
        .def_static(
            "from_state",
            [](const fs::path& state_file, std::optional<fs::path> scenario, int threads, std::optional<fs::path> out_dir,
               bool force, const std::vector<double>& save_state_s, std::optional<double> save_state_every_s) {
                return std::make_unique<Simulation3d>(state_file, scenario, threads, out_dir, force, save_state_s,
                                                      save_state_every_s);
            },
            py::arg("state_file"), py::kw_only(), py::arg("scenario") = py::none(), py::arg("threads") = 2,
            py::arg("out_dir") = py::none(), py::arg("force") = false, py::arg("save_state") = std::vector<double>{},
            py::arg("save_state_every") = py::none(),
            "A 3-D run restarted from its state file, as `blockdem run --restart`: the scenario of the state's run "
            "folder (or `scenario`, a file), its files continued there (or copied to out_dir first).")
        .def("step", &Simulation3d::step, py::arg("n") = 1, "Takes n steps (fewer at the end); returns the steps taken.")
        .def("finish", &Simulation3d::finish, "Finishes the outputs (summary.json with out_dir); returns the summary.")
        .def_property_readonly("t", [](const Simulation3d& s) { return s.world().time_s; }, "[s] time of the state")
        .def_property_readonly("step_index", [](const Simulation3d& s) { return s.world().steps; })
        .def_property_readonly("dt", [](const Simulation3d& s) { return s.world().dt_s; }, "[s]")
        .def_property_readonly("duration", [](const Simulation3d& s) { return s.world().duration_s; }, "[s]")
        .def_property_readonly("done", [](Simulation3d& s) { return s.run().ended(); })
        .def_property_readonly("failed", [](Simulation3d& s) { return s.run().failed(); })
        .def_property_readonly("body_names",
                               [](const Simulation3d& s) {
                                   std::vector<std::string> names;
                                   for (const RigidBody3d& b : s.world().bodies) names.push_back(b.name);
                                   return names;
                               })
        .def_property_readonly(
            "positions",
            [](Simulation3d& s) { return s.rows(3, [&](std::size_t i) { return xyz(position_now_m(s.world(), i)); }); },
            "[m] N x 3 centroids at t (a copy)")
        .def_property_readonly(
            "quaternions",
            [](Simulation3d& s) {
                return s.rows(4, [&](std::size_t i) {
                    const Quaternion q = turn_since_start(s.world(), s.run().monitor().bodies()[i], i);
                    return std::vector<double>{q.w, q.x, q.y, q.z};
                });
            },
            "N x 4 (w, x, y, z): each body's turn since t = 0, as history.csv writes it (a copy)")
        .def_property_readonly(
            "velocities",
            [](Simulation3d& s) { return s.rows(3, [&](std::size_t i) { return xyz(velocity_now_m_s(s.world(), i)); }); },
            "[m/s] N x 3 at t (a copy)")
        .def_property_readonly(
            "angular_velocities",
            [](Simulation3d& s) { return s.rows(3, [&](std::size_t i) { return xyz(s.world().bodies[i].angular_velocity_at_t_rad_s); }); },
            "[rad/s] N x 3 at t, world frame (a copy)")
        .def_property_readonly(
            "masses",
            [](Simulation3d& s) { return s.rows(1, [&](std::size_t i) { return std::vector<double>{s.world().bodies[i].mass_kg}; }); },
            "[kg] N x 1")
        .def("contacts", [](Simulation3d& s) { return contacts_array_3d(s.world()); },
             "The contact points at t as a structured array (a copy): body_a, body_b, x, y, z [m], nx, ny, nz "
             "(from a to b), fx, fy, fz [N] (on b), normal_force, shear_force [N], overlap [m], sliding.")
        .def("history", [](Simulation3d& s) { return history_dict_3d(s.run()); },
             "The output rows so far as numpy arrays (rows x recorded bodies), without CSV.")
        .def("set_external_force", &Simulation3d::set_external_force, py::arg("body"), py::arg("force"),
             py::arg("torque") = std::vector<double>{0.0, 0.0, 0.0},
             "Applies a force [N] (fx, fy, fz) at a dynamic body's centroid and a torque [N m] (tx, ty, tz), world frame, "
             "from the next step on, until changed; its work is booked in the energy balance (external_work_J). body: name or id.")
        .def("clear_external_forces", [](Simulation3d& s) { clear_external_loads(s.world_to_change()); },
             "Removes every external force and held velocity.")
        .def("set_velocity", &Simulation3d::set_velocity, py::arg("body"), py::arg("velocity"),
             py::arg("angular_velocity") = std::vector<double>{0.0, 0.0, 0.0},
             "Sets a dynamic body's velocity [m/s] and angular velocity [rad/s] (world frame) for the next step; the "
             "kinetic energy it adds is booked as external work.")
        .def("hold_velocity", &Simulation3d::hold_velocity, py::arg("body"), py::arg("velocity"),
             py::arg("angular_velocity") = std::vector<double>{0.0, 0.0, 0.0},
             "Drives a dynamic body at the velocity [m/s] and angular velocity [rad/s] (world frame) from the next step "
             "on, until release_velocity(body): each step the force and torque that hold it are its external load "
             "(replacing set_external_force's), their work booked as external_work_J. body: name or id.")
        .def(
            "release_velocity",
            [](Simulation3d& s, const py::handle& body) { release_body_velocity(s.world_to_change(), s.dynamic_body(body)); },
            py::arg("body"), "Ends hold_velocity: the body moves freely from the next step on, with no external load.")
        .def(
            "external_force",
            [](Simulation3d& s, const py::handle& body) {
                const std::uint32_t i = s.dynamic_body(body);
                const ExternalLoads3d& loads = s.world_to_change().external_loads;
                if (!loads.any()) return py::make_tuple(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
                const Vec3 f = loads.force_n[i];
                const Vec3 t = loads.torque_n_m[i];
                return py::make_tuple(f.x, f.y, f.z, t.x, t.y, t.z);
            },
            py::arg("body"),
            "The external load (fx, fy, fz [N], tx, ty, tz [N m], world frame) of the last step: a held body's is the "
            "force that held it.")
        .def("energy", [](Simulation3d& s) { return energy_dict(s.run().world().ledger); },
             "The energy balance at t [J] and its relative error.")
        .def("summary", [](Simulation3d& s) { return json_to_python(s.run().summary(s.run().status())); },
             "The summary of the state now (as summary.json, nothing written), its status \"running\" until the "
             "run ends, then \"completed\", \"interrupted\" or \"failed\" as finish() says.");
}

}  // namespace blockdem::python
