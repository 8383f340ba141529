#pragma once
// Scenario keys of a table motion component driven by a ground-motion record
// (type = "record") or by a synthetic earthquake-like motion (type = "synthetic").
// The keys, their units and defaults are listed in docs/records.md.
#include <filesystem>

#include "io/toml_reader.hpp"
#include "motion/table_motion.hpp"

namespace blockdem {

/// type = "record": reads the file (relative to scenario_dir), converts it to m/s^2, applies
/// scale or target PGA, time window, taper, padding and baseline correction. The reader has
/// already consumed `type`; this reads the other keys and rejects unknown ones.
AccelerationSeries read_record_motion(TableReader& keys, const std::filesystem::path& scenario_dir);

/// type = "synthetic": seeded Kanai-Tajimi filtered white noise with an envelope, scaled to a
/// target PGA. The reader has already consumed `type`; this reads the rest.
AccelerationSeries read_synthetic_motion(TableReader& keys);

}  // namespace blockdem
