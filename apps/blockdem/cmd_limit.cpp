// `blockdem limit SCENARIO [--direction +x|-x] [--non-associative] [--json FILE] [--set key=value]...`: the collapse
// multiplier of the scenario's blocks by limit analysis (analysis/limit_analysis.hpp) under a
// horizontal body force lambda m g, the tilt of a tilting table that stands for it (atan lambda),
// and the collapse mechanism: which interfaces hinge (and where), open or slide, named by their
// bodies. The geometry is the scenario's at t = 0, level (its tilt and table motion are ignored;
// no settling, no DEM run).
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analysis/limit_analysis.hpp"
#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "io/output_file.hpp"
#include "io/scenario.hpp"

namespace blockdem::cli {
namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

std::string point(Vec2 p) { return fmt::format("({:.4g}, {:.4g})", p.x, p.y); }

// "hinges at (x, y)", "opens", "slides", with the point for a hinge.
std::string describe(const BlockInterface& f, const InterfaceKinematics& k) {
    switch (k.motion) {
        case InterfaceMotion::hinge_at_end_0: return "hinges at " + point(f.end_m[0]);
        case InterfaceMotion::hinge_at_end_1: return "hinges at " + point(f.end_m[1]);
        case InterfaceMotion::opens: return "opens";
        case InterfaceMotion::slides: return "slides";
        case InterfaceMotion::locked: return "locked";
    }
    return "?";
}

void print_result(const Model& model, const LimitResult& r, const std::string& direction) {
    const auto& bodies = model.bodies;
    std::size_t dynamic = 0;
    for (const BodyDef& b : bodies) dynamic += b.kind == BodyKind::dynamic;
    fmt::print("limit analysis (static theorem, dry joints): {} dynamic bodies, {} interfaces; live load lambda m g towards {}\n",
               dynamic, r.interfaces.size(), direction);
    fmt::print("time: {:.3g} s to find the interfaces, {:.3g} s in the LP solver (GLPK)\n", r.interface_search_s, r.lp_solve_s);
    for (std::uint32_t i : r.unsupported) fmt::print("  body '{}' rests on no other body (no edge along an edge, no corner on an edge)\n", bodies[i].name);
    if (r.status == LimitStatus::no_equilibrium) {
        fmt::print("no equilibrium: the blocks cannot carry their own weight (with any horizontal load)\n");
        return;
    }
    if (r.status == LimitStatus::unbounded) {
        fmt::print("unbounded: the supports carry any horizontal load towards {}; no collapse\n", direction);
        return;
    }
    if (r.iterations > 0)
        fmt::print("non-associative friction: {} LPs after the associative one{}\n", r.iterations,
                   r.converged ? "" : " (lambda had not settled: the value is that of the last)");
    fmt::print("collapse multiplier lambda = {:.6g} (a table tilted by {:.4f} deg; a quasi-static acceleration of {:.4g} g)\n",
               r.lambda, std::atan(r.lambda) * degrees_per_radian, r.lambda);
    if (r.lambda < 0.0) fmt::print("  lambda < 0: the blocks cannot stand under their own weight alone\n");
    fmt::print("mechanism:\n");
    std::size_t moving = 0;
    for (std::size_t k = 0; k < r.interfaces.size(); ++k) {
        if (r.kinematics[k].motion == InterfaceMotion::locked) continue;
        const BlockInterface& f = r.interfaces[k];
        fmt::print("  {} / {}: {}\n", bodies[f.body_a].name, bodies[f.body_b].name, describe(f, r.kinematics[k]));
        ++moving;
    }
    if (moving == 0) fmt::print("  (no interface moves)\n");
    const bool slides = std::any_of(r.kinematics.begin(), r.kinematics.end(),
                                    [](const InterfaceKinematics& k) { return k.motion == InterfaceMotion::slides; });
    if (slides && r.iterations == 0)
        fmt::print("note: the mechanism slides; the LP's friction is associative (a sliding joint dilates), so where sliding "
                   "governs its lambda is an upper value: see --non-associative (docs/limit_analysis.md)\n");
}

nlohmann::json to_json(const Model& model, const LimitResult& r, const std::string& scenario, const std::string& direction) {
    const auto& bodies = model.bodies;
    nlohmann::json j;
    j["scenario"] = scenario;
    j["direction"] = direction;
    j["status"] = to_string(r.status);
    j["friction"] = r.iterations > 0 ? "non_associative" : "associative";
    if (r.iterations > 0) {
        j["iterations"] = r.iterations;
        j["converged"] = r.converged;
    }
    if (r.status == LimitStatus::collapse) {
        j["lambda"] = r.lambda;
        j["tilt_deg"] = std::atan(r.lambda) * degrees_per_radian;
    }
    j["unsupported"] = nlohmann::json::array();
    for (std::uint32_t i : r.unsupported) j["unsupported"].push_back(bodies[i].name);
    j["interfaces"] = nlohmann::json::array();
    for (std::size_t k = 0; k < r.interfaces.size(); ++k) {
        const BlockInterface& f = r.interfaces[k];
        nlohmann::json e{{"body_a", bodies[f.body_a].name},
                         {"body_b", bodies[f.body_b].name},
                         {"end_0_m", {f.end_m[0].x, f.end_m[0].y}},
                         {"end_1_m", {f.end_m[1].x, f.end_m[1].y}},
                         {"normal", {f.normal.x, f.normal.y}},
                         {"mu", f.mu}};
        if (r.status == LimitStatus::collapse) {
            const InterfaceForces& F = r.forces[k];
            e["normal_N"] = {F.normal_N[0], F.normal_N[1]};
            e["shear_N"] = {F.shear_N[0], F.shear_N[1]};
            e["thrust_point_m"] = {F.thrust_point_m.x, F.thrust_point_m.y};
            e["motion"] = to_string(r.kinematics[k].motion);
        }
        j["interfaces"].push_back(e);
    }
    if (r.status == LimitStatus::collapse) {
        j["mechanism"] = nlohmann::json::array();
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (bodies[i].kind != BodyKind::dynamic) continue;
            const BodyMotion& u = r.mechanism[i];
            j["mechanism"].push_back({{"body", bodies[i].name}, {"velocity", {u.velocity.x, u.velocity.y}}, {"rotation_per_m", u.rotation}});
        }
    }
    return j;
}

}  // namespace

