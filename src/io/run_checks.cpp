#include "io/run_checks.hpp"

#include <set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

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
