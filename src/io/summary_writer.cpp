#include "io/summary_writer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include "io/history_writer.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/run_checks.hpp"

namespace blockdem {
namespace {

nlohmann::json time_or_null(double t_s) { return t_s >= 0.0 ? nlohmann::json(t_s) : nlohmann::json(nullptr); }
nlohmann::json point(Vec2 p) { return {p.x, p.y}; }

// The outcome (world/outcome.hpp) and what decided it.
void add_outcome(nlohmann::json& j, const World& w, const BodyRecord& record, const ClassifiedOutcome& o) {
    j["outcome"] = to_string(o.outcome);
    j["outcome_time_s"] = time_or_null(o.time_s);
    j["failed"] = is_failure(o.outcome);
    nlohmann::json supporters = nlohmann::json::array();
    for (std::uint32_t s : record.supporters) supporters.push_back(w.bodies.name[s]);
    j["supporters"] = supporters;
    j["touches_a_supporter"] = record.touches_a_supporter;
    j["support_lost_time_s"] = time_or_null(record.support_lost_time_s);
    j["final_drop_m"] = record.drop_m;
    if (o.outcome == Outcome::fell)
        j["fell"] = {{"came_to_rest", o.at_rest}, {"position_m", point(o.rest_position_m)}};
    if (o.outcome == Outcome::left_model)
        j["left_model"] = {{"time_s", record.left_model_time_s}, {"position_m", point(record.left_model_position_m)}};
}

nlohmann::json domain_summary(const World& w) {
    const ModelDomain& d = w.domain;
    nlohmann::json left = nlohmann::json::array();
    for (const BodyLeftModel& l : d.left)
        left.push_back({{"body", w.bodies.name[l.body]}, {"time_s", l.time_s}, {"position_m", point(l.position_m)},
                        {"velocity_m_s", point(l.velocity_m_s)}});
    return {{"from", d.from_scenario ? "scenario" : "derived"},
            {"lo_m", {finite_or_null(d.box_m.lo.x), finite_or_null(d.box_m.lo.y)}},
            {"hi_m", {finite_or_null(d.box_m.hi.x), finite_or_null(d.box_m.hi.y)}},
            {"margin_m", d.margin_m},
            {"left", left}};
}

nlohmann::json thresholds_summary(const OutcomeThresholds& t) {
    return {{"rocking_ratio", t.rocking_ratio},       {"slip_ratio", t.slip_ratio},
            {"fall_drop_ratio", t.fall_drop_ratio},   {"displaced_ratio", t.displaced_ratio},
            {"rest_speed_m_s", t.rest_speed_m_s},     {"support_window_s", t.support_window_s},
            {"elastic_slip_factor", elastic_slip_factor},
            {"slid_rule", "slid: a contact point on the body below (judged_on) slid, and the base corner moved on that body by "
                          "more than slip_threshold_m = max(slip_ratio x base length, elastic_slip_factor x "
                          "peak_elastic_shear_displacement_m); rocked: peak |rotation relative to judged_on| >= rocking_ratio x "
                          "the critical angle"}};
}

// Gravity in the model's frame: its magnitude, the table's tilt at t = 0 and at the end.
nlohmann::json gravity_summary(const World& w) {
    constexpr double deg_per_rad = 180.0 / std::numbers::pi;
    const Vec2 start = gravity_at(w.settings, 0.0);
    return {{"magnitude_m_s2", w.settings.gravity_m_s2},
            {"vector_at_start_m_s2", point(start)},
            {"tilt_deg", w.settings.tilt_rad * deg_per_rad},
            {"tilt_rate_deg_s", w.settings.tilt_rate_rad_s * deg_per_rad},
            {"tilt_at_end_deg", tilt_at_rad(w.settings, w.time_s) * deg_per_rad}};
}

// On a tilting table (tilt_rate_deg_s): the table's tilt when the body first slid, first
// rocked (tipped) and overturned (null: it did not).
nlohmann::json tilt_at_events(const World& w, const BodyResponse& r) {
    constexpr double deg_per_rad = 180.0 / std::numbers::pi;
    auto tilt_deg = [&](double t_s) {
        return t_s >= 0.0 ? nlohmann::json(tilt_at_rad(w.settings, t_s) * deg_per_rad) : nlohmann::json(nullptr);
    };
    return {{"slip_onset", tilt_deg(r.slip_onset_s)},
            {"rocking_onset", tilt_deg(r.rocking_onset_s)},
            {"overturning", tilt_deg(r.overturned() ? r.last_crossing_s : -1.0)}};
}

nlohmann::json body_summary(const World& w, const BodyResponse& r, std::size_t i) {
    const Bodies& b = w.bodies;
    nlohmann::json j;
    j["name"] = b.name[i];
    j["kind"] = to_string(b.kind[i]);
    j["mass_kg"] = b.mass_kg[i];
    j["inertia_kg_m2"] = b.inertia_kg_m2[i];
    if (b.kind[i] != BodyKind::dynamic) return j;
    j["critical_angle_ccw_rad"] = r.alpha_ccw_rad;
    j["critical_angle_cw_rad"] = r.alpha_cw_rad;
    j["peak_abs_rotation_rad"] = r.peak_abs_rotation_rad;
    j["time_of_peak_rotation_s"] = r.time_of_peak_rotation_s;
    j["final_rotation_rad"] = b.rotation_rad[i];
    j["rocked"] = r.rocked();
    j["overturned"] = r.overturned();
    j["overturning_time_s"] = r.overturned() ? nlohmann::json(r.last_crossing_s) : nlohmann::json(nullptr);
    j["initial_base_tilt_rad"] = r.base_tilt_rad;
    j["slid"] = r.slid();
    j["sliding_time_s"] = r.sliding_time_s;
    j["peak_abs_base_slip_m"] = r.peak_abs_base_slip_m;
    // What "slid" and "rocked" were judged on (world/response_monitor.hpp).
    j["judged_on"] = r.support_body >= 0 ? b.name[static_cast<std::size_t>(r.support_body)] : "ground";
    j["slip_threshold_m"] = r.slip_threshold();
    j["peak_elastic_shear_displacement_m"] = r.peak_elastic_shear_m;
    j["peak_abs_rotation_on_support_rad"] = r.peak_abs_rotation_on_support_rad;
    j["final_base_slip_m"] = r.base_slip_m;
    j["peak_abs_relative_displacement_m"] = r.peak_abs_relative_displacement_m;
    j["final_relative_displacement_m"] = {r.relative_displacement_m.x, r.relative_displacement_m.y};
    j["final_position_m"] = point(b.position_m[i]);
    if (w.settings.tilt_rate_rad_s != 0.0) j["table_tilt_deg_at"] = tilt_at_events(w, r);
    return j;
}

}  // namespace

nlohmann::json make_summary(const World& w, const ResponseMonitor& monitor, const RunInfo& info) {
    nlohmann::json s;
    s["scenario"] = info.scenario;
    s["status"] = info.status;
    if (!info.error.empty()) s["error"] = info.error;
    s["time_s"] = w.time_s;
    s["steps"] = w.step_index;
    s["dt_s"] = w.dt_s;
    s["critical_dt_s"] = w.critical_dt_s;
    s["broad_phase_rebuilds"] = w.broad_phase_rebuilds;
    s["displacements_relative_to"] =
        monitor.reference_body() >= 0 ? w.bodies.name[static_cast<std::size_t>(monitor.reference_body())] : "ground";
    const EnergyLedger& e = w.energy;
    s["energy_j"] = {{"kinetic", e.kinetic_j},
                     {"gravitational_change", e.gravitational_j - e.initial_gravitational_j},
                     {"elastic", e.elastic_j},
                     {"normal_dashpot_dissipated", e.normal_dashpot_j},
                     {"shear_dashpot_dissipated", e.shear_dashpot_j},
                     {"friction_dissipated", e.friction_j},
                     {"bond_breakage_dissipated", e.bond_breakage_j},
                     {"table_work", e.table_work_j},
                     {"removed_with_bodies_leaving", e.removed_j},
                     {"tilt_work", e.tilt_work_j},
                     {"initial_stored", e.initial_j},
                     {"residual", e.residual_j()},
                     {"balance_error_relative", e.balance_error()}};
    const std::vector<BodyRecord> records = monitor.records(w);
    const std::vector<ClassifiedOutcome> outcomes = classify_outcomes(records, monitor.thresholds());
    nlohmann::json bodies = nlohmann::json::array();
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        bodies.push_back(body_summary(w, monitor.responses()[i], i));
        if (w.bodies.kind[i] == BodyKind::dynamic) add_outcome(bodies.back(), w, records[i], outcomes[i]);
    }
    s["bodies"] = bodies;
    s["checks"] = run_checks(w);
    s["warnings"] = run_warnings(w);
    for (const std::string& warning : untouched_body_warnings(records, w.bodies.name, w.time_s)) s["warnings"].push_back(warning);
    s["collapse"] = collapse_json(summarize_collapse_by_group(w.bodies.assembly, records, outcomes, monitor.thresholds()),
                                   w.bodies.name);
    s["domain"] = domain_summary(w);
    s["outcome_thresholds"] = thresholds_summary(monitor.thresholds());
    s["gravity"] = gravity_summary(w);
    s["settling"] = settling_summary(w.settling);
    nlohmann::json units;
    for (const auto& [suffix, unit] : history_column_units()) units[std::string("<body>.") + suffix] = unit;
    units["t"] = "s";
    s["history_units"] = units;
    return s;
}

