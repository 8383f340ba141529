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

namespace {

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
    try {
        for (std::int64_t n = 0;; ++n) {
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
