#include "world/run_checks_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "dynamics/critical_time_step_3d.hpp"
#include "dynamics/highest_mode.hpp"
#include "world/model.hpp"
#include "world/model_domain_3d.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {

void check_energy_balance_3d(const World3d& w, double max_error, double start_limit_s) {
    const double error = w.ledger.balance_error();
    if (w.steps <= 10 || w.ledger.scale_j() <= 1e-9 || !(error > max_error || std::isnan(error))) return;
    const std::string culprit = unstable_body_clause(
        w.domain.left, w.bodies.size(), [&](std::size_t i) { return w.bodies[i].mass_kg; },
        [&](std::size_t i) { return w.bodies[i].name; }, [&](std::size_t i) { return length(w.bodies[i].velocity_at_t_m_s); });
    const CriticalTimeStep3d live = live_time_step_3d(w);
    const double ratio = w.stability.limit_ratio > 0.0 ? w.stability.limit_ratio : 1.0;
    const StabilityWatch3d& watch = w.stability;
    const std::string least =
        watch.first_exceeded_s < 0.0 ? std::string()
                                     : fmt::format("; {:.4g} s for the contacts body '{}' had at t = {:.6g} s", watch.least_limit_s,
                                                   watch.least_limit_body, watch.least_limit_time_s);
    throw SimulationError(fmt::format(
        "unstable: energy balance error {:.3g} (of the largest term, {:.4g} J) exceeds {:g} at t = {:.6g} s (step {}); "
        "{}; reduce dt (now {:g} s; stable limit {:.4g} s at the start, {:.4g} s now{})",
        error, w.ledger.scale_j(), max_error, w.time_s, w.steps, culprit, w.dt_s, start_limit_s, ratio * live.dt_s, least));
}

void watch_live_time_step_3d(World3d& w) {
    if (w.steps % live_limit_every_3d != 0) return;
    const CriticalTimeStep3d bound = live_time_step_3d(w);
    if (!std::isfinite(bound.dt_s)) return;  // (no dynamic body carries a point)
    StabilityWatch3d& watch = w.stability;
    // The proven bound times the ratio of the highest mode's limit to it (1.7 to 2.1 for a block on
    // its base, 3.7 to 4 for a brick with six neighbours), estimated again on a new layout
    // (dynamics/highest_mode.hpp, live_limit_s; an estimate costs some 250 passes over the contacts).
    double limit_s = live_limit_s({watch.limit_ratio, watch.ratio_bound_s, watch.estimates}, watch.first_exceeded_s >= 0.0,
                                  w.dt_s, bound.dt_s, [&] { return highest_mode_time_step_3d(w, w.contacts, bound).dt_s; });
    std::uint32_t body = bound.body;
    // One ratio for the whole model can miss a body whose own layout has a smaller one; a body
    // whose own blocks are unstable at dt is above the limit for certain (Cauchy's interlacing).
    // Every fourth look: it costs about as much as the bound (3 % of the brick wall example's
    // run every 32 steps, 0.7 % so).
    if (w.steps % (own_blocks_every * live_limit_every_3d) == 0) {
        const CriticalTimeStep3d own = body_block_limit_3d(w, w.dt_s);
        if (own.dt_s < limit_s) limit_s = own.dt_s, body = own.body;
    }
    if (watch.least_limit_s == 0.0 || limit_s < watch.least_limit_s) {
        watch.least_limit_s = limit_s;
        watch.least_limit_body = w.bodies[body].name;
        watch.least_limit_time_s = w.time_s;
    }
    if (w.dt_s > limit_s && watch.first_exceeded_s < 0.0) {
        watch.first_exceeded_s = w.time_s;
        watch.exceeded_body = w.bodies[body].name;
    }
}

std::vector<double> least_widths_m(const World3d& w) {
    std::vector<double> widths;
    for (const RigidBody3d& b : w.bodies) {
        double least = std::numeric_limits<double>::infinity();
        for (const Vec3& n : b.shape.face_normals) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (const Vec3& v : b.shape.vertices_m) {
                lo = std::min(lo, dot(v, n));
                hi = std::max(hi, dot(v, n));
            }
            least = std::min(least, hi - lo);
        }
        widths.push_back(least);
    }
    return widths;
}

void watch_overlap_3d(World3d& w, const std::vector<double>& widths_m, double max_ratio) {
    const ContactPoint3d* deepest = nullptr;
    double deepest_ratio = 0.0;
    for (const ContactPoint3d& c : w.contacts) {
        const double ratio = c.overlap_m / std::min(widths_m[c.key.body_a], widths_m[c.key.body_b]);
        if (ratio > deepest_ratio) {
            deepest_ratio = ratio;
            deepest = &c;
        }
    }
    if (deepest == nullptr) return;
    StabilityWatch3d& watch = w.stability;
    if (deepest_ratio > watch.max_overlap_ratio) {
        watch.max_overlap_ratio = deepest_ratio;
        watch.max_overlap_m = deepest->overlap_m;
        watch.max_overlap_time_s = w.time_s;
        watch.max_overlap_body_a = deepest->key.body_a;
        watch.max_overlap_body_b = deepest->key.body_b;
    }
    if (deepest_ratio <= max_ratio) return;
    // As in 2-D: the impact rule (overlap as 1/sqrt(kn)) brings the overlap near 1% either way.
    const double kn = w.contact.kn_N_m;
    throw SimulationError(fmt::format(
        "penetration: bodies '{}' and '{}' overlap by {:.4g} m at t = {:.6g} s (step {}), {:.3g} of the least width "
        "of the thinner body; the limit is {:g} (simulation.max_overlap). The contact is too soft for its load: "
        "raise kn (now {:.4g} N/m) to about {:.3g} N/m for an overlap near 1%",
        w.bodies[deepest->key.body_a].name, w.bodies[deepest->key.body_b].name, deepest->overlap_m, w.time_s, w.steps,
        deepest_ratio, max_ratio, kn, kn * (deepest_ratio / overlap_warning_ratio) * (deepest_ratio / overlap_warning_ratio)));
}

}  // namespace blockdem
