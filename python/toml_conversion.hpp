#pragma once
// Python values to TOML and back, for Scenario.from_dict, its setters and to_dict. A value that
// TOML cannot hold (None, an object, a 3-D array, NaN) is refused with a TypeError or ValueError
// naming its key.
#include <string>

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

namespace blockdem::python {

/// A dict (str keys) as a TOML table; `where` names it in messages ("" for the top).
toml::table table_from_dict(const pybind11::handle& dict, const std::string& where);
/// Sets table[key] to a Python value (bool, int, float, str, sequences and numpy arrays of
/// them, dicts, sequences of dicts as arrays of tables).
void set_value(toml::table& table, const std::string& key, const pybind11::handle& value, const std::string& where);
/// A TOML table as a dict of Python values (arrays as lists).
pybind11::dict dict_from_table(const toml::table& table);

}  // namespace blockdem::python
