#pragma once
// Scenario keys of the outcomes (docs/scenario.md): [simulation] domain, the model's extent
// (world/model_domain.hpp), and the [outcomes] thresholds (world/outcome.hpp).
//   [simulation] domain = [[x_min, y_min], [x_max, y_max]]   [m]; must contain every body at t = 0
//   [outcomes] rocking_ratio, slip_ratio, fall_drop_ratio, displaced_ratio [-], rest_speed [m/s],
//              support_window [s]: each a number >= 0
#include <optional>

#include "io/toml_reader.hpp"
#include "world/model.hpp"

namespace blockdem {

/// [simulation] domain, or nullopt when absent. Throws InputError for a malformed box.
std::optional<DomainBox> read_domain(TableReader& simulation);

/// Throws InputError at [simulation] domain when the box does not contain every body's corners
/// as given (t = 0, before any settling).
void check_domain_contains_bodies(TableReader simulation, const Model& model);

/// [outcomes]; rejects unknown keys, negative values and values that are not numbers.
OutcomeThresholds read_outcome_thresholds(TableReader outcomes);

}  // namespace blockdem
