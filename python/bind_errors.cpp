// Python exceptions for blockdem's errors: InputError (bad input; a ValueError) carries the
// file, key, line and body the CLI's message names; SimulationError (the run became unstable or
// penetrated; a RuntimeError); OutputError (a file could not be written; an OSError).
#include <string>

#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "python/bindings.hpp"
#include "world/simulation_error.hpp"

namespace py = pybind11;

namespace blockdem::python {
namespace {

// The body a key names: "bodies.NAME.key" (io/toml_reader.hpp names array entries by their
// name); None for keys of other tables.
py::object body_of_key(const std::string& key) {
    const std::string prefix = "bodies.";
    if (key.rfind(prefix, 0) != 0) return py::none();
    const std::size_t end = key.find('.', prefix.size());
    return py::str(key.substr(prefix.size(), end == std::string::npos ? std::string::npos : end - prefix.size()));
}

void raise_input_error(PyObject* type, const InputError& e) {
    py::object error = py::reinterpret_borrow<py::object>(type)(py::str(e.what()));
    const InputLocation& where = e.where();
    error.attr("file") = where.file.empty() ? py::object(py::none()) : py::object(py::str(where.file));
    error.attr("key") = where.key.empty() ? py::object(py::none()) : py::object(py::str(where.key));
    error.attr("line") = where.line > 0 ? py::object(py::int_(where.line)) : py::object(py::none());
    error.attr("body") = body_of_key(where.key);
    error.attr("problem") = py::str(e.problem());
    PyErr_SetObject(type, error.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
    static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
    input_error.doc() = "Bad input, with the attributes file, key, line, body (None where unknown) and problem.";
    static py::exception<SimulationError> simulation_error(m, "SimulationError", PyExc_RuntimeError);
    static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            raise_input_error(input_error.ptr(), e);
        } catch (const SimulationError& e) {
            PyErr_SetString(simulation_error.ptr(), e.what());
        } catch (const OutputError& e) {
            PyErr_SetString(output_error.ptr(), e.what());
        }
    });
}

}  // namespace blockdem::python
