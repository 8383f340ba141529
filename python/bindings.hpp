#pragma once
// The Python module blockdem._core (docs/python.md): one bind_*.cpp per topic, each adding its
// classes and functions to the module; module.cpp calls them in order (errors first, so that the
// others can raise them). A new topic is a new bind_*.cpp and one line in module.cpp.
#include <pybind11/pybind11.h>

namespace blockdem::python {

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
