#pragma once
// The Python module blockdem._core (docs/python.md): one bind_*.cpp per topic, each adding its
// classes and functions to the module; module.cpp calls them in order (errors first, so that the
// others can raise them). A new topic is a new bind_*.cpp and one line in module.cpp.
#include <cmath>

#include <fmt/format.h>
#include <pybind11/pybind11.h>

namespace blockdem::python {

/// Raises ValueError naming the argument unless value is finite and > 0.
inline void require_positive(double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value))
        throw pybind11::value_error(fmt::format("{} must be > 0, got {}", name, value));
}

void bind_errors(pybind11::module_& m);
void bind_scenario(pybind11::module_& m);
void bind_simulation(pybind11::module_& m);
void bind_simulation_3d(pybind11::module_& m);
void bind_study(pybind11::module_& m);
void bind_analysis(pybind11::module_& m);
void bind_limit(pybind11::module_& m);
void bind_laws(pybind11::module_& m);
void bind_calibration(pybind11::module_& m);

}  // namespace blockdem::python
