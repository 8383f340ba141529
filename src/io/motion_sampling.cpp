#include "io/motion_sampling.hpp"

#include <optional>

#include <fmt/format.h>

namespace blockdem {
namespace {

// The period [s] the step must resolve: a sine's or a pulse's, a Ricker wavelet's 1 / peak
// frequency; none for rest and for sampled series.
std::optional<double> resolved_period_s(const ComponentMotion& motion) {
    if (const auto* m = std::get_if<SineMotion>(&motion)) return m->period_s;
    if (const auto* m = std::get_if<PulseMotion>(&motion)) return m->period_s;
    if (const auto* m = std::get_if<RickerMotion>(&motion)) return 1.0 / m->peak_frequency_hz;
    return std::nullopt;
}

}  // namespace

void check_motion_sampling(TableReader motion_table, const std::string& key, const ComponentMotion& motion, double dt_s) {
    const std::optional<double> period_s = resolved_period_s(motion);
    if (!period_s || !(dt_s > 0.0) || *period_s >= min_steps_per_period * dt_s) return;
    TableReader component = motion_table.table(key);
    const bool by_period = component.has("period");
    const std::string given = by_period ? fmt::format("period {:g} s", *period_s)
                                        : fmt::format("frequency {:g} Hz (a period of {:g} s)", 1.0 / *period_s, *period_s);
    component.fail(by_period ? "period" : "frequency",
                   fmt::format("the {} spans {:.3g} time steps of dt = {:g} s; it must span at least {:g}: the step samples "
                               "the motion once per dt, and fewer than {:g} samples a cycle miss its peaks (at 2, the "
                               "Nyquist limit, the shaking is lost altogether); give a longer period or a smaller "
                               "simulation.dt",
                               given, *period_s / dt_s, dt_s, min_steps_per_period, min_steps_per_period));
}

}  // namespace blockdem
