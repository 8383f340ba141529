#pragma once
// A folder given where a scenario file belongs (`blockdem run examples/paper`): the message
// names the folder and the scenarios in it, so that the fix is one word away.
#include <filesystem>
#include <string>

namespace blockdem {

/// "is a folder, not a scenario file: give one of the scenarios in it (a.toml, b.toml)", or
/// "... (it holds no .toml file)". At most 8 names, sorted, then a count.
std::string folder_not_scenario_message(const std::filesystem::path& folder);

}  // namespace blockdem
