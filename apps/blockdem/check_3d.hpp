#pragma once
// `blockdem check` on a `dimension = 3` scenario (check_3d.cpp).
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace blockdem::cli {

/// Loads the 3-D scenario as `blockdem run` does (io/scenario_3d.hpp: errors are InputErrors,
/// exit 2) and prints its derived quantities.
void check_scenario_3d(toml::table root, const std::filesystem::path& file, const std::vector<std::string>& overrides);

}  // namespace blockdem::cli
