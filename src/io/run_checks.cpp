#include "io/run_checks.hpp"

#include <fmt/format.h>

namespace blockdem {

nlohmann::json run_checks(const World& w) {
    const StabilityWatch& s = w.stability;
    const Bodies& b = w.bodies;
    nlohmann::json j;
    j["time_step"] = {{"dt_s", w.dt_s},
                      {"stable_limit_at_start_s", w.critical_dt_s},
                      {"proven_stable_below_s", w.proven_stable_dt_s},
                      {"least_live_limit_s", s.least_limit_s},
                      {"least_live_limit_body", s.least_limit_body},
                      {"least_live_limit_time_s", s.least_limit_time_s},
                      {"dt_above_live_limit", s.first_exceeded_s >= 0.0},
                      {"dt_above_live_limit_from_s", s.first_exceeded_s >= 0.0 ? nlohmann::json(s.first_exceeded_s)
                                                                                : nlohmann::json(nullptr)}};
    nlohmann::json overlap = {{"max_ratio", s.max_overlap_ratio},
                              {"warning_ratio", overlap_warning_ratio},
                              {"limit_ratio", w.settings.max_overlap_ratio}};
    if (s.max_overlap_ratio > 0.0) {
        overlap["max_m"] = s.max_overlap_m;
        overlap["time_s"] = s.max_overlap_time_s;
        overlap["bodies"] = {b.name[s.max_overlap_pair_a], b.name[s.max_overlap_pair_b]};
    }
    j["overlap"] = overlap;
    const EnergyLedger& e = w.energy;
    j["energy"] = {{"residual_j", e.residual_j()},
                   {"balance_error_relative", e.balance_error()},
                   {"warning_ratio", energy_warning_ratio},
                   {"stop_ratio", w.settings.max_energy_error}};
    return j;
}

std::vector<std::string> run_warnings(const World& w) {
    const StabilityWatch& s = w.stability;
    const Bodies& b = w.bodies;
    std::vector<std::string> warnings;
    if (s.first_exceeded_s >= 0.0)
        warnings.push_back(fmt::format(
            "dt = {:g} s was above the stable limit of the live contacts from t = {:.6g} s (least {:.4g} s, body '{}' at "
            "t = {:.6g} s): the result may be wrong; rerun with a smaller dt (blockdem converge)",
            w.dt_s, s.first_exceeded_s, s.least_limit_s, s.least_limit_body, s.least_limit_time_s));
    if (s.max_overlap_ratio > overlap_warning_ratio)
        warnings.push_back(fmt::format(
            "bodies '{}' and '{}' overlapped by {:.4g} m at t = {:.6g} s, {:.3g} of the thinner body's least width "
            "(above {:g}): the contacts are soft for their load; raise kn",
            b.name[s.max_overlap_pair_a], b.name[s.max_overlap_pair_b], s.max_overlap_m, s.max_overlap_time_s,
            s.max_overlap_ratio, overlap_warning_ratio));
    if (w.energy.balance_error() > energy_warning_ratio)
        warnings.push_back(fmt::format(
            "the energy balance error is {:.3g} of the largest term (above {:g}): the time step or the contact "
            "stiffness may be too coarse for this run; check with blockdem converge",
            w.energy.balance_error(), energy_warning_ratio));
    return warnings;
}

}  // namespace blockdem
