#include "world/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "world/step.hpp"

namespace blockdem {

std::int64_t total_steps(const World& w) {
    return static_cast<std::int64_t>(std::llround(w.settings.duration_s / w.dt_s));
}

std::int64_t steps_per_output(const World& w) {
    // Clamped as a double before the cast: output_interval = 1e300 s means "only the ends".
    return static_cast<std::int64_t>(std::clamp(std::round(w.settings.output_interval_s / w.dt_s), 1.0, 1e18));
}

void run_simulation(World& w, const RunOptions& options) {
    using clock = std::chrono::steady_clock;
    const auto started = clock::now();
    auto last_report = started;
    const std::int64_t steps = total_steps(w);
    const std::int64_t every = steps_per_output(w);
    auto finish_all = [&] {
        for (Recorder* r : options.recorders) r->finish(w);
    };
    try {
        for (std::int64_t n = 0;; ++n) {
            step_begin(w);
            if (options.on_step) options.on_step(w);
            if (n % every == 0 || n == steps)
                for (Recorder* r : options.recorders) r->record(w);
            if (n == steps) break;
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
        finish_all();
        throw;
    }
    finish_all();
}

}  // namespace blockdem
