#pragma once
// The verdict of a convergence study (`blockdem converge`, docs/convergence.md): compares the
// per-body summaries of runs at dt, dt/2 and dt/4, of runs at other contact stiffnesses, and of
// an ensemble of tiny perturbations, and says per body and overall whether the answer is
// converged, not converged, or chaotic (sensitive to the initial conditions). Pure functions
// of the summaries: no run is started here.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace blockdem {

/// What summary.json says about one dynamic body: the quantities a study compares. A 3-D
/// summary gives the same three numbers in its own terms (quantities_3d_json): the peak tilt
/// about any horizontal axis as the peak rotation, and the slip vector's length as the slip.
struct BodyOutcome {
    std::string name;
    double peak_rotation_rad = 0.0;            ///< [rad] peak |rotation| (3-D: peak tilt)
    double peak_slip_m = 0.0;                  ///< [m] peak |base slip| (3-D: peak |slip vector|)
    double final_slip_m = 0.0;                 ///< [m] base slip at the end (signed; 3-D: |slip vector|)
    bool overturned = false;
    std::optional<double> overturning_time_s;  ///< [s] when overturned
    std::optional<std::string> outcome;        ///< "stable", "rocked", ... when the summary has it
};

/// One run's summary, reduced to its dynamic bodies.
struct RunOutcome {
    std::string label;                 ///< "dt", "dt_2", "kn_x2", "ensemble_3", ...
    std::string status = "completed";  ///< "completed", or "failed" with error
    std::string error;
    double dt_s = 0.0;                 ///< [s]
    std::vector<BodyOutcome> bodies;   ///< in the order of the summary
};

/// Reads the dynamic bodies of a summary.json, 2-D or 3-D (its "dimension"). Throws
/// std::runtime_error naming the key when a summary lacks one (a file from another program).
RunOutcome outcome_of_summary(const nlohmann::json& summary, const std::string& label);

/// converge.json's "quantities_3d": what each compared quantity is in a 3-D summary.
nlohmann::json quantities_3d_json();

/// How close is close enough. A relative change is |b - a| / max(|a|, |b|, floor): the floor of
/// a quantity keeps a value near zero (a block at rest turns by 1e-6 rad) from giving a huge
/// relative change, so rtol x floor is the smallest change that counts (1 mrad, 0.5 mm, 5 ms
/// by default). The floors sit above the elastic tilt and shear deflection of soft contact
/// springs (tenths of a mrad or mm, halved by 2 x kn), which are no rocking or sliding.
struct ConvergenceTolerance {
    double rtol = 0.05;                  ///< relative change allowed at the last refinement
    double floor_rotation_rad = 0.02;    ///< [rad] floor of the peak rotation (1.1 degrees)
    double floor_slip_m = 0.01;          ///< [m] floor of the peak and final slip
    double floor_time_s = 0.1;           ///< [s] floor of the overturning time
    /// An ensemble spread at least this fraction of the spread over dt, dt/2 and dt/4 means the
    /// differences between time steps are those of a chaotic response, not of a too-long step.
    double chaos_ratio = 0.5;
};

enum class Verdict { converged, not_converged, chaotic };
std::string to_string(Verdict v);

/// The relative change from a to b with the floor, as defined above.
double relative_change(double a, double b, double floor);

/// One quantity of one body across the runs of a study.
struct QuantityComparison {
    std::string quantity;                           ///< "peak_rotation_rad", "overturned", ...
    bool discrete = false;                          ///< a flag or a word, compared for equality
    std::vector<std::optional<double>> values;      ///< per run (dt, dt/2, dt/4); null when not applicable
    std::vector<std::optional<std::string>> words;  ///< discrete quantities: per run
    std::vector<std::optional<double>> changes;     ///< relative change between successive runs
    std::optional<double> base_error;               ///< relative change from the first run to the last
    std::optional<double> change_ratio;             ///< |q1 - q0| / |q2 - q1|: > 1 when the changes shrink
    std::optional<double> observed_order;           ///< log2(change_ratio) when > 1
    bool judged = true;                             ///< false: reported only (a body that overturned)
    bool converged = true;                          ///< the last change is within the tolerance
};

/// The ensemble's spread of one quantity (runs at the base dt, the base run included).
struct EnsembleSpread {
    std::string quantity;
    bool discrete = false;
    std::optional<double> mean, min, max;  ///< continuous quantities over the members where it applies
    std::optional<double> relative_spread; ///< (max - min) / max(|min|, |max|, floor)
    std::optional<double> dt_spread_ratio; ///< (max - min) / spread over dt, dt/2, dt/4 (inf when that is 0)
    std::vector<std::string> distinct;     ///< discrete quantities: the values seen
    bool judged = true;                    ///< false: reported only (a body that overturned)
    bool sensitive = false;                ///< spread beyond the tolerance, or more than one value
    bool chaotic = false;                  ///< sensitive, and as wide as the dt spread (chaos_ratio)
};

/// The stiffness study of one quantity: runs at 0.5 x, 1 x and 2 x the contact stiffness.
struct StiffnessComparison {
    std::string quantity;
    bool discrete = false;
    std::vector<std::optional<double>> values;      ///< at the factors, in order
    std::vector<std::optional<std::string>> words;
    std::optional<double> max_change;               ///< largest relative change from the 1 x run
    bool judged = true;
    bool sensitive = false;
};

struct BodyConvergence {
    std::string name;
    std::vector<QuantityComparison> dt;
    std::vector<EnsembleSpread> ensemble;           ///< empty without an ensemble
    std::optional<double> fraction_overturned;      ///< over the ensemble
    std::vector<StiffnessComparison> stiffness;     ///< empty without the stiffness runs
    Verdict verdict = Verdict::converged;
    bool stiffness_sensitive = false;
    bool base_within_tolerance = true;              ///< the base run's answer is within rtol of dt/4's
    std::vector<std::string> reasons;               ///< why not converged / chaotic, in words
};

struct ConvergenceResult {
    std::vector<BodyConvergence> bodies;
    Verdict verdict = Verdict::converged;
    std::optional<bool> stiffness_sensitive;        ///< nullopt: not studied
    int converged_count = 0, not_converged_count = 0, chaotic_count = 0;
    std::vector<std::string> failed_runs;           ///< "label: error"
};

/// Runs of one study, by role. refinement: dt, dt/2, dt/4 (the last one the finest). ensemble:
/// the base run's perturbed copies at the base dt. stiffness: 0.5 x, 1 x, 2 x (all at one dt).
struct StudyRuns {
    std::vector<RunOutcome> refinement;
    std::vector<RunOutcome> ensemble;
    std::vector<RunOutcome> stiffness;
};

/// The verdict (see docs/convergence.md for the rule). A failed run makes every body
/// "not converged" with the failure as its reason.
ConvergenceResult judge_convergence(const StudyRuns& runs, const ConvergenceTolerance& tol);

/// converge.json's "bodies", "verdict", counts and tolerance.
nlohmann::json to_json(const ConvergenceResult& result, const ConvergenceTolerance& tol);

}  // namespace blockdem
