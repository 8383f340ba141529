// `blockdem check SCENARIO [--set key=value]...`: validates the scenario and prints the derived
// quantities: mass and inertia of each body, h_n, C_n, C_s per material pair, the critical and
// the chosen time step, and the table motion.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "io/scenario.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/restitution.hpp"

namespace blockdem::cli {
namespace {

void print_bodies(const World& w) {
    const Bodies& b = w.bodies;
    fmt::print("bodies ({}):\n", b.size());
    fmt::print("  {:<16} {:<8} {:>12} {:>14} {:>22} {:>10}\n", "name", "kind", "mass [kg]", "inertia [kg m^2]",
               "centroid [m]", "material");
    for (std::size_t i = 0; i < b.size(); ++i)
        fmt::print("  {:<16} {:<8} {:>12.5g} {:>14.5g} {:>22} {:>10}\n", b.name[i], to_string(b.kind[i]), b.mass_kg[i],
                   b.inertia_kg_m2[i], fmt::format("({:.4g}, {:.4g})", b.position_m[i].x, b.position_m[i].y),
                   w.contact.materials[b.material[i]]);
}

void print_contact(const World& w) {
    const Bodies& b = w.bodies;
    fmt::print("contact parameters per material pair:\n");
    const auto& m = w.contact.materials;
    for (std::uint32_t i = 0; i < m.size(); ++i) {
        for (std::uint32_t j = i; j < m.size(); ++j) {
            const ContactParameters& p = w.contact.at(i, j);
            fmt::print("  {} / {}: kn = {:.4g} N/m, ks = {:.4g} N/m, mu = {:.4g}, h_n = {:.4g} (paper e = {:.4g}, "
                       "rebound e = {:.4g}), h_s = {:.4g}\n",
                       m[i], m[j], p.kn_N_m, p.ks_N_m, p.mu, p.h_n, p.h_n < 1.0 ? restitution_paper(p.h_n) : 0.0,
                       restitution_no_tension(p.h_n), p.h_s);
        }
    }
    // Dashpot coefficients for each dynamic body against a static one (M = its mass, one point)
    // and lying flat on two points (M = m / 2 per point).
    fmt::print("dashpots of each dynamic body on a fixed or driven body (C = 2 h sqrt(M k)):\n");
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic) continue;
        for (std::size_t s = 0; s < b.size(); ++s) {
            if (b.kind[s] == BodyKind::dynamic) continue;
            const ContactParameters& p = w.contact.at(b.material[i], b.material[s]);
            const DashpotCoefficients one = dashpot_coefficients(p, b.mass_kg[i]);
            const DashpotCoefficients two = dashpot_coefficients(p, 0.5 * b.mass_kg[i]);
            fmt::print("  {} on {}: one point C_n = {:.4g}, C_s = {:.4g} N s/m; two points C_n = {:.4g}, C_s = {:.4g} "
                       "N s/m each\n",
                       b.name[i], b.name[s], one.cn_N_s_m, one.cs_N_s_m, two.cn_N_s_m, two.cs_N_s_m);
        }
    }
}

void print_motion(const World& w) {
    const double end = w.settings.duration_s;
    auto line = [&](const char* name, const ComponentMotion& m) {
        const MotionSample last = sample(m, end);
        fmt::print("  {}: {}; peak {:.4g} m/s^2 ({:.4g} g); at t = {:g} s: velocity {:.4g} m/s, displacement {:.4g} m\n",
                   name, describe(m), peak_acceleration(m), peak_acceleration(m) / standard_gravity_m_s2, end,
                   last.velocity_m_s, last.displacement_m);
    };
    fmt::print("table motion:\n");
    line("horizontal", w.table_motion.horizontal);
    line("vertical", w.table_motion.vertical);
}

}  // namespace

void add_check_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("check", "Validate a scenario and print its derived quantities");
    auto scenario = std::make_shared<std::string>();
    auto sets = std::make_shared<std::vector<std::string>>();
    cmd->add_option("scenario", *scenario, "scenario file (TOML)")->required();
    cmd->add_option("--set", *sets, "override a scenario key: --set contact.h_s=0.5 (repeatable)");
    cmd->callback([=] {
        const LoadedScenario s = load_scenario(*scenario, *sets);
        const World& w = s.world;
        fmt::print("scenario {}: valid\n", *scenario);
        fmt::print("duration {:g} s, gravity {:g} m/s^2, output every {:g} s\n", w.settings.duration_s,
                   w.settings.gravity_m_s2, w.settings.output_interval_s);
        print_bodies(w);
        print_contact(w);
        fmt::print("time step: dt = {:.4g} s; stable limit {:.4g} s (dt / limit = {:.3f}); {} steps\n", w.dt_s,
                   w.critical_dt_s, w.dt_s / w.critical_dt_s, std::llround(w.settings.duration_s / w.dt_s));
        print_motion(w);
    });
}

}  // namespace blockdem::cli
