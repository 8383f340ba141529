#include "study/convergence_plan.hpp"

#include <cmath>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "world/model.hpp"

namespace blockdem {
namespace {

// Every follow-up run has an explicit time step and writes no VTK frames (the base run keeps
// the scenario's [output]); only the summary is compared. A 3-D scenario has no report to switch
// off (its reader refuses the key).
std::vector<std::string> run_overrides(double dt_s, int dimension) {
    std::vector<std::string> out{"simulation.dt=" + toml_float(dt_s), "output.vtk=false"};
    if (dimension != 3) out.push_back("output.report=false");
    return out;
}

std::string factor_label(double f) { return fmt::format("kn_x{}", f); }

// contact.kn and contact.ks, and those of every [[contact.pairs]] entry that sets them.
std::vector<std::string> stiffness_overrides(const toml::table& scenario, double factor) {
    std::vector<std::string> out;
    const auto add = [&](const toml::node_view<const toml::node>& table, const std::string& prefix) {
        for (const char* key : {"kn", "ks"})
            if (const auto v = table[key].value<double>()) out.push_back(fmt::format("{}.{}={}", prefix, key, toml_float(factor * *v)));
    };
    add(scenario["contact"], "contact");
    if (const toml::array* pairs = scenario["contact"]["pairs"].as_array())
        for (std::size_t i = 0; i < pairs->size(); ++i)
            add(toml::node_view<const toml::node>(pairs->get(i)), fmt::format("contact.pairs.{}", i));
    return out;
}

}  // namespace

std::string to_string(RunRole role) {
    switch (role) {
        case RunRole::refinement: return "refinement";
        case RunRole::stiffness: return "stiffness";
        case RunRole::ensemble: return "ensemble";
    }
    return "?";
}

std::string toml_float(double x) {
    std::string s = fmt::format("{}", x);
    if (s.find_first_of(".eEni") == std::string::npos) s += ".0";
    return s;
}

std::vector<double> ensemble_perturbations(int n, double magnitude) {
    std::vector<double> out;
    const int half = (n + 1) / 2;
    for (int k = 1; k <= n; ++k) {
        const double sign = k % 2 == 1 ? 1.0 : -1.0;
        out.push_back(sign * magnitude * static_cast<double>((k + 1) / 2) / static_cast<double>(half));
    }
    return out;
}

std::vector<PlannedRun> plan_follow_up_runs(const toml::table& scenario, double base_dt_s, const ConvergenceOptions& options) {
    std::vector<PlannedRun> plan;
    const int dimension = scenario["dimension"].value<int>().value_or(2);
    const auto common_overrides = [dimension](double dt_s) { return run_overrides(dt_s, dimension); };
    for (const int divisor : {2, 4}) {
        PlannedRun r{fmt::format("dt_{}", divisor), RunRole::refinement, common_overrides(base_dt_s / divisor),
                     fmt::format("dt/{} = {:.4g} s", divisor, base_dt_s / divisor)};
        plan.push_back(std::move(r));
    }
    if (options.stiffness) {
        // At dt/2: the stable limit falls as 1/sqrt(kn), so dt/2 stays below it at 2 x kn
        // whatever fraction of the limit the base dt was; the 1 x run is dt_2 itself.
        for (const double f : stiffness_factors) {
            if (f == 1.0) continue;
            PlannedRun r{factor_label(f), RunRole::stiffness, common_overrides(base_dt_s / 2),
                         fmt::format("kn and ks x {} at dt/2", f)};
            const auto more = stiffness_overrides(scenario, f);
            if (more.empty()) throw InputError({"", "contact.kn", 0, 0}, "--stiffness: the scenario has no contact.kn to scale");
            r.overrides.insert(r.overrides.end(), more.begin(), more.end());
            plan.push_back(std::move(r));
        }
    }
    if (options.ensemble < 0) throw InputError({"", "--ensemble", 0, 0}, fmt::format("must be >= 0, got {}", options.ensemble));
    if (options.ensemble > 0) {
        // gravity = [gx, gy] is scaled as a whole: its magnitude is perturbed, its direction kept.
        // (3-D gravity is a magnitude acting in -z: the scalar form.)
        const toml::array* vector = scenario["simulation"]["gravity"].as_array();
        const double gx = vector && vector->size() == 2 ? (*vector)[0].value<double>().value_or(0.0) : 0.0;
        const double gy = vector && vector->size() == 2 ? (*vector)[1].value<double>().value_or(0.0) : 0.0;
        const double g = vector ? std::hypot(gx, gy)
                                : scenario["simulation"]["gravity"].value<double>().value_or(SimulationSettings{}.gravity_m_s2);
        if (g == 0.0)
            throw InputError({"", "simulation.gravity", 0, 0},
                             "--ensemble perturbs gravity, which is 0 in this scenario: there is nothing to perturb");
        if (!(options.perturbation > 0.0) || options.perturbation > 1e-3)
            throw InputError({"", "--perturbation", 0, 0}, fmt::format("must be in (0, 1e-3], got {}", options.perturbation));
        const std::vector<double> d = ensemble_perturbations(options.ensemble, options.perturbation);
        for (std::size_t k = 0; k < d.size(); ++k) {
            PlannedRun r{fmt::format("ensemble_{}", k + 1), RunRole::ensemble, common_overrides(base_dt_s),
                         fmt::format("gravity x (1 {:+.3g}) at dt", d[k])};
            r.overrides.push_back(vector ? fmt::format("simulation.gravity=[{}, {}]", toml_float(gx * (1.0 + d[k])),
                                                       toml_float(gy * (1.0 + d[k])))
                                         : fmt::format("simulation.gravity={}", toml_float(g * (1.0 + d[k]))));
            plan.push_back(std::move(r));
        }
    }
    return plan;
}

}  // namespace blockdem
