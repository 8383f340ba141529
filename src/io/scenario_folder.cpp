#include "io/scenario_folder.hpp"

#include <algorithm>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace blockdem {

std::string folder_not_scenario_message(const std::filesystem::path& folder) {
    std::vector<std::string> scenarios;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.path().extension() == ".toml") scenarios.push_back(entry.path().filename().string());
    std::sort(scenarios.begin(), scenarios.end());
    constexpr std::size_t shown = 8;
    if (scenarios.empty()) return "is a folder, not a scenario file (it holds no .toml file): give a scenario's .toml file";
    const std::size_t more = scenarios.size() > shown ? scenarios.size() - shown : 0;
    scenarios.resize(std::min(scenarios.size(), shown));
    return fmt::format("is a folder, not a scenario file: give one of the scenarios in it ({}{})", fmt::join(scenarios, ", "),
                       more ? fmt::format(" and {} more", more) : "");
}

}  // namespace blockdem
