// `blockdem run SCENARIO --out DIR [--set key=value]... [--force] [--threads N]
//      [--save-state T1,T2,...] [--save-state-every DT]`
// `blockdem run --restart STATE.h5 [SCENARIO] [--out DIR] ...`
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "apps/blockdem/stop_signal.hpp"
#include "io/output_folder.hpp"
#include "run/run_scenario.hpp"
#include "world/settling.hpp"

namespace blockdem::cli {
namespace {

void print_progress(const RunProgress& p) {
    const double fraction = p.end_time_s > 0 ? p.time_s / p.end_time_s : 1.0;
    const double rate = p.wall_s > 0 ? static_cast<double>(p.steps) / p.wall_s : 0.0;
    const double left = fraction > 0 ? p.wall_s * (1.0 - fraction) / fraction : 0.0;
    fmt::print(stderr, "blockdem: t = {:.3f} / {:.3f} s ({:.0f}%), {} steps, {:.3g} steps/s, about {:.0f} s left\n",
               p.time_s, p.end_time_s, 100.0 * fraction, p.steps, rate, left);
}

// The outcome word (docs/outputs.md, "Outcomes"), upper case for a failure, with its event.
std::string outcome_words(const nlohmann::json& body) {
    const std::string outcome = body["outcome"].get<std::string>();
    const double t = body["outcome_time_s"].is_number() ? body["outcome_time_s"].get<double>() : -1.0;
    const auto point = [](const nlohmann::json& position_m) {  // (x, y) in 2-D, (x, y, z) in 3-D
        std::vector<std::string> at;
        for (const auto& x : position_m) at.push_back(fmt::format("{:.3f}", x.get<double>()));
        return fmt::format("({}) m", fmt::join(at, ", "));
    };
    if (outcome == "fell") {
        const auto& fell = body["fell"];
        return fmt::format("FELL from its supporters at t = {:.3f} s, {} {}", t,
                           fell["came_to_rest"].get<bool>() ? "came to rest at" : "still moving at the end, at",
                           point(fell["position_m"]));
    }
    if (outcome == "left_model")
        return fmt::format("LEFT THE MODEL at t = {:.3f} s at {} (taken out of the run)", t,
                           point(body["left_model"]["position_m"]));
    if (outcome == "overturned") return fmt::format("OVERTURNED at t = {:.3f} s", t);
    if (outcome == "stable") return "stable";
    return fmt::format("{} (from t = {:.3f} s)", outcome == "rocked_and_slid" ? "rocked and slid" : outcome, t);
}

// Each assembly's collapse, then all blocks' (both dimensions; docs/outputs.md).
void print_collapse(const nlohmann::json& summary) {
    const auto& collapse = summary["collapse"];
    for (const auto& c : collapse) {
        // ("all" repeats a lone assembly that holds every block.)
        const bool repeats = c["group"] == "all" && collapse.size() == 2 && collapse[0]["blocks"] == c["blocks"];
        if (c["blocks"].get<std::size_t>() < 2 || repeats) continue;
        fmt::print("{}: {} of {} blocks fell, {} overturned, {} left the model; {:.0f}% of the mass displaced{}\n",
                   c["group"] == "all" ? std::string("all blocks") : "assembly " + c["group"].get<std::string>(),
                   c["fell"].get<std::size_t>(), c["blocks"].get<std::size_t>(), c["overturned"].get<std::size_t>(),
                   c["left_model"].get<std::size_t>(), 100.0 * c["displaced_mass_fraction"].get<double>(),
                   c["first_to_go"].is_string() ? fmt::format("; first to go: {} at t = {:.3f} s",
                                                              c["first_to_go"].get<std::string>(),
                                                              c["first_to_go_time_s"].get<double>())
                                                : std::string());
    }
}

// A 3-D run's lines (docs/3d.md, "Outputs"): one a body, or for more than 12 bodies the count
// that overturned and the largest tilt and slip (summary.json has every body).
void print_outcome_3d(const nlohmann::json& summary, const std::string& out_dir) {
    for (const auto& note : summary.value("assemblies", nlohmann::json::array())) fmt::print("{}\n", note.get<std::string>());
    std::vector<nlohmann::json> bodies;
    for (const auto& body : summary["bodies"])
        if (body["kind"] == "dynamic") bodies.push_back(body);
    const auto slip = [](const nlohmann::json& b) { return std::hypot(b["slip_m"][0].get<double>(), b["slip_m"][1].get<double>()); };
    if (bodies.size() <= 12) {
        for (const auto& body : bodies)
            fmt::print("{}: {}; peak tilt {:.4g} rad at t = {:.3f} s, slip ({:.4g}, {:.4g}) m\n", body["name"].get<std::string>(),
                       outcome_words(body), body["peak_tilt_rad"].get<double>(),
                       body["peak_tilt_time_s"].get<double>(), body["slip_m"][0].get<double>(),
                       body["slip_m"][1].get<double>());
    } else {
        std::size_t tilted = 0, slid = 0;
        std::map<std::string, std::size_t> words;
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            ++words[bodies[i]["outcome"].get<std::string>()];
            if (bodies[i]["peak_tilt_rad"].get<double>() > bodies[tilted]["peak_tilt_rad"].get<double>()) tilted = i;
            if (slip(bodies[i]) > slip(bodies[slid])) slid = i;
        }
        std::vector<std::string> counts;
        for (const auto& [word, count] : words) counts.push_back(fmt::format("{} {}", count, word));
        fmt::print("{} bodies: {}; largest peak tilt {:.4g} rad ({}), largest slip {:.4g} m ({})\n",
                   bodies.size(), fmt::join(counts, ", "), bodies[tilted]["peak_tilt_rad"].get<double>(),
                   bodies[tilted]["name"].get<std::string>(), slip(bodies[slid]), bodies[slid]["name"].get<std::string>());
    }
    print_collapse(summary);
    fmt::print("energy balance error {:.3g} of the largest term; results in {}/ (history.csv, energy.csv, summary.json, "
               "vtk/bodies.pvd)\n",
               summary["energy_j"]["balance_error_relative"].get<double>(), out_dir);
    if (summary.contains("warnings"))
        for (const auto& warning : summary["warnings"]) fmt::print(stderr, "WARNING: {}\n", warning.get<std::string>());
}

void print_outcome(const nlohmann::json& summary, const std::string& out_dir) {
    if (summary.value("dimension", 2) == 3) return print_outcome_3d(summary, out_dir);
    for (const auto& body : summary["bodies"]) {
        if (body["kind"] != "dynamic") continue;
        fmt::print("{}: {}; peak rotation {:.4g} rad, peak base slip {:.4g} m, peak displacement relative to {} {:.4g} m\n",
                   body["name"].get<std::string>(), outcome_words(body), body["peak_abs_rotation_rad"].get<double>(),
                   body["peak_abs_base_slip_m"].get<double>(), summary["displacements_relative_to"].get<std::string>(),
                   body["peak_abs_relative_displacement_m"].get<double>());
    }
    print_collapse(summary);
    fmt::print("energy balance error {:.3g} of the largest term; results in {}/ (history.csv, summary.json)\n",
               summary["energy_j"]["balance_error_relative"].get<double>(), out_dir);
    if (summary.contains("warnings"))
        for (const auto& warning : summary["warnings"]) fmt::print(stderr, "WARNING: {}\n", warning.get<std::string>());
}

}  // namespace

