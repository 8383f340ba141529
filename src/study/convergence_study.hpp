#pragma once
// `blockdem converge`: runs a scenario at dt, dt/2 and dt/4 (and, on request, at other contact
// stiffnesses and as an ensemble of tiny perturbations) through the ordinary run path, one
// subfolder per run, and writes converge.json and converge.csv with the verdict
// (docs/convergence.md).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/convergence_plan.hpp"
#include "study/convergence_verdict.hpp"
#include "world/simulation.hpp"

namespace blockdem {

struct ConvergenceRequest {
    std::filesystem::path scenario;
    std::vector<std::string> overrides;   ///< the user's --set, applied to every run
    std::filesystem::path out_dir;        ///< the study folder: converge.json, converge.csv, one folder per run
    ConvergenceOptions options;
    ConvergenceTolerance tolerance;
    /// Called before each run: its plan entry, its 0-based position and the number of runs.
    std::function<void(const PlannedRun&, std::size_t, std::size_t)> on_run_start;
    std::function<void(const RunProgress&)> on_progress;
};

struct ConvergenceStudy {
    std::vector<PlannedRun> runs;        ///< the base run first
    StudyRuns outcomes;
    ConvergenceResult result;
    nlohmann::json report;               ///< what converge.json holds
};

/// Runs the study. Bad input (InputError) stops it before anything runs; a run that fails
/// once started is recorded as failed (its folder keeps what it wrote) and the study goes on.
ConvergenceStudy run_convergence_study(const ConvergenceRequest& request);

}  // namespace blockdem
