#include "world/energy_check_3d.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dynamics/critical_time_step_3d.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {

void check_energy_balance_3d(const World3d& w, double max_error, double start_bound_s) {
    const double error = w.ledger.balance_error();
    if (w.steps <= 10 || w.ledger.scale_j() <= 1e-9 || !(error > max_error || std::isnan(error))) return;
    std::size_t fastest = 0;
    for (std::size_t i = 1; i < w.bodies.size(); ++i)
        if (length(w.bodies[i].velocity_at_t_m_s) > length(w.bodies[fastest].velocity_at_t_m_s)) fastest = i;
    const CriticalTimeStep3d live = live_time_step_3d(w);
    throw SimulationError(fmt::format(
        "unstable: energy balance error {:.3g} (of the largest term, {:.4g} J) exceeds {:g} at t = {:.6g} s (step {}); "
        "fastest body '{}' at {:.4g} m/s; reduce dt (now {:g} s; stable limit {:.4g} s at the start, {:.4g} s now)",
        error, w.ledger.scale_j(), max_error, w.time_s, w.steps, w.bodies[fastest].name,
        length(w.bodies[fastest].velocity_at_t_m_s), w.dt_s, start_bound_s, live.dt_s));
}

}  // namespace blockdem
