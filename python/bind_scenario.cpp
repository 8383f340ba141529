// blockdem.Scenario: from a file, TOML text or a dict, checked as the CLI checks it, and edited
// from Python (set a key as --set does, add or remove bodies and assemblies, merge contact keys,
// set a table motion, a numpy array of accelerations included). Every edit is checked at once;
// an edit that fails leaves the scenario as it was.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "io/input_error.hpp"
#include "io/overrides.hpp"
#include "io/toml_format.hpp"
#include "io/scenario_3d.hpp"
#include "python/bindings.hpp"
#include "python/scenario_source.hpp"
#include "python/toml_conversion.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace blockdem::python {
namespace {

fs::path named_in(const std::optional<fs::path>& base_dir, const char* name) {
    return base_dir ? *base_dir / name : fs::path(name);
}

ScenarioSource checked(ScenarioSource s) {
    // (A 3-D scenario is checked by the 3-D reader: blockdem.Simulation3d runs it.)
    toml::table root = s.parse();
    if (scenario_dimension(root, s.file.string()) == 3)
        load_scenario_3d(std::move(root), s.file, {});
    else
        s.load(false);
    return s;
}

// Applies an edit to a copy, checks the copy, and only then keeps it.
template <class Edit>
void edit(ScenarioSource& s, Edit&& change) {
    toml::table root = s.parse();
    change(root);
    s = checked({toml_text(root), s.file});
}

std::string file_text(const fs::path& path) {
    load_toml_file(path);  // (the CLI's checks and messages: a folder, a missing file, a syntax error)
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

toml::array& array_of_tables(toml::table& root, const char* key) {
    if (!root.contains(key)) root.insert(key, toml::array{});
    toml::array* array = root[key].as_array();
    if (!array) throw py::value_error(fmt::format("the scenario's '{}' is not an array of tables", key));
    return *array;
}

// The TOML text of one Python value, as --set reads it.
std::string toml_value_text(const py::handle& value, const std::string& key) {
    if (py::isinstance<py::dict>(value))
        throw py::type_error(fmt::format("{}: set() takes a value; merge a table with set_contact() or add_body()", key));
    toml::table holder;
    set_value(holder, "v", value, key);
    std::ostringstream text;
    holder.get("v")->visit([&](const auto& node) { text << node; });
    return text.str();
}

void set_motion(ScenarioSource& s, const py::object& accelerations, std::optional<double> dt_s, const std::string& direction,
                const std::string& unit, const std::optional<py::dict>& motion) {
    if (direction != "horizontal" && direction != "vertical")
        throw py::value_error(fmt::format("direction must be \"horizontal\" or \"vertical\", got \"{}\"", direction));
    const std::string where = "table_motion." + direction;
    toml::table component;
    if (motion) {
        if (!accelerations.is_none()) throw py::type_error("give either accelerations (with dt) or a motion dict, not both");
        component = table_from_dict(*motion, where);
    } else {
        if (accelerations.is_none()) throw py::type_error("set_motion needs accelerations (with dt) or a motion dict");
        if (!dt_s) throw py::type_error("accelerations need their time step: dt=... [s]");
        const auto samples = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(accelerations);
        if (!samples) throw py::type_error(fmt::format("{}: accelerations must be a 1-D array of numbers", where));
        if (samples.ndim() != 1)
            throw py::value_error(fmt::format("{}: accelerations must be a 1-D array, got {} dimensions", where, samples.ndim()));
        toml::array values;
        for (py::ssize_t i = 0; i < samples.shape(0); ++i) {
            const double a = samples.at(i);
            if (!std::isfinite(a))
                throw py::value_error(fmt::format("{}: acceleration {} (sample {}, t = {:g} s) is not a finite number", where,
                                                  a, i, static_cast<double>(i) * *dt_s));
            values.push_back(a);
        }
        component.insert("type", "series");
        component.insert("dt", *dt_s);
        component.insert("unit", unit);
        component.insert("values", std::move(values));
    }
    edit(s, [&](toml::table& root) {
        if (!root.contains("table_motion")) root.insert("table_motion", toml::table{});
        toml::table* motions = root["table_motion"].as_table();
        if (!motions) throw py::value_error("the scenario's table_motion is not a table");
        motions->insert_or_assign(direction, component);
    });
}

}  // namespace

void bind_scenario(py::module_& m) {
    py::class_<ScenarioSource>(m, "Scenario", "A scenario (docs/scenario.md), checked as `blockdem run` checks it.")
        .def_static(
            "from_file", [](const fs::path& path) { return checked({file_text(path), path}); }, py::arg("path"),
            "Reads a scenario file (TOML). Raises InputError naming the file, key and line.")
        .def_static(
            "from_toml",
            [](const std::string& text, std::optional<fs::path> base_dir) {
                return checked({text, named_in(base_dir, "<toml>")});
            },
            py::arg("text"), py::arg("base_dir") = py::none(),
            "A scenario from TOML text; relative file names are read from base_dir (default: the working folder).")
        .def_static(
            "from_dict",
            [](const py::dict& dict, std::optional<fs::path> base_dir) {
                return checked({toml_text(table_from_dict(dict, "")), named_in(base_dir, "<dict>")});
            },
            py::arg("scenario"), py::arg("base_dir") = py::none(),
            "A scenario from a dict shaped as the TOML file (lists of dicts for [[bodies]]); messages name lines of "
            "its to_toml() text.")
        .def_property_readonly("file", [](const ScenarioSource& s) { return s.file.string(); })
        .def("to_dict", [](const ScenarioSource& s) { return dict_from_table(s.parse()); })
        .def("to_toml", [](const ScenarioSource& s) { return s.text; })
        .def(
            "set",
            [](ScenarioSource& s, const std::string& key, const py::handle& value) {
                const std::string assignment = key + "=" + toml_value_text(value, key);
                edit(s, [&](toml::table& root) { apply_overrides(root, {assignment}); });
            },
            py::arg("key"), py::arg("value"),
            "Sets one key as `--set key=value` does: scenario.set(\"bodies.block.width\", 0.3).")
        .def(
            "add_body",
            [](ScenarioSource& s, const py::dict& body) {
                toml::table table = table_from_dict(body, "bodies");
                edit(s, [&](toml::table& root) { array_of_tables(root, "bodies").push_back(table); });
            },
            py::arg("body"), "Adds a [[bodies]] entry given as a dict.")
        .def(
            "remove_body",
            [](ScenarioSource& s, const std::string& name) {
                edit(s, [&](toml::table& root) {
                    toml::array& bodies = array_of_tables(root, "bodies");
                    for (auto it = bodies.begin(); it != bodies.end(); ++it)
                        if (it->is_table() && (*it->as_table())["name"].value<std::string>() == name) {
                            bodies.erase(it);
                            return;
                        }
                    throw py::key_error(fmt::format("no [[bodies]] entry is named '{}'", name));
                });
            },
            py::arg("name"))
        .def(
            "add_assembly",
            [](ScenarioSource& s, const py::dict& assembly) {
                toml::table table = table_from_dict(assembly, "assemblies");
                edit(s, [&](toml::table& root) { array_of_tables(root, "assemblies").push_back(table); });
            },
            py::arg("assembly"), "Adds an [[assemblies]] entry given as a dict.")
        .def(
            "set_contact",
            [](ScenarioSource& s, const py::dict& keys) {
                toml::table merged = table_from_dict(keys, "contact");
                edit(s, [&](toml::table& root) {
                    if (!root.contains("contact")) root.insert("contact", toml::table{});
                    toml::table* contact = root["contact"].as_table();
                    if (!contact) throw py::value_error("the scenario's contact is not a table");
                    for (auto&& [key, node] : merged) contact->insert_or_assign(key, node);
                });
            },
            py::arg("keys"), "Merges keys into [contact]: scenario.set_contact({\"mu\": 0.6}).")
        .def("set_motion", &set_motion, py::arg("accelerations") = py::none(), py::arg("dt") = py::none(),
             py::arg("direction") = "horizontal", py::arg("unit") = "m/s^2", py::arg("motion") = py::none(),
             "Sets [table_motion.<direction>]: a 1-D array of accelerations at a step dt [s] from t = 0 (NaN "
             "refused), or a motion dict ({\"type\": \"sine\", ...}).")
        .def("__repr__", [](const ScenarioSource& s) { return fmt::format("<blockdem.Scenario {}>", s.file.string()); });
}

}  // namespace blockdem::python
