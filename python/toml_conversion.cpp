#include "python/toml_conversion.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace py = pybind11;

namespace blockdem::python {
namespace {

std::string join(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }

// numpy scalars and arrays become Python scalars and lists first (tolist), so that one path
// handles both.
py::object plain(const py::handle& value) {
    if (py::hasattr(value, "tolist") && py::hasattr(value, "dtype")) return value.attr("tolist")();
    return py::reinterpret_borrow<py::object>(value);
}

double finite(const py::handle& value, const std::string& where) {
    const double x = value.cast<double>();
    if (!std::isfinite(x)) throw py::value_error(fmt::format("{}: {} is not a finite number", where, x));
    return x;
}

bool is_sequence(const py::handle& v) { return py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v); }

void push_value(toml::array& array, const py::handle& raw, const std::string& where);

template <class Sink>
void put(Sink&& sink, const py::handle& raw, const std::string& where) {
    const py::object value = plain(raw);
    if (py::isinstance<py::bool_>(value)) {
        sink(toml::value<bool>(value.cast<bool>()));
    } else if (py::isinstance<py::int_>(value)) {
        sink(toml::value<std::int64_t>(value.cast<std::int64_t>()));
    } else if (py::isinstance<py::float_>(value)) {
        sink(toml::value<double>(finite(value, where)));
    } else if (py::isinstance<py::str>(value)) {
        sink(toml::value<std::string>(value.cast<std::string>()));
    } else if (py::isinstance<py::dict>(value)) {
        sink(table_from_dict(value, where));
    } else if (is_sequence(value)) {
        toml::array array;
        std::size_t i = 0;
        for (const py::handle item : value) push_value(array, item, fmt::format("{}[{}]", where, i++));
        sink(std::move(array));
    } else {
        throw py::type_error(fmt::format("{}: a {} cannot be a scenario value (bool, int, float, str, list, dict or numpy array)",
                                         where, py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
    }
}

void push_value(toml::array& array, const py::handle& raw, const std::string& where) {
    put([&](auto&& node) { array.push_back(std::forward<decltype(node)>(node)); }, raw, where);
}

py::object python_value(const toml::node& node) {
    if (const auto* t = node.as_table()) return dict_from_table(*t);
    if (const auto* a = node.as_array()) {
        py::list list;
        for (const toml::node& item : *a) list.append(python_value(item));
        return list;
    }
    if (auto v = node.value_exact<bool>()) return py::bool_(*v);
    if (auto v = node.value_exact<std::int64_t>()) return py::int_(*v);
    if (auto v = node.value_exact<double>()) return py::float_(*v);
    if (auto v = node.value_exact<std::string>()) return py::str(*v);
    std::ostringstream text;  // (dates and times: as written)
    node.visit([&](const auto& n) { text << n; });
    return py::str(text.str());
}

}  // namespace

toml::table table_from_dict(const py::handle& dict, const std::string& where) {
    if (!py::isinstance<py::dict>(dict))
        throw py::type_error(fmt::format("{}: must be a dict", where.empty() ? "the scenario" : where));
    toml::table table;
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(dict)) {
        if (!py::isinstance<py::str>(key)) throw py::type_error(fmt::format("{}: keys must be strings", where));
        set_value(table, key.cast<std::string>(), value, where);
    }
    return table;
}

void set_value(toml::table& table, const std::string& key, const py::handle& value, const std::string& where) {
    put([&](auto&& node) { table.insert_or_assign(key, std::forward<decltype(node)>(node)); }, value, join(where, key));
}

py::dict dict_from_table(const toml::table& table) {
    py::dict dict;
    for (const auto& [key, node] : table) dict[py::str(std::string(key.str()))] = python_value(node);
    return dict;
}

}  // namespace blockdem::python
