#pragma once
// The runs of a convergence study (`blockdem converge`, docs/convergence.md) after its base
// run: dt/2 and dt/4; with the stiffness study, 0.5 x and 2 x the contact stiffness at dt/2;
// with an ensemble, N copies of the base run at the base dt with gravity perturbed by a tiny
// relative amount. Each run is the scenario with `--set` overrides added after the user's, so
// that it goes through the ordinary run path.
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace blockdem {

struct ConvergenceOptions {
    bool stiffness = false;          ///< also run at 0.5 x and 2 x kn and ks
    int ensemble = 0;                ///< number of perturbed copies (0: none)
    double perturbation = 1e-9;      ///< [-] largest relative perturbation of gravity
};

enum class RunRole { refinement, stiffness, ensemble };
std::string to_string(RunRole role);

struct PlannedRun {
    std::string label;                   ///< also its folder's name in the study folder
    RunRole role = RunRole::refinement;
    std::vector<std::string> overrides;  ///< "key=value", applied after the user's --set
    std::string description;             ///< e.g. "dt/2 = 5e-05 s"
};

/// The label and folder of the base run (the scenario as given, with the user's --set).
inline constexpr const char* base_run_label = "dt";

/// The runs that follow the base run, in the order they are run: dt_2, dt_4, then kn_x0.5 and
/// kn_x2, then ensemble_1 .. ensemble_N. scenario_as_run is the base run's scenario.toml (after
/// the user's --set); base_dt_s the time step it ran with. Throws InputError when the ensemble
/// is asked for a scenario without gravity (nothing to perturb) or a negative size.
std::vector<PlannedRun> plan_follow_up_runs(const toml::table& scenario_as_run, double base_dt_s, const ConvergenceOptions& options);

/// The relative perturbations of the ensemble members: +-magnitude x k / ceil(n / 2),
/// alternating in sign (+1, -1, +2, -2, ... of magnitude / ceil(n / 2)), none of them zero.
std::vector<double> ensemble_perturbations(int n, double magnitude);

/// The stiffness factors of the stiffness study, in the order of its runs (1 x is dt_2).
inline constexpr double stiffness_factors[] = {0.5, 1.0, 2.0};

/// A number as a TOML float that reads back as the same double ("2000000000.0", "5e-05").
std::string toml_float(double x);

}  // namespace blockdem
