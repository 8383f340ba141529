#include "io/run_checks.hpp"

#include <cmath>
#include <set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace blockdem {

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

namespace {

// The thresholds' objects and sentences, one form for 2-D and 3-D.

nlohmann::json time_step_check(double dt_s, double start_bound_s, double least_limit_s, const std::string& least_body,
                               double least_time_s, double first_exceeded_s) {
    return {{"dt_s", dt_s},
            {"stable_limit_at_start_s", finite_or_null(start_bound_s)},
            {"least_live_limit_s", least_limit_s > 0.0 ? nlohmann::json(least_limit_s) : nlohmann::json(nullptr)},
            {"least_live_limit_body", least_body},
            {"least_live_limit_time_s", least_time_s},
            {"dt_above_live_limit", first_exceeded_s >= 0.0},
            {"dt_above_live_limit_from_s", first_exceeded_s >= 0.0 ? nlohmann::json(first_exceeded_s) : nlohmann::json(nullptr)}};
}

nlohmann::json overlap_check(double max_ratio, double max_overlap_m, double time_s, const std::string& body_a,
                             const std::string& body_b, double limit_ratio) {
    nlohmann::json overlap = {{"max_ratio", max_ratio}, {"warning_ratio", overlap_warning_ratio}, {"limit_ratio", limit_ratio}};
    if (max_ratio > 0.0) {
        overlap["max_m"] = max_overlap_m;
        overlap["time_s"] = time_s;
        overlap["bodies"] = {body_a, body_b};
    }
    return overlap;
}

nlohmann::json energy_check(const EnergyLedger& e, double stop_ratio) {
    return {{"residual_j", e.residual_j()},
            {"balance_error_relative", e.balance_error()},
            {"warning_ratio", energy_warning_ratio},
            {"stop_ratio", stop_ratio}};
}

std::string live_limit_warning(double dt_s, double first_exceeded_s, const std::string& exceeded_body,
                               double least_limit_s, const std::string& least_body, double least_time_s) {
    return fmt::format(
        "dt = {:g} s was above the stable limit of the live contacts from t = {:.6g} s (body '{}'; least {:.4g} s, body "
        "'{}' at t = {:.6g} s): the result may be wrong; rerun with a smaller dt (blockdem converge)",
        dt_s, first_exceeded_s, exceeded_body, least_limit_s, least_body, least_time_s);
}

std::string overlap_warning(const std::string& body_a, const std::string& body_b, double overlap_m, double time_s,
                            double ratio) {
    return fmt::format(
        "bodies '{}' and '{}' overlapped by {:.4g} m at t = {:.6g} s, {:.3g} of the thinner body's least width "
        "(above {:g}): the contacts are soft for their load; raise kn",
        body_a, body_b, overlap_m, time_s, ratio, overlap_warning_ratio);
}

std::string energy_warning(double balance_error) {
    return fmt::format(
        "the energy balance error is {:.3g} of the largest term (above {:g}): the time step or the contact "
        "stiffness may be too coarse for this run; check with blockdem converge",
        balance_error, energy_warning_ratio);
}

// The warnings of a run's watches (2-D StabilityWatch or StabilityWatch3d), name(i) naming body i.
template <class Watch, class Name>
std::vector<std::string> watch_warnings(const Watch& s, double dt_s, const EnergyLedger& energy, const Name& name,
                                        std::uint32_t overlap_a, std::uint32_t overlap_b) {
    std::vector<std::string> warnings;
    if (s.first_exceeded_s >= 0.0)
        warnings.push_back(live_limit_warning(dt_s, s.first_exceeded_s, s.exceeded_body, s.least_limit_s,
                                              s.least_limit_body, s.least_limit_time_s));
    if (s.max_overlap_ratio > overlap_warning_ratio)
        warnings.push_back(
            overlap_warning(name(overlap_a), name(overlap_b), s.max_overlap_m, s.max_overlap_time_s, s.max_overlap_ratio));
    if (energy.balance_error() > energy_warning_ratio) warnings.push_back(energy_warning(energy.balance_error()));
    return warnings;
}

}  // namespace

nlohmann::json run_checks(const World& w) {
    const StabilityWatch& s = w.stability;
    const Bodies& b = w.bodies;
    nlohmann::json j;
    j["time_step"] = time_step_check(w.dt_s, w.critical_dt_s, s.least_limit_s, s.least_limit_body, s.least_limit_time_s,
                                     s.first_exceeded_s);
    j["time_step"]["proven_stable_below_s"] = w.proven_stable_dt_s;
    const bool seen = s.max_overlap_ratio > 0.0;  // (a pair to name only then)
    j["overlap"] = overlap_check(s.max_overlap_ratio, s.max_overlap_m, s.max_overlap_time_s,
                                 seen ? b.name[s.max_overlap_pair_a] : std::string(),
                                 seen ? b.name[s.max_overlap_pair_b] : std::string(), w.settings.max_overlap_ratio);
    j["energy"] = energy_check(w.energy, w.settings.max_energy_error);
    return j;
}