void add_limit_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("limit", "Collapse multiplier of the blocks under a horizontal body force, by limit analysis");
    auto scenario = std::make_shared<std::string>();
    auto direction = std::make_shared<std::string>("+x");
    auto json_file = std::make_shared<std::string>();
    auto sets = std::make_shared<std::vector<std::string>>();
    auto non_associative = std::make_shared<bool>(false);
    cmd->add_option("scenario", *scenario, "scenario file (TOML)")->required();
    cmd->add_option("--direction", *direction, "direction of the live load lambda m g: +x or -x")
        ->check(CLI::IsMember({"+x", "-x"}));
    cmd->add_option("--json", *json_file, "also write the result (forces, thrust points, mechanism) to this JSON file")
        ->check(output_file());
    cmd->add_option("--set", *sets, "override a scenario key: --set contact.mu=0.5 (repeatable)");
    cmd->add_flag("--non-associative", *non_associative,
                  "joints slip without dilating (iterated LPs; default: the associative static theorem)");
    cmd->callback([=] {
        const LoadedScenario s = load_scenario(*scenario, *sets, false);
        LimitOptions options;
        options.live_load_direction = {*direction == "+x" ? 1.0 : -1.0, 0.0};
        if (*non_associative) options.friction = FrictionFlow::non_associative;
        const LimitResult r = solve_limit_analysis(s.model, options);
        print_result(s.model, r, *direction);
        if (!json_file->empty()) write_output_file(*json_file, to_json(s.model, r, *scenario, *direction).dump(2) + "\n");
    });
}

}  // namespace blockdem::cli
