// `blockdem check SCENARIO [--set key=value]...`: validates the scenario and prints the derived
// quantities: mass and inertia of each body, kn and ks (and how the rule derived them from the
// material), h_n per material pair, C_n and C_s of the pairs touching at the start, the contact
// period and the static overlap, the critical and the chosen time step, and the table motion.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/blockdem/check_3d.hpp"
#include "apps/blockdem/commands.hpp"
#include "dynamics/critical_time_step.hpp"
#include "io/run_checks.hpp"
#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/material_stiffness.hpp"
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

std::string describe_side(const JointSide& s) {
    return fmt::format("E = {:.4g} Pa, nu = {:.3g}, typical block {:.4g} m high, {:.4g} m wide, {:.4g} m thick",
                       s.material.young_modulus_pa, s.material.poisson_ratio, s.block.height_m, s.block.width_m,
                       s.block.thickness_m);
}

// How the rule got a pair's kn and ks (docs/physics.md, "Choosing the contact stiffness").
void print_stiffness_origin(const StiffnessOrigin& o) {
    if (!o.derived) return;
    if (o.kn_given && o.ks_given) {
        fmt::print("    kn and ks given for this pair (the rule would give kn = {:.4g}, ks = {:.4g} N/m)\n", o.rule.kn_N_m,
                   o.rule.ks_N_m);
        return;
    }
    const std::string a = describe_side(o.a);
    const std::string b = describe_side(o.b);
    fmt::print("    rule block_deformability: {}\n", a == b ? a + " on both sides" : a + " against " + b);
    fmt::print("    per unit area kn'' = {:.4g} Pa/m, ks'' = {:.4g} Pa/m; per unit length of joint kn' = {:.4g} N/m/m; "
               "each point carries {:.4g} m x {:.4g} m{}{}\n",
               o.rule.kn_per_area_pa_m, o.rule.ks_per_area_pa_m, o.rule.kn_per_area_pa_m * o.rule.thickness_m,
               o.rule.tributary_length_m, o.rule.thickness_m, o.kn_given ? "; kn given for this pair" : "",
               o.ks_given ? "; ks given for this pair" : "");
}

// What the stiffness means for each dynamic body: the period of its mass on one contact point,
// T = 2 pi sqrt(m / kn), and the overlap its own weight makes on one point (rocking on a corner),
// m g / kn, against its height. Per material pair, the extremes over the bodies, named.
void print_stiffness_effects(const World& w) {
    const Bodies& b = w.bodies;
    const auto& m = w.contact.materials;
    std::vector<bool> used(m.size(), false);
    for (std::size_t i = 0; i < b.size(); ++i) used[b.material[i]] = true;
    fmt::print("contact period T = 2 pi sqrt(m / kn) and static overlap m g / kn of a dynamic body on one point:\n");
    for (std::uint32_t mi = 0; mi < m.size(); ++mi) {
        for (std::uint32_t mj = 0; mj < m.size(); ++mj) {
            if (!used[mj]) continue;
            // (A per-length joint's point stiffness depends on the contact: the start contacts show it.)
            if (w.contact.at(mi, mj).stiffness == StiffnessBasis::per_length) continue;
            const double kn = w.contact.at(mi, mj).kn_N_m;
            double shortest_s = INFINITY, largest_fraction = 0.0, largest_overlap_m = 0.0;
            std::string shortest_body, largest_body;
            for (std::size_t i = 0; i < b.size(); ++i) {
                if (b.kind[i] != BodyKind::dynamic || b.material[i] != mi) continue;
                const double period_s = 2.0 * std::numbers::pi * std::sqrt(b.mass_kg[i] / kn);
                const double overlap_m = b.mass_kg[i] * w.settings.gravity_m_s2 / kn;
                const std::span<const Vec2> corners(&b.world_vertices_m[b.vertex_begin[i]], b.vertex_count[i]);
                const double fraction = overlap_m / block_dimensions(corners, 1.0).height_m;
                if (period_s < shortest_s) {
                    shortest_s = period_s;
                    shortest_body = b.name[i];
                }
                if (fraction > largest_fraction) {
                    largest_fraction = fraction;
                    largest_overlap_m = overlap_m;
                    largest_body = b.name[i];
                }
            }
            if (shortest_body.empty()) continue;
            fmt::print("  {} on {} (kn = {:.4g} N/m): shortest T = {:.4g} s ({}); largest overlap {:.3g} m = {:.3g} of "
                       "the body's height ({})\n",
                       m[mi], m[mj], kn, shortest_s, shortest_body, largest_overlap_m, largest_fraction, largest_body);
        }
    }
    fmt::print("  (a body carrying others sinks more: the overlap grows with the weight above it)\n");
}

