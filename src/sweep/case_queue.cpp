#include "sweep/case_queue.hpp"

#include <exception>
#include <thread>

#include "sweep/case_runner.hpp"
#include "sweep/sweep_plan.hpp"

namespace blockdem::sweep {

CaseQueue::CaseQueue(std::vector<std::int64_t> pending, const std::atomic<bool>* cancel)
    : pending_(std::move(pending)), cancel_(cancel) {}

std::optional<std::int64_t> CaseQueue::next() {
    if (cancel_ && cancel_->load()) return std::nullopt;
    const std::size_t k = next_.fetch_add(1);
    if (k >= pending_.size()) return std::nullopt;
    return pending_[k];
}

ResultCollector::ResultCollector(FinishedCasesLog& log, std::int64_t total, std::size_t status_column,
                                 std::function<void(const SweepProgress&)> on_progress)
    : log_(log), total_(total), status_column_(status_column), on_progress_(std::move(on_progress)) {
    for (const auto& [id, row] : log_.rows())
        if (is_failure(row)) ++failed_;
}

bool ResultCollector::is_failure(const std::string& row) const {
    const std::vector<std::string> fields = split_csv_line(row);
    return fields.size() > status_column_ && fields[status_column_] != "completed";
}

void ResultCollector::record(std::int64_t id, const std::string& row) {
    {
        std::lock_guard lock(mutex_);
        const bool again = log_.rows().count(id) > 0;  // a case redone after a lost reply: count once
        log_.append(id, row);
        if (!again) {
            ++done_this_run_;
            if (is_failure(row)) ++failed_;
        }
    }
    // The fsync waits for the disk, not the CPU: outside the lock, so that other workers'
    // rows do not queue behind it (the kernel serves concurrent syncs of one file together).
    log_.sync();
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (on_progress_ && now - last_report_ >= std::chrono::seconds(1)) {
        last_report_ = now;
        on_progress_(snapshot_locked());
    }
}

void ResultCollector::finish() {
    std::lock_guard lock(mutex_);
    SweepProgress p = snapshot_locked();
    p.final = true;
    if (on_progress_) on_progress_(p);
}

SweepProgress ResultCollector::progress() const {
    std::lock_guard lock(mutex_);
    return snapshot_locked();
}

SweepProgress ResultCollector::snapshot_locked() const {
    SweepProgress p;
    p.total = total_;
    p.done = static_cast<std::int64_t>(log_.rows().size());
    p.failed = failed_;
    p.done_this_run = done_this_run_;
    p.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    p.rate_cases_s = p.elapsed_s > 0.0 ? static_cast<double>(done_this_run_) / p.elapsed_s : 0.0;
    p.remaining_s = p.rate_cases_s > 0.0 ? static_cast<double>(p.total - p.done) / p.rate_cases_s : 0.0;
    return p;
}

void run_on_threads(int threads, CaseQueue& queue, const std::function<void(std::int64_t)>& work) {
    std::mutex error_mutex;
    std::exception_ptr first_error;
    auto worker = [&] {
        try {
            while (auto id = queue.next()) work(*id);
        } catch (const CaseCancelled&) {
            // Ctrl-C: the case in hand is dropped and will be redone by a rerun.
        } catch (...) {
            std::lock_guard lock(error_mutex);
            if (!first_error) first_error = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (first_error) std::rethrow_exception(first_error);
}

}  // namespace blockdem::sweep
