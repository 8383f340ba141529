// `blockdem converge SCENARIO --out DIR [--stiffness] [--ensemble N] [--rtol 0.05] ...`: the
// scenario at dt, dt/2 and dt/4 (docs/convergence.md). No physics here: the study is
// src/study/convergence_study.hpp; this file parses options and prints the verdict.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "study/convergence_study.hpp"
#include "world/simulation_error.hpp"

namespace blockdem::cli {
namespace {

struct QuantityLabel {
    const char* key;
    const char* label;
};
constexpr QuantityLabel labels[] = {{"peak_rotation_rad", "peak rotation [rad]"},  {"peak_slip_m", "peak slip [m]"},
                                    {"final_slip_m", "final slip [m]"},            {"overturning_time_s", "overturned at [s]"},
                                    {"overturned", "overturned"},                  {"outcome", "outcome"}};

// A 3-D summary's terms for the same quantities (study/convergence_verdict.hpp).
constexpr QuantityLabel labels_3d[] = {{"peak_rotation_rad", "peak tilt [rad]"},
                                       {"peak_slip_m", "peak |slip| [m]"},
                                       {"final_slip_m", "final |slip| [m]"}};

// Set once per study by print_study, before any table is printed.
struct Labels {
    bool three_d = false;
    std::string of(const std::string& key) const {
        if (three_d)
            for (const auto& l : labels_3d)
                if (key == l.key) return l.label;
        for (const auto& l : labels)
            if (key == l.key) return l.label;
        return key;
    }
};

std::string value_text(const std::optional<double>& v) { return v ? fmt::format("{:.4g}", *v) : "-"; }
std::string change_text(const std::optional<double>& v) { return v ? fmt::format("{:.2f}%", 100.0 * *v) : "-"; }

void print_dt_table(const BodyConvergence& b, const Labels& label) {
    fmt::print("  {:<22}{:>16}{:>16}{:>16}{:>13}{:>13}  {}\n", "quantity", "dt", "dt/2", "dt/4", "dt -> dt/2", "dt/2 -> dt/4",
               "");
    for (const QuantityComparison& q : b.dt) {
        std::vector<std::string> v;
        for (std::size_t i = 0; i < 3; ++i) v.push_back(q.discrete ? q.words[i].value_or("-") : value_text(q.values[i]));
        const std::string note = !q.judged ? "(not judged)" : q.converged ? "ok" : "NOT CONVERGED";
        fmt::print("  {:<22}{:>16}{:>16}{:>16}{:>13}{:>13}  {}\n", label.of(q.quantity), v[0], v[1], v[2],
                   q.discrete ? "" : change_text(q.changes[0]), q.discrete ? "" : change_text(q.changes[1]), note);
    }
}

void print_ensemble(const BodyConvergence& b, std::size_t members, const Labels& label) {
    fmt::print("  ensemble of {} runs at dt: overturned in {:.0f}%\n", members, 100.0 * b.fraction_overturned.value_or(0.0));
    for (const EnsembleSpread& s : b.ensemble) {
        if (s.discrete) {
            fmt::print("    {:<22} seen: {}{}\n", label.of(s.quantity), fmt::join(s.distinct, ", "), s.chaotic ? "  CHAOTIC" : "");
        } else if (s.mean) {
            fmt::print("    {:<22} mean {:.4g}, min {:.4g}, max {:.4g}, spread {}{}\n", label.of(s.quantity), *s.mean, *s.min,
                       *s.max, change_text(s.relative_spread),
                       !s.judged ? "  (not judged)" : s.chaotic ? "  CHAOTIC" : s.sensitive ? "  sensitive" : "");
        }
    }
}

void print_stiffness(const BodyConvergence& b, const Labels& label) {
    fmt::print("  contact stiffness x 0.5 / 1 / 2 (at dt/2):\n");
    for (const StiffnessComparison& s : b.stiffness) {
        std::vector<std::string> v;
        for (std::size_t i = 0; i < 3; ++i) v.push_back(s.discrete ? s.words[i].value_or("-") : value_text(s.values[i]));
        fmt::print("    {:<22}{:>16}{:>16}{:>16}{:>13}  {}\n", label.of(s.quantity), v[0], v[1], v[2],
                   s.discrete ? "" : change_text(s.max_change), !s.judged ? "(not judged)" : s.sensitive ? "SENSITIVE" : "ok");
    }
}

// The stiffness verdict with its largest change, so that an elastic tilt of a mrad is told
// from a collapse at one stiffness only.
void print_stiffness_line(const ConvergenceResult& r, const Labels& label) {
    if (!*r.stiffness_sensitive) {
        fmt::print("contact stiffness: the answer does not depend on kn within the tolerance\n");
        return;
    }
    const BodyConvergence* body = nullptr;
    const StiffnessComparison* worst = nullptr;
    for (const auto& b : r.bodies)
        for (const auto& s : b.stiffness) {
            if (!s.sensitive) continue;
            // A changed flag outranks any relative change.
            const double change = s.discrete ? 1e300 : s.max_change.value_or(0.0);
            const double best = !worst ? -1.0 : worst->discrete ? 1e300 : worst->max_change.value_or(0.0);
            if (change > best) body = &b, worst = &s;
        }
    std::vector<std::string> v;
    for (std::size_t i = 0; i < 3; ++i) v.push_back(worst->discrete ? worst->words[i].value_or("-") : value_text(worst->values[i]));
    fmt::print("contact stiffness: the answer DEPENDS on kn; most of all {} {} at kn x 0.5 / 1 / 2: {} / {} / {}\n", body->name,
               label.of(worst->quantity), v[0], v[1], v[2]);
}

int rank(Verdict v) { return v == Verdict::chaotic ? 0 : v == Verdict::not_converged ? 1 : 2; }

void print_study(const ConvergenceStudy& study, const ConvergenceTolerance& tol, std::size_t show) {
    const auto& r = study.result;
    const nlohmann::json& j = study.report;
    const Labels label{j.value("dimension", 2) == 3};
    // (0: a 3-D model with no body resting on another at the start has no bound there.)
    const double critical_dt_s = j["critical_dt_s"].get<double>();
    const std::string limit = critical_dt_s > 0.0 ? fmt::format("stable limit {:.4g} s", critical_dt_s) : "no stable limit at the start";
    fmt::print("base dt = {:.4g} s ({}); tolerance: relative change <= {:g}% at dt/2 -> dt/4, "
               "floors {:g} rad (rotation), {:g} m (slip), {:g} s (overturning time)\n",
               j["base_dt_s"].get<double>(), limit, 100.0 * tol.rtol, tol.floor_rotation_rad, tol.floor_slip_m, tol.floor_time_s);
    // The bodies that are not converged first; a large assembly prints only the first `show`.
    std::vector<const BodyConvergence*> order;
    for (const auto& b : r.bodies) order.push_back(&b);
    std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return rank(a->verdict) < rank(b->verdict); });
    const std::size_t members = study.outcomes.ensemble.size() + 1;
    for (std::size_t i = 0; i < order.size() && i < show; ++i) {
        const BodyConvergence& b = *order[i];
        fmt::print("\n{}: {}{}\n", b.name, to_string(b.verdict),
                   b.verdict == Verdict::converged && !b.base_within_tolerance ? " at dt/4 (the base dt's answer is outside the tolerance)" : "");
        if (!b.dt.empty()) print_dt_table(b, label);
        if (!b.ensemble.empty()) print_ensemble(b, members, label);
        if (!b.stiffness.empty()) print_stiffness(b, label);
        for (const std::string& reason : b.reasons) fmt::print("  - {}\n", reason);
    }
    if (order.size() > show) fmt::print("\n... and {} more bodies (all in converge.csv)\n", order.size() - show);
    for (const std::string& f : r.failed_runs) fmt::print("run failed: {}\n", f);
    fmt::print("\nverdict: {} ({} bodies converged, {} not converged, {} chaotic; rtol {:g}%)\n", to_string(r.verdict),
               r.converged_count, r.not_converged_count, r.chaotic_count, 100.0 * tol.rtol);
    if (r.stiffness_sensitive) print_stiffness_line(r, label);
    if (r.verdict == Verdict::not_converged && study.outcomes.ensemble.empty())
        fmt::print("(--ensemble N tells a chaotic response from a too-long time step)\n");
}

