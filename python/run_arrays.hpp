#pragma once
// The run's data as numpy: zero-copy read-only views of the world's body arrays, the contact
// points as a structured array, the energy ledger and the rows kept in memory (run/run_trace.hpp).
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "geometry/vec2.hpp"
#include "run/scenario_run.hpp"
#include "run/scenario_run_3d.hpp"
#include "world/energy_ledger.hpp"
#include "world/world.hpp"
#include "world/world_3d.hpp"

namespace blockdem::python {

/// An N x 2 read-only view of a Vec2 array; `owner` (the Simulation) is kept alive by it.
pybind11::array vec2_view(const std::vector<Vec2>& values, const pybind11::object& owner);
/// An N read-only view of a double array.
pybind11::array scalar_view(const std::vector<double>& values, const pybind11::object& owner);
/// Every contact point of the table now (the two end points of each pair; the interior points
/// of sub-contacts are not listed).
pybind11::array contacts_array(const World& w);
/// The 3-D contact points at t as a structured array (a copy): body_a, body_b, x, y, z [m],
/// nx, ny, nz (from a to b), fx, fy, fz [N] (on b), normal_force, shear_force [N], overlap [m], sliding.
pybind11::array contacts_array_3d(const World3d& w);
/// The ledger's terms [J] with the balance's residual and relative error.
pybind11::dict energy_dict(const EnergyLedger& e);
/// The rows of the run's RunTrace as arrays; raises when the run keeps none.
pybind11::dict history_dict(const ScenarioRun& run);
/// A 3-D run's rows kept in memory (run/run_trace_3d.hpp) as numpy arrays (rows x recorded
/// bodies): x, y, z [m], qw, qx, qy, qz, tilt [rad], vx, vy, vz [m/s], wx, wy, wz [rad/s], and
/// energy (energy.csv's columns).
pybind11::dict history_dict_3d(const ScenarioRun3d& run);
/// A JSON value (the summary) as Python dicts, lists and numbers.
pybind11::object json_to_python(const nlohmann::json& value);

}  // namespace blockdem::python
