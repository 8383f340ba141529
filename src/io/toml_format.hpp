#pragma once
// TOML text of a table for the files blockdem writes (the scenario as run, scenario.toml in the
// output folder). toml++ prints every float with 17 significant digits, so a scenario's
// `mu = 0.3` came back as `mu = 0.29999999999999999`; here every float is written in its
// shortest form that reads back to the same double (fmt's "{}"), so the copy shows the values
// as the user typed them. Everything else (strings, integers, booleans, dates) is printed by
// toml++ itself, one value at a time.
#include <string>

#include <toml++/toml.h>

namespace blockdem {

/// The TOML text of root: its keys and values first, then each sub-table as `[a.b]` and each
/// array of tables as `[[a]]`, in toml++'s (sorted) key order. Parsing it gives a table equal
/// to root.
std::string toml_text(const toml::table& root);

/// A float as TOML writes it, in the shortest form that reads back to the same double:
/// 0.3 -> "0.3", 3 -> "3.0", 1e-10 -> "1e-10", infinity -> "inf".
std::string toml_float_text(double value);

}  // namespace blockdem
