#pragma once
// Dynamic scheduling: the cases still to do, handed out one at a time to whichever worker
// (thread or MPI rank) asks next, so that a slow case never holds up a fixed share of others;
// and the collector that records each finished case durably and reports progress.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "sweep/results_table.hpp"

namespace blockdem::sweep {

/// The pending case ids, handed out in increasing order. Thread safe.
class CaseQueue {
public:
    CaseQueue(std::vector<std::int64_t> pending, const std::atomic<bool>* cancel);
    /// The next case, or nothing when all are handed out or the sweep is cancelled.
    std::optional<std::int64_t> next();
    std::size_t size() const { return pending_.size(); }

private:
    std::vector<std::int64_t> pending_;
    std::atomic<std::size_t> next_{0};
    const std::atomic<bool>* cancel_;
};

struct SweepProgress {
    std::int64_t total = 0;           ///< cases in the sweep
    std::int64_t done = 0;            ///< finished, including those from an earlier run
    std::int64_t failed = 0;          ///< finished with status failed or error
    std::int64_t done_this_run = 0;
    double elapsed_s = 0.0;           ///< [s] wall time of this run
    double rate_cases_s = 0.0;        ///< [1/s] cases finished per second in this run
    double remaining_s = 0.0;         ///< [s] estimated time left (0 when unknown)
    bool final = false;               ///< the last report
};

/// Records finished cases in the log (durably) and reports progress. Thread safe.
class ResultCollector {
public:
    /// status_column: index of the status field in a row (to count failures).
    ResultCollector(FinishedCasesLog& log, std::int64_t total, std::size_t status_column,
                    std::function<void(const SweepProgress&)> on_progress);
    /// A finished case: its formatted row.
    void record(std::int64_t id, const std::string& row);
    /// Reports progress with final = true.
    void finish();
    SweepProgress progress() const;

private:
    SweepProgress snapshot_locked() const;
    bool is_failure(const std::string& row) const;

    mutable std::mutex mutex_;
    FinishedCasesLog& log_;
    std::int64_t total_;
    std::size_t status_column_;
    std::int64_t failed_ = 0;
    std::int64_t done_this_run_ = 0;
    std::function<void(const SweepProgress&)> on_progress_;
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_report_ = started_;
};

/// Runs work(id) for every case of the queue on `threads` threads (dynamic scheduling). The
/// first exception of a worker (other than CaseCancelled, which just stops that worker) is
/// rethrown after all threads have joined.
void run_on_threads(int threads, CaseQueue& queue, const std::function<void(std::int64_t)>& work);

}  // namespace blockdem::sweep