void print_run_start(const PlannedRun& run, std::size_t index, std::size_t count) {
    fmt::print(stderr, "blockdem converge: run {}/{}: {} ({})\n", index + 1, count, run.label, run.description);
}

// Long runs: a line every 10 s of wall time, not every second as `blockdem run` does.
std::function<void(const RunProgress&)> sparse_progress() {
    auto last_s = std::make_shared<double>(0.0);
    return [last_s](const RunProgress& p) {
        if (p.wall_s < *last_s) *last_s = 0.0;  // a new run
        if (p.wall_s - *last_s < 10.0) return;
        *last_s = p.wall_s;
        fmt::print(stderr, "blockdem converge:   t = {:.3f} / {:.3f} s, {:.0f} s of wall time\n", p.time_s, p.end_time_s, p.wall_s);
    };
}

}  // namespace

void add_converge_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("converge", "Rerun a scenario at dt, dt/2, dt/4 and say whether its answer is converged");
    auto scenario = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>("converge");
    auto sets = std::make_shared<std::vector<std::string>>();
    auto options = std::make_shared<ConvergenceOptions>();
    auto tol = std::make_shared<ConvergenceTolerance>();
    auto quiet = std::make_shared<bool>(false);
    auto report = std::make_shared<bool>(false);
    auto show = std::make_shared<std::size_t>(10);
    cmd->add_option("scenario", *scenario, "scenario file (TOML)")->required();
    cmd->add_option("--out,-o", *out, "study folder: converge.json, converge.csv and one folder per run (dt/ is the base run)")
        ->capture_default_str()
        ->check(output_folder());
    cmd->add_option("--set", *sets, "override a scenario key in every run: --set simulation.duration=5 (repeatable)");
    cmd->add_flag("--stiffness", options->stiffness, "also run at 0.5 x and 2 x the contact stiffness (kn and ks, at dt/2)");
    cmd->add_option("--ensemble", options->ensemble, "also run N copies at dt with gravity perturbed by up to --perturbation")
        ->check(whole_number_in(0, max_ensemble, "each copy is a whole run"));
    cmd->add_option("--perturbation", options->perturbation, "largest relative perturbation of the ensemble")->capture_default_str();
    cmd->add_option("--rtol", tol->rtol, "relative change allowed from dt/2 to dt/4")->capture_default_str()->check(finite_positive());
    cmd->add_option("--floor-rotation", tol->floor_rotation_rad, "[rad] floor of the rotation in a relative change")
        ->capture_default_str()->check(finite_positive());
    cmd->add_option("--floor-slip", tol->floor_slip_m, "[m] floor of the slip in a relative change")
        ->capture_default_str()->check(finite_positive());
    cmd->add_option("--floor-time", tol->floor_time_s, "[s] floor of the overturning time in a relative change")
        ->capture_default_str()->check(finite_positive());
    cmd->add_option("--show", *show, "print at most this many bodies (the least converged first)")->capture_default_str();
    cmd->add_flag("--report", *report, "also write DIR/dt/report.html, with the verdict");
    cmd->add_flag("--quiet,-q", *quiet, "no progress lines");
    cmd->callback([=] {
        // The report draws 2-D runs only (blockdem report refuses a 3-D folder): refused before
        // any run rather than after all of them.
        if (*report && scenario_dimension(load_toml_file(*scenario), *scenario) == 3)
            throw InputError({*scenario, "--report", 0, 0},
                             "a 3-D study has no report yet (reports draw 2-D runs): its results are converge.json, "
                             "converge.csv and each run's folder (ParaView frames in dt/vtk)");
        ConvergenceRequest request;
        request.scenario = *scenario;
        request.overrides = *sets;
        request.out_dir = *out;
        request.options = *options;
        request.tolerance = *tol;
        if (!*quiet) {
            request.on_run_start = print_run_start;
            request.on_progress = sparse_progress();
        }
        const ConvergenceStudy study = run_convergence_study(request);
        print_study(study, *tol, *show);
        fmt::print("results in {}/ (converge.json, converge.csv; the runs in {}/dt, {}/dt_2, ...)\n", *out, *out, *out);
        if (*report) {
            write_report((std::filesystem::path(*out) / "dt").string());
            fmt::print("report: {}/dt/report.html\n", *out);
        }
        if (!study.result.failed_runs.empty())
            throw SimulationError(fmt::format("{} of the study's runs failed (see above and converge.json)", study.result.failed_runs.size()));
    });
}

}  // namespace blockdem::cli
