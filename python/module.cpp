// blockdem._core: the extension the package blockdem (python/blockdem/__init__.py) re-exports.
#include "python/bindings.hpp"

PYBIND11_MODULE(_core, m) {
    m.doc() = "blockdem: 2-D rigid blocks under earthquake shaking (distinct element method)";
    blockdem::python::bind_errors(m);
    blockdem::python::bind_scenario(m);
    blockdem::python::bind_simulation(m);
    blockdem::python::bind_simulation_3d(m);
    blockdem::python::bind_study(m);
    blockdem::python::bind_analysis(m);
    blockdem::python::bind_limit(m);
    blockdem::python::bind_laws(m);
    blockdem::python::bind_calibration(m);
}
