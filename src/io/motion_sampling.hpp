#pragma once
// The table's analytic motions against the time step, checked once dt is known (it may be
// derived from the contacts after the motion was read). The step samples the motion once per dt:
// a sine whose period spans fewer than 4 steps has its peaks missed, and at 2 steps or fewer
// (the Nyquist limit) its shape is lost altogether, so that the run shakes the blocks with
// something other than what the scenario says. Sampled motions (records, csv, series) are
// integrated exactly between their samples and are not refused for being fine.
#include <string>

#include "io/toml_reader.hpp"
#include "motion/table_motion.hpp"

namespace blockdem {

/// The fewest time steps a sine or pulse period (or the 1 / frequency of a Ricker wavelet) may span.
inline constexpr double min_steps_per_period = 4.0;

/// Refuses, at its `period` or `frequency` key, a component whose period spans fewer than
/// min_steps_per_period steps of dt_s. motion_table: [table_motion]; key: the component's table
/// in it ("horizontal", "x", ...), which need not be there (the component is then at rest).
void check_motion_sampling(TableReader motion_table, const std::string& key, const ComponentMotion& motion, double dt_s);

}  // namespace blockdem
