#pragma once
// What a run says about its own trustworthiness (docs/outputs.md, "Checks and warnings"), in 2-D
// and 3-D alike: the
// stable time step at the start and of the live contacts, the deepest overlap, and the energy
// balance, each with the threshold it is judged by; and the warnings a user must read before
// believing the result. Written into summary.json and printed by `blockdem run`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "world/world.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// Balance errors above this fraction of (table work + dissipation + the largest stored term)
/// are reported as a warning (the long-run validation cases stay below 1e-3).
inline constexpr double energy_warning_ratio = 0.01;

/// x as JSON, or null where it is not finite (JSON has no infinity: a bound never met, a side of
/// the model left open).
nlohmann::json finite_or_null(double x);

/// The "checks" object of summary.json.
nlohmann::json run_checks(const World& w);

/// One sentence per problem found (empty: nothing to warn about).
std::vector<std::string> run_warnings(const World& w);

/// The 3-D run's "checks" object (the same keys as 2-D's): its start limit (the highest mode's)
/// and proven bound, the live limit's watch, the deepest overlap and the energy balance
/// (world/run_checks_3d.hpp), each with the threshold it is judged by.
nlohmann::json run_checks_3d(const World3d& w, double start_limit_s, double max_overlap_ratio, double max_energy_error);

/// The 3-D run's warnings, the same sentences as run_warnings' (empty: nothing to warn about).
std::vector<std::string> run_warnings_3d(const World3d& w);

/// What the scenario (root, after --set) leaves to a default the user may not expect: a pair of
/// materials that can touch a dynamic body with neither `e` nor `h_n` ([contact] or its
/// [[contact.pairs]] entry) runs with h_n = 0, an undamped contact. One sentence per problem.
std::vector<std::string> input_warnings(const toml::table& root, const World& w);

}  // namespace blockdem