void print_contact(const World& w) {
    fmt::print("contact parameters per material pair:\n");
    const auto& m = w.contact.materials;
    for (std::uint32_t i = 0; i < m.size(); ++i) {
        for (std::uint32_t j = i; j < m.size(); ++j) {
            const ContactParameters& p = w.contact.at(i, j);
            if (p.stiffness == StiffnessBasis::per_length) {
                fmt::print("  {} / {}: per unit length of joint: kn = {:.4g} Pa/m, ks = {:.4g} Pa/m (a point: times its "
                           "tributary length and the thickness; see the start contacts), mu = {:.4g}, cohesion = {:.4g} "
                           "Pa, tensile_strength = {:.4g} Pa, residual_mu = {:.4g} (bonded points only), h_n = {:.4g}, "
                           "h_s = {:.4g}, termination = {}\n",
                           m[i], m[j], p.kn_pa_m, p.ks_pa_m, p.mu, p.cohesion_pa, p.tensile_strength_pa,
                           residual_friction(p), p.h_n, p.h_s, to_string(p.termination));
                continue;
            }
            fmt::print("  {} / {}: kn = {:.4g} N/m, ks = {:.4g} N/m, mu = {:.4g}, h_n = {:.4g} (paper e = {:.4g}, "
                       "rebound e = {:.4g}), h_s = {:.4g}, termination = {}\n",
                       m[i], m[j], p.kn_N_m, p.ks_N_m, p.mu, p.h_n, p.h_n < 1.0 ? restitution_paper(p.h_n) : 0.0,
                       restitution_of(p.h_n, p.termination), p.h_s, to_string(p.termination));
            if (!w.contact.origins.empty()) print_stiffness_origin(w.contact.origins[i * m.size() + j]);
        }
    }
}