std::vector<std::string> run_warnings(const World& w) {
    const Bodies& b = w.bodies;
    return watch_warnings(w.stability, w.dt_s, w.energy, [&](std::uint32_t i) { return b.name[i]; },
                          w.stability.max_overlap_pair_a, w.stability.max_overlap_pair_b);
}

nlohmann::json run_checks_3d(const World3d& w, double start_limit_s, double max_overlap_ratio, double max_energy_error) {
    const StabilityWatch3d& s = w.stability;
    nlohmann::json j;
    j["time_step"] = time_step_check(w.dt_s, start_limit_s, s.least_limit_s, s.least_limit_body, s.least_limit_time_s,
                                     s.first_exceeded_s);
    j["time_step"]["proven_stable_below_s"] = finite_or_null(s.start_bound_s);
    // (The pair's names only where an overlap was seen: a world without bodies has none to name.)
    const bool seen = s.max_overlap_ratio > 0.0;
    j["overlap"] = overlap_check(s.max_overlap_ratio, s.max_overlap_m, s.max_overlap_time_s,
                                 seen ? w.bodies[s.max_overlap_body_a].name : std::string(),
                                 seen ? w.bodies[s.max_overlap_body_b].name : std::string(), max_overlap_ratio);
    j["energy"] = energy_check(w.ledger, max_energy_error);
    return j;
}

std::vector<std::string> run_warnings_3d(const World3d& w) {
    return watch_warnings(w.stability, w.dt_s, w.ledger, [&](std::uint32_t i) { return w.bodies[i].name; },
                          w.stability.max_overlap_body_a, w.stability.max_overlap_body_b);
}

namespace {

bool gives_damping(const toml::node_view<const toml::node>& table) { return table["e"] || table["h_n"]; }

// The material pairs (names, sorted within the pair) whose [[contact.pairs]] entry gives e or h_n.
std::set<std::pair<std::string, std::string>> damped_pairs(const toml::node_view<const toml::node>& contact) {
    std::set<std::pair<std::string, std::string>> damped;
    if (const toml::array* pairs = contact["pairs"].as_array())
        for (const toml::node& entry : *pairs) {
            const toml::node_view<const toml::node> pair(entry);
            const auto a = pair["materials"][0].value<std::string>();
            const auto b = pair["materials"][1].value<std::string>();
            if (a && b && gives_damping(pair)) damped.insert(std::minmax(*a, *b));
        }
    return damped;
}

}  // namespace

std::vector<std::string> input_warnings(const toml::table& root, const World& w) {
    const toml::node_view<const toml::node> contact = root["contact"];
    if (gives_damping(contact)) return {};
    const std::vector<std::string>& names = w.contact.materials;
    std::vector<bool> used(names.size(), false), moves(names.size(), false);
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        used[w.bodies.material[i]] = true;
        if (w.bodies.kind[i] == BodyKind::dynamic) moves[w.bodies.material[i]] = true;
    }
    const auto damped = damped_pairs(contact);
    std::vector<std::string> undamped;
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = i; j < names.size(); ++j) {
            const bool can_touch_a_moving_body = (moves[i] && used[j]) || (moves[j] && used[i]);
            const double h_n = w.contact.at(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)).h_n;
            if (can_touch_a_moving_body && h_n == 0.0 && !damped.count(std::minmax(names[i], names[j])))
                undamped.push_back(fmt::format("{} / {}", names[i], names[j]));
        }
    if (undamped.empty()) return {};
    const bool one_material = names.size() == 1 || (undamped.size() == 1 && undamped[0] == "default / default");
    return {fmt::format(
        "contact: neither e (restitution) nor h_n (normal damping ratio) is given{}, so h_n = 0 is used: an undamped "
        "normal contact, where every impact rebounds as fast as it came and a rocking block loses no energy at its "
        "impacts; give e (e.g. e = 0.5, docs/physics.md) or h_n (h_n = 0 to keep it undamped and silence this warning)",
        one_material ? "" : fmt::format(" for the material pair{} {}", undamped.size() == 1 ? "" : "s", fmt::join(undamped, ", ")))};
}

}  // namespace blockdem
