#include "world/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "world/step.hpp"

namespace blockdem {

std::int64_t total_steps(const World& w) {
    return static_cast<std::int64_t>(std::llround(w.settings.duration_s / w.dt_s));
}

std::int64_t steps_per_output(const World& w) {
    // Clamped as a double before the cast: output_interval = 1e300 s means "only the ends".
    return static_cast<std::int64_t>(std::clamp(std::round(w.settings.output_interval_s / w.dt_s), 1.0, 1e18));
}

std::int64_t output_rows_before(const World& w, std::int64_t n) {
    // The rows of the steps k < n with k % every == 0 (the last step's row comes at k = n = steps).
    return n <= 0 ? 0 : (n - 1) / steps_per_output(w) + 1;
}

std::int64_t step_at_time(const World& w, double t_s) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::llround(t_s / w.dt_s)), 0, total_steps(w));
}

namespace {

bool save_point_due(const SavePoints& points, std::int64_t n) {
    if (points.every_steps > 0 && n > 0 && n % points.every_steps == 0) return true;
    return std::find(points.steps.begin(), points.steps.end(), n) != points.steps.end();
}

// Every recorder is finished (each closes its own files), then the first failure is rethrown.
void finish_all(const World& w, const std::vector<Recorder*>& recorders) {
    std::exception_ptr first_error;
    for (Recorder* r : recorders) {
        try {
            r->finish(w);
        } catch (...) {
            if (!first_error) first_error = std::current_exception();
        }
    }
    if (first_error) std::rethrow_exception(first_error);
}

}  // namespace

RunEnd run_simulation(World& w, const RunOptions& options) {
    using clock = std::chrono::steady_clock;
    const auto started = clock::now();
    auto last_report = started;
    const std::int64_t steps = total_steps(w);
    const std::int64_t every = steps_per_output(w);
    auto stop_requested = [&] { return options.stop_requested && options.stop_requested->load(std::memory_order_relaxed); };
    RunEnd end = RunEnd::completed;
    const std::int64_t first = w.step_index;
    try {
        for (std::int64_t n = first;; ++n) {
            // (A restored run does not save again the state it started from.)
            if (options.on_save_point && (n > first || first == 0) && save_point_due(options.save_points, n))
                options.on_save_point(w, std::find(options.save_points.steps.begin(), options.save_points.steps.end(), n) !=
                                                 options.save_points.steps.end()
                                             ? SaveReason::at_time
                                             : SaveReason::every);
            step_begin(w);
            if (options.on_step) options.on_step(w);
            const bool output_now = n % every == 0 || n == steps;
            if (output_now)
                for (Recorder* r : options.recorders) r->record(w);
            if (n == steps) break;
            if (stop_requested()) {
                // The time reached is the last row of every file, also between output times.
                if (!output_now)
                    for (Recorder* r : options.recorders) r->record(w);
                if (options.on_save_point) {
                    // The world stays at the time recorded last (the summary reports it); the
                    // state to go on from is the one after this step.
                    World next = w;
                    step_end(next);
                    options.on_save_point(next, SaveReason::stopped);
                }
                end = RunEnd::stopped;
                break;
            }
            step_end(w);
            if (options.on_progress && (n & 255) == 0) {
                const auto now = clock::now();
                if (now - last_report > std::chrono::seconds(1)) {
                    last_report = now;
                    options.on_progress({w.time_s, w.settings.duration_s, w.step_index,
                                         std::chrono::duration<double>(now - started).count()});
                }
            }
        }
    } catch (...) {
        // Keep what was written readable; a second failure (the same full disk) must not hide
        // the first.
        try {
            finish_all(w, options.recorders);
        } catch (...) {
        }
        throw;
    }
    finish_all(w, options.recorders);
    return end;
}

}  // namespace blockdem
