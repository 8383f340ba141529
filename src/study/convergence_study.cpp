#include "study/convergence_study.hpp"

#include <fstream>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/overrides.hpp"
#include "run/run_scenario.hpp"
#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "study/convergence_csv.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

// One run through the ordinary run path. A failure after the start leaves its summary.json
// (status "failed"), which is read back; bad input propagates.
RunOutcome run_one(const ConvergenceRequest& request, const PlannedRun& plan, nlohmann::json& summary_out) {
    RunRequest run;
    run.scenario = request.scenario;
    run.overrides = request.overrides;
    run.overrides.insert(run.overrides.end(), plan.overrides.begin(), plan.overrides.end());
    run.out_dir = request.out_dir / plan.label;
    run.on_progress = request.on_progress;
    try {
        summary_out = run_scenario(run);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::ifstream in(run.out_dir / "summary.json");
        summary_out = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        if (!summary_out.is_object() || !summary_out.contains("dt_s")) {
            RunOutcome failed;
            failed.label = plan.label;
            failed.status = "failed";
            failed.error = e.what();
            return failed;
        }
        summary_out["status"] = "failed";
        summary_out["error"] = e.what();
    }
    return outcome_of_summary(summary_out, plan.label);
}

// A number of the summary, or 0 where it has none (a 3-D run with no stable bound writes null).
double number_or_zero(const nlohmann::json& summary, const char* key) {
    return summary.is_object() && summary.contains(key) && summary[key].is_number() ? summary[key].get<double>() : 0.0;
}

nlohmann::json run_entry(const PlannedRun& plan, const RunOutcome& outcome, const nlohmann::json& summary) {
    nlohmann::json j{{"label", plan.label},
                     {"folder", plan.label},
                     {"role", to_string(plan.role)},
                     {"description", plan.description},
                     {"overrides", plan.overrides},
                     {"status", outcome.status},
                     {"dt_s", outcome.dt_s}};
    if (!outcome.error.empty()) j["error"] = outcome.error;
    if (summary.is_object()) {
        j["critical_dt_s"] = number_or_zero(summary, "critical_dt_s");
        j["wall_time_s"] = number_or_zero(summary, "wall_time_s");
    }
    return j;
}

void add(StudyRuns& runs, RunRole role, RunOutcome outcome) {
    switch (role) {
        case RunRole::refinement: runs.refinement.push_back(std::move(outcome)); break;
        case RunRole::stiffness: runs.stiffness.push_back(std::move(outcome)); break;
        case RunRole::ensemble: runs.ensemble.push_back(std::move(outcome)); break;
    }
}

// The 1 x member of the stiffness study is the dt/2 run: 0.5 x, 1 x, 2 x in order.
std::vector<RunOutcome> stiffness_in_order(const StudyRuns& runs) {
    if (runs.stiffness.size() != 2 || runs.refinement.size() < 2) return runs.stiffness;
    return {runs.stiffness[0], runs.refinement[1], runs.stiffness[1]};
}

void write_json(const fs::path& file, const nlohmann::json& j) {
    std::ofstream out(file);
    if (!out) throw InputError({file.string(), "", 0, 0}, "cannot write the file");
    out << j.dump(2) << '\n';
}

}  // namespace

ConvergenceStudy run_convergence_study(const ConvergenceRequest& request) {
    ConvergenceStudy study;
    std::error_code ec;
    fs::create_directories(request.out_dir, ec);
    if (ec) throw InputError({request.out_dir.string(), "", 0, 0}, "cannot create the output folder: " + ec.message());
    // Every key and option is checked before the first run: the scenario as the runs will read
    // it, then the plan with a stand-in time step.
    toml::table root = load_toml_file(request.scenario);
    const int dimension = scenario_dimension(root, request.scenario.string());
    // A 3-D scenario is checked by building it as the run will (its reader applies the --set).
    if (dimension == 3) load_scenario_3d(root, request.scenario, request.overrides);
    apply_overrides(root, request.overrides);
    if (dimension == 2) read_model(root, request.scenario.string(), request.scenario.parent_path());
    const std::size_t run_count = 1 + plan_follow_up_runs(root, 1.0, request.options).size();

    const PlannedRun base{base_run_label, RunRole::refinement, {}, "dt as the scenario sets it"};
    if (request.on_run_start) request.on_run_start(base, 0, run_count);
    nlohmann::json summary;
    RunOutcome base_outcome = run_one(request, base, summary);
    nlohmann::json entries = nlohmann::json::array({run_entry(base, base_outcome, summary)});
    const double base_dt_s = base_outcome.dt_s;
    const double critical_dt_s = number_or_zero(summary, "critical_dt_s");
    study.runs = {base};
    add(study.outcomes, base.role, std::move(base_outcome));
    if (!(base_dt_s > 0.0)) throw std::runtime_error("the base run stopped before it had a time step: " + study.outcomes.refinement[0].error);

    const std::vector<PlannedRun> plan = plan_follow_up_runs(root, base_dt_s, request.options);
    for (std::size_t i = 0; i < plan.size(); ++i) {
        if (request.on_run_start) request.on_run_start(plan[i], i + 1, run_count);
        RunOutcome outcome = run_one(request, plan[i], summary);
        entries.push_back(run_entry(plan[i], outcome, summary));
        study.runs.push_back(plan[i]);
        add(study.outcomes, plan[i].role, std::move(outcome));
    }

    StudyRuns judged = study.outcomes;
    judged.stiffness = stiffness_in_order(study.outcomes);
    study.result = judge_convergence(judged, request.tolerance);

    nlohmann::json& j = study.report;
    j["scenario"] = request.scenario.string();
    j["dimension"] = dimension;
    if (dimension == 3) j["quantities_3d"] = quantities_3d_json();
    j["overrides"] = request.overrides;
    j["base_run"] = base_run_label;
    j["base_dt_s"] = base_dt_s;
    j["critical_dt_s"] = critical_dt_s;
    j["refinement"] = {"dt", "dt_2", "dt_4"};
    if (request.options.stiffness) j["stiffness_study"] = {{"factors", stiffness_factors}, {"runs", {"kn_x0.5", "dt_2", "kn_x2"}},
                                                           {"scaled_keys", "contact.kn, contact.ks (and those of [[contact.pairs]])"}};
    if (request.options.ensemble > 0)
        j["ensemble_study"] = {{"size", request.options.ensemble},
                               {"perturbed_key", "simulation.gravity"},
                               {"relative_perturbations", ensemble_perturbations(request.options.ensemble, request.options.perturbation)},
                               {"members", "the base run and ensemble_1 .. ensemble_N, all at the base dt"}};
    j["runs"] = entries;
    j.update(to_json(study.result, request.tolerance));
    write_json(request.out_dir / "converge.json", j);
    write_convergence_csv(request.out_dir / "converge.csv", study.result);
    return study;
}

}  // namespace blockdem
