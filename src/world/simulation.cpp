#include "world/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <utility>

#include "world/step.hpp"
#include "world/step_3d.hpp"

namespace blockdem {

template <class W>
std::int64_t total_steps(const W& w) {
    return static_cast<std::int64_t>(std::llround(end_time_s(w) / w.dt_s));
}

template <class W>
std::int64_t steps_per_output(const W& w) {
    // Clamped as a double before the cast: output_interval = 1e300 s means "only the ends".
    return static_cast<std::int64_t>(std::clamp(std::round(output_interval_s(w) / w.dt_s), 1.0, 1e18));
}

template <class W>
std::int64_t output_rows_before(const W& w, std::int64_t n) {
    // The rows of the steps k < n with k % every == 0 (the last step's row comes at k = n = steps).
    return n <= 0 ? 0 : (n - 1) / steps_per_output(w) + 1;
}

template <class W>
std::int64_t step_at_time(const W& w, double t_s) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::llround(t_s / w.dt_s)), 0, total_steps(w));
}

namespace {

bool save_point_due(const SavePoints& points, std::int64_t n) {
    if (points.every_steps > 0 && n > 0 && n % points.every_steps == 0) return true;
    return std::find(points.steps.begin(), points.steps.end(), n) != points.steps.end();
}

// Every recorder is finished (each closes its own files), then the first failure is rethrown.
template <class W>
void finish_all(const W& w, const std::vector<RecorderOf<W>*>& recorders) {
    std::exception_ptr first_error;
    for (RecorderOf<W>* r : recorders) {
        try {
            r->finish(w);
        } catch (...) {
            if (!first_error) first_error = std::current_exception();
        }
    }
    if (first_error) std::rethrow_exception(first_error);
}

}  // namespace

template <class W>
RunLoopOf<W>::RunLoopOf(W& w, RunOptionsOf<W> options)
    : w_(w),
      options_(std::move(options)),
      steps_(total_steps(w)),
      every_(steps_per_output(w)),
      first_(step_index(w)),
      started_(std::chrono::steady_clock::now()),
      last_report_(started_) {}

template <class W>
void RunLoopOf<W>::begin_step() {
    const std::int64_t n = step_index(w_);
    // (A restored run does not save again the state it started from.)
    const auto& at = options_.save_points.steps;
    if (options_.on_save_point && (n > first_ || first_ == 0) && save_point_due(options_.save_points, n))
        options_.on_save_point(w_, std::find(at.begin(), at.end(), n) != at.end() ? SaveReason::at_time : SaveReason::every);
    step_begin(w_);
    begun_ = true;
    if (options_.on_step) options_.on_step(w_);
    output_now_ = n % every_ == 0 || n == steps_;
    if (output_now_)
        for (RecorderOf<W>* r : options_.recorders) r->record(w_);
    if (n == steps_) ended_ = true;
}

template <class W>
void RunLoopOf<W>::end_step() {
    const std::int64_t n = step_index(w_);
    step_end(w_);
    begun_ = false;
    if (options_.on_progress && (n & 255) == 0) {
        const auto now = std::chrono::steady_clock::now();
        if (now - last_report_ > std::chrono::seconds(1)) {
            last_report_ = now;
            options_.on_progress({w_.time_s, end_time_s(w_), step_index(w_),
                                  std::chrono::duration<double>(now - started_).count()});
        }
    }
}

template <class W>
void RunLoopOf<W>::fail_and_rethrow() {
    failed_ = true;
    ended_ = true;
    // Keep what was written readable; a second failure (the same full disk) must not hide the
    // first.
    if (!finished_) {
        finished_ = true;
        try {
            finish_all(w_, options_.recorders);
        } catch (...) {
        }
    }
    throw;
}

template <class W>
std::int64_t RunLoopOf<W>::advance(std::int64_t steps) {
    if (failed_) throw std::logic_error("the run failed earlier: it cannot go on");
    std::int64_t taken = 0;
    try {
        if (!begun_ && !ended_) begin_step();
        auto stop_requested = [&] {
            return options_.stop_requested && options_.stop_requested->load(std::memory_order_relaxed);
        };
        while (!ended_ && taken < steps) {
            if (stop_requested()) {
                stop();
                break;
            }
            end_step();
            ++taken;
            begin_step();
        }
    } catch (...) {
        fail_and_rethrow();
    }
    return taken;
}

template <class W>
void RunLoopOf<W>::stop() {
    if (ended_) return;
    try {
        if (!begun_) begin_step();
        if (ended_) return;  // (the start was the end)
        // The time reached is the last row of every file, also between output times.
        if (!output_now_)
            for (RecorderOf<W>* r : options_.recorders) r->record(w_);
        if (options_.on_save_point) {
            // The world stays at the time recorded last (the summary reports it); the state to
            // go on from is the one after this step.
            W next = w_;
            step_end(next);
            options_.on_save_point(next, SaveReason::stopped);
        }
        end_ = RunEnd::stopped;
        ended_ = true;
    } catch (...) {
        fail_and_rethrow();
    }
}

template <class W>
void RunLoopOf<W>::finish() {
    if (finished_) return;
    finished_ = true;
    finish_all(w_, options_.recorders);
}

template class RunLoopOf<World>;
template class RunLoopOf<World3d>;
template std::int64_t total_steps(const World&);
template std::int64_t total_steps(const World3d&);
template std::int64_t steps_per_output(const World&);
template std::int64_t steps_per_output(const World3d&);
template std::int64_t output_rows_before(const World&, std::int64_t);
template std::int64_t output_rows_before(const World3d&, std::int64_t);
template std::int64_t step_at_time(const World&, double);
template std::int64_t step_at_time(const World3d&, double);

RunEnd run_simulation(World& w, const RunOptions& options) {
    RunLoop loop(w, options);
    loop.advance(std::numeric_limits<std::int64_t>::max());
    loop.finish();
    return loop.end();
}

}  // namespace blockdem