// The dashpots as the contact law uses them (C = 2 h sqrt(M k), M the pair's reduced mass shared
// by its points) for the pairs that touch at the start, after any settling: the contacts the
// stable time step is computed from (dynamics/critical_time_step.hpp: touching within a
// millionth of a body's size). A pair that never touches has no dashpot to report, and in an
// assembly the list would otherwise be every brick against every table. The first `shown`
// pairs, then a count; then the dynamic bodies that touch nothing.
void print_start_contacts(const World& w, std::size_t shown = 20) {
    const Bodies& b = w.bodies;
    const std::vector<StiffnessPoint> points = start_stiffness_points(w);
    std::vector<std::string> free;
    std::size_t pairs = 0;
    fmt::print("dashpots of the pairs touching at the start (C = 2 h sqrt(M k), M = the pair's reduced mass / its "
               "points):\n");
    // One line per body pair, however many part pairs of concave bodies it has and wherever the
    // table puts them: its first point stands for it, with the count of all its points.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> points_of_pair;
    std::vector<std::size_t> first_points;
    for (std::size_t k = 0; k < points.size(); ++k)
        if (points_of_pair[{points[k].a, points[k].b}]++ == 0) first_points.push_back(k);
    for (const std::size_t k : first_points) {
        const StiffnessPoint& p = points[k];
        const std::size_t count = points_of_pair[{p.a, p.b}];
        if (p.a >= b.size()) {  // a landing: the stable step's stand-in for a body that touches nothing
            free.push_back(b.name[p.b]);
            continue;
        }
        if (b.kind[p.a] != BodyKind::dynamic && b.kind[p.b] != BodyKind::dynamic) continue;
        if (++pairs > shown) continue;
        const double reduced_mass_kg = 1.0 / (b.inv_mass_1_kg[p.a] + b.inv_mass_1_kg[p.b]);
        const bool per_length = w.contact.at(b.material[p.a], b.material[p.b]).stiffness == StiffnessBasis::per_length;
        fmt::print("  {} / {}: {} point{}, M = {:.4g} kg; C_n = {:.4g}, C_s = {:.4g} N s/m per point{}\n", b.name[p.a],
                   b.name[p.b], count, count == 1 ? "" : "s", reduced_mass_kg, p.cn_N_s_m, p.cs_N_s_m,
                   per_length ? fmt::format("; per-length joint: kn = {:.4g}, ks = {:.4g} N/m per point", p.kn_N_m, p.ks_N_m)
                              : "");
    }
    if (pairs == 0) fmt::print("  none\n");
    if (pairs > shown) fmt::print("  ... and {} more pairs\n", pairs - shown);
    if (!free.empty())
        fmt::print("  touching nothing at the start (falls or flies until it meets a body): {}{}\n",
                   fmt::join(free.begin(), free.begin() + static_cast<std::ptrdiff_t>(std::min(free.size(), shown)), ", "),
                   free.size() > shown ? fmt::format(" and {} more", free.size() - shown) : "");
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
        toml::table root = load_toml_file(*scenario);
        if (scenario_dimension(root, *scenario) == 3) return check_scenario_3d(std::move(root), *scenario, *sets);
        const LoadedScenario s = load_scenario(*scenario, *sets);
        const World& w = s.world;
        fmt::print("scenario {}: valid\n", *scenario);
        for (const std::string& warning : input_warnings(s.root, w)) fmt::print(stderr, "WARNING: {}\n", warning);
        fmt::print("duration {:g} s, gravity {:g} m/s^2, output every {:g} s\n", w.settings.duration_s,
                   w.settings.gravity_m_s2, w.settings.output_interval_s);
        if (w.settings.tilt_rad != 0.0 || w.settings.tilt_rate_rad_s != 0.0)
            fmt::print("table tilted by {:.4g} deg (+x end up), gravity ({:.4g}, {:.4g}) m/s^2; tilt rising {:g} deg/s to "
                       "{:.4g} deg at the end\n",
                       w.settings.tilt_rad * 180.0 / std::numbers::pi, w.gravity_now_m_s2.x, w.gravity_now_m_s2.y,
                       w.settings.tilt_rate_rad_s * 180.0 / std::numbers::pi,
                       tilt_at_rad(w.settings, w.settings.duration_s) * 180.0 / std::numbers::pi);
        print_bodies(w);
        print_contact(w);
        print_start_contacts(w);
        print_stiffness_effects(w);
        fmt::print("time step: dt = {:.4g} s; stable limit {:.4g} s (dt / limit = {:.3f}); {} steps\n", w.dt_s,
                   w.critical_dt_s, w.dt_s / w.critical_dt_s, std::llround(w.settings.duration_s / w.dt_s));
        fmt::print("  (the limit of the highest contact mode at the start, mostly body '{}'; every dt <= {:.4g} s is "
                   "proven stable for those contacts; docs/physics.md)\n",
                   w.stability.least_limit_body, w.proven_stable_dt_s);
        if (w.settling)
            fmt::print("settling: at rest after {:.4g} s, {} steps (every body's kinetic energy < {:.3g} x m g L over {:g} s; "
                       "friction {}); the bodies moved by up to {:.3g} m ('{}') and turned by up to {:.3g} rad ('{}')\n",
                       w.settling->time_s, w.settling->steps, s.model.settling->kinetic_ratio, s.model.settling->window_s,
                       w.settling->friction_held ? "held" : "actual", w.settling->largest_move_m,
                       w.settling->largest_move_body, w.settling->largest_turn_rad, w.settling->largest_turn_body);
        print_motion(w);
    });
}

}  // namespace blockdem::cli