void add_run_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("run", "Run a scenario and write history.csv and summary.json");
    auto scenario = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>("out");
    auto sets = std::make_shared<std::vector<std::string>>();
    auto quiet = std::make_shared<bool>(false);
    auto force = std::make_shared<bool>(false);
    auto threads = std::make_shared<int>(0);
    auto save_times = std::make_shared<std::vector<double>>();
    auto save_every = std::make_shared<double>(0.0);
    auto restart = std::make_shared<std::string>();
    cmd->add_option("scenario", *scenario, "scenario file (TOML); with --restart, default: the run folder's scenario.toml");
    auto* out_option = cmd->add_option("--out,-o", *out, "output folder (with --restart, default: the state's run folder, "
                                                         "continued in place)")
                           ->capture_default_str()
                           ->check(output_folder());
    cmd->add_option("--set", *sets, "override a scenario key: --set contact.h_s=0.5 (repeatable)");
    cmd->add_flag("--quiet,-q", *quiet, "no progress lines");
    cmd->add_flag("--force", *force, "replace the run already in --out (removes only blockdem's own files there)");
    cmd->add_option("--threads,-j", *threads, "threads of the time step (default: OMP_NUM_THREADS, else all cores); "
                                              "results do not depend on it")
        ->check(whole_number_in(1, max_threads));
    cmd->add_option("--save-state", *save_times, "write the whole state at these times [s] to DIR/state/t_<time>s.h5 "
                                                 "(comma-separated), to restart from or start other runs from")
        ->delimiter(',')
        ->check(finite_non_negative());
    cmd->add_option("--save-state-every", *save_every, "write the whole state every DT seconds of simulated time")
        ->check(finite_positive());
    cmd->add_option("--restart", *restart, "continue the run a state file was saved in, from the state's time: the "
                                           "files end as those of a run that never stopped");
    cmd->callback([=] {
        if (*threads != 0) set_step_threads(*threads);
        if (scenario->empty() && restart->empty()) throw CLI::RequiredError("scenario");
        RunRequest request;
        request.scenario = *scenario;
        request.overrides = *sets;
        request.out_dir = restart->empty() || out_option->count() > 0 ? *out : std::string();
        request.force = *force;
        request.save_state_times_s = *save_times;
        request.save_state_every_s = *save_every;
        request.restart = *restart;
        if (!*quiet) request.on_progress = print_progress;
        request.on_warning = [](const std::string& text) { fmt::print(stderr, "warning: {}\n", text); };
        request.on_state_saved = [quiet](const std::filesystem::path& file) {
            if (!*quiet) fmt::print(stderr, "blockdem: state saved to {}\n", file.string());
        };
        request.stop_requested = &install_stop_handlers();
        nlohmann::json summary;
        try {
            summary = run_scenario(request);
        } catch (const SettlingStopped& e) {  // nothing was written: say so, with the stop's exit status
            fmt::print(stderr, "interrupted: {}\n", e.what());
            throw ExitStatus{stop_exit_status()};
        }
        const std::string folder = summary["run_folder"].get<std::string>();
        if (summary["status"] == "interrupted") {
            fmt::print(stderr, "interrupted at t = {:.4g} s of {:.4g} s: the results so far are in {}/ (summary.json "
                               "status \"interrupted\")\n",
                       summary["time_s"].get<double>(), summary["end_time_s"].get<double>(), folder);
            if (!summary["state_files"].empty())
                fmt::print(stderr, "to go on: blockdem run --restart {}\n", summary["state_files"].back().get<std::string>());
            throw ExitStatus{stop_exit_status()};
        }
        print_outcome(summary, folder);
        // [output] report = true: the report is made here, in the tool, because the library never
        // starts processes.
        if (summary.contains("outputs") && summary["outputs"].value("report", false)) {
            // Held while the report writes there: a second run into the folder would mix with it.
            const RunFolderLock hold = RunFolderLock::take(folder);
            write_report(folder);
            fmt::print("report: {}/report.html\n", folder);
        }
    });
}

}  // namespace blockdem::cli
