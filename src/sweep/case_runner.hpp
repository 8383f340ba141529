#pragma once
// One case of a sweep, end to end and in memory: the scenario (parsed once, copied per case),
// the case's --set assignments and record, the run with the response monitor and the
// rocking-mode observer, and the outcome per body. A case never throws for a bad parameter or
// an unstable run: the error goes into its result, so that the other cases go on.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "sweep/sweep_plan.hpp"

namespace blockdem::sweep {

/// dem: the distinct element model of the scenario. housner: the project's independent
/// equation-of-motion solver (analysis/housner_rocking) for the scenario's one rectangular
/// block on the table, as a reference on the same grid.
enum class Solver { dem, housner };

struct CaseOptions {
    Solver solver = Solver::dem;
    bool stop_when_overturned = true;   ///< end a DEM run once every block lies past (alpha + 90 deg) / 2
    double housner_dt_s = 1.0e-4;       ///< [s] RK4 step of the Housner solver
    double housner_restitution = -1.0;  ///< [-] r per impact; negative: Housner's 1 - 1.5 sin^2 alpha
    std::filesystem::path histories_dir;///< not empty: <dir>/<case id>/history.csv for every case
};

/// The scenario a sweep varies: read once.
struct SweepScenario {
    std::filesystem::path file;
    toml::table root;
    std::vector<std::string> body_names;   ///< the dynamic bodies of the unvaried scenario (columns)
};

/// Reads and validates the unvaried scenario. Throws InputError.
SweepScenario load_sweep_scenario(const std::filesystem::path& file);
/// The same for a scenario already parsed (the Python module's blockdem.sweep): `file` names it
/// in messages, and its folder resolves relative file names.
SweepScenario load_sweep_scenario(toml::table root, const std::filesystem::path& file);

struct BodyOutcome {
    bool overturned = false;
    double overturning_time_s = -1.0;     ///< [s], -1 when it did not overturn
    double peak_rotation_rad = 0.0;       ///< [rad] peak |rotation|
    double peak_sliding_m = 0.0;          ///< [m] peak |slip of the base midpoint relative to the table| (x)
    double residual_sliding_m = 0.0;      ///< [m] that slip at the end, signed (+x)
    std::string mode;                     ///< rocking mode (analysis/rocking_mode.hpp)
    int rocking_period_ratio = 0;         ///< [-] rocking period / table period (0: not rocking)
    double phase_lag_deg = 0.0;           ///< [deg] rotation behind the table acceleration (in/anti-phase)
    // The outcome of world/outcome.hpp (docs/outputs.md, "Outcomes"), as `blockdem run` reports it.
    std::string outcome = "stable";       ///< stable, rocked, slid, rocked_and_slid, overturned, fell, left_model
    double outcome_time_s = -1.0;         ///< [s] time of the deciding event, -1 for stable
    bool failed = false;                  ///< overturned, fell or left_model: what fragility counts
};

struct CaseResult {
    std::int64_t id = 0;
    std::string status;        ///< "completed", "failed" (unstable run) or "error" (bad input)
    std::string error;         ///< the message when not completed
    double wall_s = 0.0;       ///< [s]
    double table_pga_m_s2 = 0.0;  ///< [m/s^2] peak horizontal table acceleration as run
    std::vector<std::optional<BodyOutcome>> bodies;   ///< aligned with SweepScenario::body_names
};

/// Refuses (InputError) a plan with an axis none of whose values can be read into the scenario
/// (an unknown key, a value of the wrong type or range), each value tried with the first case's
/// other values and failing on the axis's own key, before any case runs: a value that fails only
/// in some cases is recorded with them, an axis that fails in all would only fill the table with
/// the same error.
void check_axes_readable(const SweepScenario& scenario, const SweepPlan& plan);

/// Thrown out of run_case when `cancel` turns true (Ctrl-C): the case is not finished and is
/// not recorded, so that a rerun does it again.
struct CaseCancelled {};

/// Runs one case. cancel may be null.
CaseResult run_case(const SweepScenario& scenario, const SweepPlan& plan, const SweepCase& c,
                    const CaseOptions& options, const std::atomic<bool>* cancel);

}  // namespace blockdem::sweep
