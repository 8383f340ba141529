#pragma once
// `--set key=value`: overrides any scenario key by its dotted path before the scenario is read.
// A path segment selects a table key, or in an array of tables ([[bodies]]) an element by its
// name or its 0-based index: `bodies.block.width=0.3`, `bodies.1.width=0.3`,
// `contact.h_s=0.5`, `table_motion.horizontal.amplitude=300`. The value is read as a TOML
// value (number, boolean, string in quotes, array); anything that is not valid TOML is taken
// as a plain string, so `table_motion.horizontal.type=sine` works without quotes.
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace blockdem {

/// Applies "key=value" assignments to root in order. Throws InputError (key "--set ...") when
/// an assignment is malformed or its path runs through something that is not a table.
void apply_overrides(toml::table& root, const std::vector<std::string>& assignments);

/// apply_overrides for the scenario read from file: its InputError names that file, as an error
/// in the file itself would, so that both dimensions' loaders report a bad `--set` the same way.
void apply_overrides_to_scenario(toml::table& root, const std::vector<std::string>& assignments,
                                 const std::filesystem::path& file);

}  // namespace blockdem
