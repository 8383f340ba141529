#include "io/summary_writer.hpp"

#include "io/history_writer.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/run_checks.hpp"

namespace blockdem {
namespace {

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
    j["final_base_slip_m"] = r.base_slip_m;
    j["peak_abs_relative_displacement_m"] = r.peak_abs_relative_displacement_m;
    j["final_relative_displacement_m"] = {r.relative_displacement_m.x, r.relative_displacement_m.y};
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
    s["wall_time_s"] = info.wall_s;
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
                     {"table_work", e.table_work_j},
                     {"initial_stored", e.initial_j},
                     {"residual", e.residual_j()},
                     {"balance_error_relative", e.balance_error()}};
    nlohmann::json bodies = nlohmann::json::array();
    for (std::size_t i = 0; i < w.bodies.size(); ++i) bodies.push_back(body_summary(w, monitor.responses()[i], i));
    s["bodies"] = bodies;
    s["checks"] = run_checks(w);
    s["warnings"] = run_warnings(w);
    nlohmann::json units;
    for (const auto& [suffix, unit] : history_column_units()) units[std::string("<body>.") + suffix] = unit;
    units["t"] = "s";
    s["history_units"] = units;
    return s;
}

void write_summary(const std::filesystem::path& file, const nlohmann::json& summary) {
    write_output_file(file, summary.dump(2) + '\n');
}

}  // namespace blockdem
