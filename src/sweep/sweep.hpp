#pragma once
// A parameter study: every case of a plan run once, on threads (and on MPI ranks when started
// by mpirun), each finished case written durably at once, the sorted table at the end. A rerun
// with the same plan and --out does only the cases that are missing (docs/sweeps.md).
//
// Out folder:
//   sweep.json          the plan's fingerprint, the columns with units, the counts, the status
//                       ("running", "complete", or "interrupted" after SIGINT / SIGTERM)
//   finished_cases.csv  rows as they finish (the durable log; see results_table.hpp)
//   results.csv         rows sorted by case id, written when the run ends (also when cancelled)
//   cases/<id>/         history.csv per case, with --histories
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweep/case_queue.hpp"
#include "sweep/case_runner.hpp"
#include "sweep/sweep_plan.hpp"

namespace blockdem::sweep {

struct SweepRequest {
    std::filesystem::path scenario;
    SweepPlan plan;
    CaseOptions options;                 ///< histories_dir is set from out_dir and `histories`
    bool histories = false;
    std::filesystem::path out_dir;
    int threads = 0;                     ///< per rank; 0: all cores (1 per rank under mpirun)
    std::string command_line;            ///< recorded in sweep.json
    std::function<void(const SweepProgress&)> on_progress;   ///< called on rank 0 only
    const std::atomic<bool>* cancel = nullptr;               ///< Ctrl-C
};

struct SweepOutcome {
    bool reporting_rank = true;   ///< false on MPI ranks other than 0 (they report nothing)
    std::int64_t total = 0;
    std::int64_t done = 0;        ///< finished cases, including earlier runs'
    std::int64_t failed = 0;
    std::int64_t ran_now = 0;     ///< cases run by this invocation
    int ranks = 1;
    int threads_per_rank = 1;
    double wall_s = 0.0;          ///< [s]
    bool complete() const { return done == total; }
};

/// Runs the sweep. Throws InputError / std::invalid_argument for a bad plan or an out folder
/// that holds another sweep or a run, OutputError for a file that cannot be written; never for
/// a failing case. On *cancel the running cases are dropped (rerun later), the rows so far are
/// sorted into results.csv and sweep.json says "interrupted".
SweepOutcome run_sweep(const SweepRequest& request);

/// A fingerprint of everything that decides the results (scenario text, plan, solver options).
std::string plan_fingerprint(const SweepScenario& scenario, const SweepPlan& plan, const CaseOptions& options);

}  // namespace blockdem::sweep
