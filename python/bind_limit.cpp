// blockdem.limit_analysis: the collapse multiplier of a scenario's blocks by the LP of
// analysis/limit_analysis.hpp, the same solver as `blockdem limit` (docs/limit_analysis.md).
//   r = blockdem.limit_analysis(scenario, direction="+x", non_associative=False)
//   r["lambda"], r["mechanism"] (bodies x 3: vx, vy, rotation), r["interfaces"] (dict of arrays)
// Nothing is computed here: the scenario is loaded as the CLI loads it (its checks and
// messages), the LP solved in C++, its result copied into numpy arrays.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "analysis/limit_analysis.hpp"
#include "python/bindings.hpp"
#include "python/scenario_source.hpp"

namespace py = pybind11;

namespace blockdem::python {
namespace {

/// "+x", "-x" or a 2-vector (any length: made unit) for the live load lambda m g.
Vec2 live_load_direction(const py::handle& direction) {
    if (py::isinstance<py::str>(direction)) {
        const auto text = direction.cast<std::string>();
        if (text == "+x") return {1.0, 0.0};
        if (text == "-x") return {-1.0, 0.0};
        throw py::value_error(fmt::format("direction must be \"+x\", \"-x\" or a 2-vector, got \"{}\"", text));
    }
    const auto v = direction.cast<std::array<double, 2>>();
    const double length = std::hypot(v[0], v[1]);
    if (!std::isfinite(length) || length == 0.0)
        throw py::value_error(fmt::format("direction must be a finite, non-zero 2-vector, got ({}, {})", v[0], v[1]));
    return {v[0] / length, v[1] / length};
}

template <class Row>
py::array_t<double> table(std::size_t rows, std::size_t columns, Row row) {
    py::array_t<double> a({rows, columns});
    auto out = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < rows; ++i) {
        const std::vector<double> values = row(i);
        for (std::size_t j = 0; j < columns; ++j) out(i, j) = values[j];
    }
    return a;
}

py::dict interfaces_dict(const Model& model, const LimitResult& r) {
    const std::size_t n = r.interfaces.size();
    const bool collapse = r.status == LimitStatus::collapse;
    const double nan = std::nan("");
    py::array_t<std::uint32_t> body_a(static_cast<py::ssize_t>(n)), body_b(static_cast<py::ssize_t>(n));
    py::list names_a, names_b, motion;
    for (std::size_t k = 0; k < n; ++k) {
        const BlockInterface& f = r.interfaces[k];
        body_a.mutable_at(k) = f.body_a;
        body_b.mutable_at(k) = f.body_b;
        names_a.append(model.bodies[f.body_a].name);
        names_b.append(model.bodies[f.body_b].name);
        motion.append(collapse ? to_string(r.kinematics[k].motion) : "");
    }
    auto per_end = [&](auto value) {
        return table(n, 2, [&](std::size_t k) -> std::vector<double> {
            if (!collapse) return {nan, nan};
            const std::array<double, 2> v = value(k);
            return {v[0], v[1]};
        });
    };
    py::dict d;
    d["body_a"] = body_a;
    d["body_b"] = body_b;
    d["name_a"] = py::array(names_a);
    d["name_b"] = py::array(names_b);
    d["end_0"] = table(n, 2, [&](std::size_t k) -> std::vector<double> { return {r.interfaces[k].end_m[0].x, r.interfaces[k].end_m[0].y}; });
    d["end_1"] = table(n, 2, [&](std::size_t k) -> std::vector<double> { return {r.interfaces[k].end_m[1].x, r.interfaces[k].end_m[1].y}; });
    d["normal"] = table(n, 2, [&](std::size_t k) -> std::vector<double> { return {r.interfaces[k].normal.x, r.interfaces[k].normal.y}; });
    d["mu"] = table(n, 1, [&](std::size_t k) -> std::vector<double> { return {r.interfaces[k].mu}; }).attr("ravel")();
    d["normal_force"] = per_end([&](std::size_t k) { return r.forces[k].normal_N; });
    d["shear_force"] = per_end([&](std::size_t k) { return r.forces[k].shear_N; });
    d["thrust_point"] = per_end([&](std::size_t k) { return std::array<double, 2>{r.forces[k].thrust_point_m.x, r.forces[k].thrust_point_m.y}; });
    d["thrust_fraction"] =
        table(n, 1, [&](std::size_t k) -> std::vector<double> { return {collapse ? r.forces[k].thrust_fraction : nan}; }).attr("ravel")();
    d["opening"] = per_end([&](std::size_t k) { return r.kinematics[k].opening; });
    d["slip"] = per_end([&](std::size_t k) { return r.kinematics[k].slip; });
    d["motion"] = py::array(motion);
    return d;
}

py::dict limit_analysis(const ScenarioSource& scenario, const py::handle& direction, bool non_associative, int max_iterations) {
    LimitOptions options;
    options.live_load_direction = live_load_direction(direction);
    if (non_associative) options.friction = FrictionFlow::non_associative;
    if (max_iterations < 1) throw py::value_error(fmt::format("max_iterations must be 1 or more, got {}", max_iterations));
    options.max_iterations = max_iterations;
    const LoadedScenario loaded = scenario.load(false);
    const Model& model = loaded.model;
    LimitResult r;
    try {
        py::gil_scoped_release release;   // (an arch's or a wall's LPs take a while)
        r = solve_limit_analysis(model, options);
    } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
    }
    const bool collapse = r.status == LimitStatus::collapse;
    py::list names;
    for (const BodyDef& b : model.bodies) names.append(b.name);
    py::dict d;
    d["status"] = to_string(r.status);
    d["lambda"] = collapse ? r.lambda : std::nan("");
    d["direction"] = py::make_tuple(options.live_load_direction.x, options.live_load_direction.y);
    d["friction"] = non_associative ? "non_associative" : "associative";
    d["bodies"] = py::array(names);
    // Per body: the centroid's virtual velocity and the rotation, in the LP's free scale (zero
    // for fixed and driven bodies); NaN without a collapse.
    d["mechanism"] = table(model.bodies.size(), 3, [&](std::size_t i) -> std::vector<double> {
        if (!collapse) return {std::nan(""), std::nan(""), std::nan("")};
        return {r.mechanism[i].velocity.x, r.mechanism[i].velocity.y, r.mechanism[i].rotation};
    });
    d["interfaces"] = interfaces_dict(model, r);
    d["unsupported"] = r.unsupported;
    d["iterations"] = r.iterations;
    d["converged"] = r.converged;
    d["lp_solve_s"] = r.lp_solve_s;
    return d;
}

}  // namespace

void bind_limit(py::module_& m) {
    m.def("limit_analysis", &limit_analysis, py::arg("scenario"), py::kw_only(), py::arg("direction") = "+x",
          py::arg("non_associative") = false, py::arg("max_iterations") = 200,
          "The collapse multiplier lambda of the scenario's blocks under a live load lambda m g along direction "
          "(\"+x\", \"-x\" or a 2-vector), by the LP of `blockdem limit`. Returns a dict: status (\"collapse\", "
          "\"no_equilibrium\", \"unbounded\"), lambda, bodies, mechanism (bodies x 3: vx, vy, rotation [1/m]), "
          "interfaces (dict of arrays: body_a, body_b, end_0, end_1, normal, mu, normal_force and shear_force per end "
          "[N] on b, thrust_point [m], thrust_fraction, opening, slip, motion), unsupported, iterations, converged.");
}

}  // namespace blockdem::python
