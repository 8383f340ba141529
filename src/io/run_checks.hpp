#pragma once
// What a run says about its own trustworthiness (docs/outputs.md, "Checks and warnings"): the
// stable time step at the start and of the live contacts, the deepest overlap, and the energy
// balance, each with the threshold it is judged by; and the warnings a user must read before
// believing the result. Written into summary.json and printed by `blockdem run`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "world/world.hpp"

namespace blockdem {

/// Balance errors above this fraction of (table work + dissipation + the largest stored term)
/// are reported as a warning (the long-run validation cases stay below 1e-3).
inline constexpr double energy_warning_ratio = 0.01;

/// The "checks" object of summary.json.
nlohmann::json run_checks(const World& w);

/// One sentence per problem found (empty: nothing to warn about).
std::vector<std::string> run_warnings(const World& w);

/// What the scenario (root, after --set) leaves to a default the user may not expect: a pair of
/// materials that can touch a dynamic body with neither `e` nor `h_n` ([contact] or its
/// [[contact.pairs]] entry) runs with h_n = 0, an undamped contact. One sentence per problem.
std::vector<std::string> input_warnings(const toml::table& root, const World& w);

}  // namespace blockdem