void write_summary(const std::filesystem::path& file, const nlohmann::json& summary) {
    write_output_file(file, summary.dump(2) + '\n');
}

nlohmann::json settling_summary(const std::optional<SettlingRecord>& settled) {
    if (!settled) return nullptr;
    const SettlingRecord& s = *settled;
    return {{"time_s", s.time_s},
            {"steps", s.steps},
            {"friction", s.friction_held ? "held" : "actual"},
            {"kinetic_ratio", s.kinetic_ratio},
            {"largest_displacement_m", s.largest_move_m},
            {"largest_displacement_body", s.largest_move_body},
            {"largest_rotation_rad", s.largest_turn_rad},
            {"largest_rotation_body", s.largest_turn_body}};
}

nlohmann::json collapse_json(const std::vector<CollapseSummary>& groups, const std::vector<std::string>& body_names) {
    nlohmann::json out = nlohmann::json::array();
    for (const CollapseSummary& c : groups)
        out.push_back({{"group", c.group},
                       {"blocks", c.blocks},
                       {"fell", c.fell},
                       {"overturned", c.overturned},
                       {"left_model", c.left_model},
                       {"displaced_mass_fraction", c.displaced_mass_fraction},
                       {"first_to_go", c.first_to_go >= 0 ? nlohmann::json(body_names[static_cast<std::size_t>(c.first_to_go)])
                                                          : nlohmann::json(nullptr)},
                       {"first_to_go_time_s", time_or_null(c.first_to_go_time_s)}});
    return out;
}

}  // namespace blockdem
