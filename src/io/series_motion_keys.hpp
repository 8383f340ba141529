#pragma once
// [table_motion.horizontal] or [table_motion.vertical] with type = "series": the accelerations
// written in the scenario itself, `values` at a time step `dt` [s] from t = 0, in `unit`
// (default m/s^2) times `scale` (default 1). It is how the Python module passes a numpy array
// of accelerations (docs/python.md); a CSV file ("csv") is the same series kept on disk.
#include "io/toml_reader.hpp"
#include "motion/table_motion.hpp"

namespace blockdem {

/// Reads the keys of a "series" motion (the reader is at the component's table). A value that is
/// not a finite number is refused with its index.
AccelerationSeries read_series_motion_keys(TableReader& keys);

}  // namespace blockdem
