// `blockdem sweep SCENARIO --vary key=start:stop:step --vary key=v1,v2 [--cases FILE]
//  [--records DIR|LIST (--scale LIST | --target-pga LIST)] --out DIR [--threads N] [--histories]`
// Parameter studies (docs/sweeps.md): the cartesian product of the varied values, run on
// threads, or on MPI ranks under mpirun; resumable; a progress line on stderr.
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "apps/blockdem/stop_signal.hpp"
#include "sweep/mpi_cases.hpp"
#include "sweep/sweep.hpp"

namespace blockdem::cli {
namespace {

struct SweepArguments {
    std::string scenario;
    std::vector<std::string> vary;
    std::string cases;
    std::string records;
    std::string scale;
    std::string target_pga;
    std::string target_pga_unit;   // no default: sweep::check_target_pga_unit
    std::vector<std::string> record_keys;
    std::string out;
    int threads = 0;
    bool histories = false;
    std::string solver = "dem";
    double housner_dt_s = 1.0e-4;
    double housner_restitution = -1.0;
    bool keep_going = false;
    bool quiet = false;
};

std::string duration_text(double seconds) {
    if (seconds < 90.0) return fmt::format("{:.0f} s", seconds);
    if (seconds < 5400.0) return fmt::format("{:.0f} min", seconds / 60.0);
    return fmt::format("{:.1f} h", seconds / 3600.0);
}

// One line per second on a terminal (rewritten in place), one per 10 s into a file.
std::function<void(const sweep::SweepProgress&)> progress_printer() {
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    auto last = std::make_shared<double>(-1e9);
    return [tty, last](const sweep::SweepProgress& p) {
        if (!tty && !p.final && p.elapsed_s - *last < 10.0) return;
        *last = p.elapsed_s;
        const std::string left = p.final ? "" : p.rate_cases_s > 0 ? ", about " + duration_text(p.remaining_s) + " left" : "";
        fmt::print(stderr, "{}sweep: {}/{} cases done ({} failed), {:.3g} cases/s{}{}", tty ? "\r" : "", p.done, p.total,
                   p.failed, p.rate_cases_s, left, tty && !p.final ? "   " : "\n");
        std::fflush(stderr);
    };
}

sweep::SweepPlan make_plan(const SweepArguments& a) {
    sweep::SweepPlan plan;
    if (!a.cases.empty()) plan.axes.push_back(sweep::read_case_list(a.cases));
    for (const auto& v : a.vary) plan.axes.push_back(sweep::parse_vary(v));
    if (!a.records.empty()) {
        plan.suite.records = sweep::read_record_suite(a.records);
        if (!a.scale.empty() && !a.target_pga.empty()) throw CLI::ValidationError("give either --scale or --target-pga, not both");
        if (!a.target_pga.empty()) {
            plan.suite.scaling = sweep::RecordScaling::target_pga;
            plan.suite.levels = sweep::parse_value_list(a.target_pga);
        } else if (!a.scale.empty()) {
            plan.suite.levels = sweep::parse_value_list(a.scale);
        }
        sweep::check_target_pga_unit(a.target_pga, a.target_pga_unit);
        if (!a.target_pga_unit.empty()) plan.suite.pga_unit = a.target_pga_unit;
        for (const auto& k : a.record_keys) {
            const auto eq = k.find('=');
            if (eq == std::string::npos) throw CLI::ValidationError("--record-key expects key=value, got " + k);
            plan.suite.common_keys.push_back({k.substr(0, eq), k.substr(eq + 1)});
        }
    } else if (!a.scale.empty() || !a.target_pga.empty() || !a.record_keys.empty()) {
        throw CLI::ValidationError("--scale, --target-pga and --record-key need --records");
    }
    plan.check_keys_distinct();
    return plan;
}

sweep::SweepRequest make_request(const SweepArguments& a, const std::string& command_line) {
    sweep::SweepRequest r;
    r.scenario = a.scenario;
    r.plan = make_plan(a);
    r.options.solver = a.solver == "housner" ? sweep::Solver::housner : sweep::Solver::dem;
    r.options.stop_when_overturned = !a.keep_going;
    r.options.housner_dt_s = a.housner_dt_s;
    r.options.housner_restitution = a.housner_restitution;
    r.histories = a.histories;
    r.out_dir = a.out;
    r.threads = a.threads;
    r.command_line = command_line;
    return r;
}

// The command as given, for sweep.json (CLI11 keeps no copy of argv).
std::string describe_command(const SweepArguments& a) {
    std::string c = "blockdem sweep " + a.scenario;
    for (const auto& v : a.vary) c += " --vary " + v;
    if (!a.cases.empty()) c += " --cases " + a.cases;
    if (!a.records.empty()) c += " --records " + a.records;
    if (!a.scale.empty()) c += " --scale " + a.scale;
    if (!a.target_pga.empty()) c += " --target-pga " + a.target_pga + " --target-pga-unit " + a.target_pga_unit;
    for (const auto& k : a.record_keys) c += " --record-key " + k;
    if (a.solver != "dem") c += " --solver " + a.solver;
    if (a.keep_going) c += " --keep-going";
    return c + " --out " + a.out;
}

void print_outcome(const sweep::SweepOutcome& o, const std::string& out) {
    fmt::print("sweep: {} cases, {} done ({} failed or bad input), {} run now in {:.1f} s ({:.3g} cases/s) on {} rank{} x {} thread{}\n",
               o.total, o.done, o.failed, o.ran_now, o.wall_s, o.wall_s > 0 ? o.ran_now / o.wall_s : 0.0, o.ranks,
               o.ranks == 1 ? "" : "s", o.threads_per_rank, o.threads_per_rank == 1 ? "" : "s");
    if (o.complete())
        fmt::print("results: {}/results.csv\n", out);
    else
        fmt::print("interrupted with {} cases to do: rerun the same command to finish (results so far: {}/results.csv)\n",
                   o.total - o.done, out);
}

}  // namespace

void add_sweep_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("sweep", "Run a parameter study: many cases of one scenario, in parallel, resumable");
    auto a = std::make_shared<SweepArguments>();
    cmd->add_option("scenario", a->scenario, "scenario file (TOML)")->required();
    cmd->add_option("--vary", a->vary, "a varied key: key=start:stop:step or key=v1,v2,... (repeatable; the first varies slowest)");
    cmd->add_option("--cases", a->cases, "case list CSV: a header of keys, then one row of values per point (varied together)");
    cmd->add_option("--records", a->records, "record suite: a folder of record files, or a list file (path [key=value ...] per line)");
    cmd->add_option("--scale", a->scale, "scale factors for every record: f1,f2,... or start:stop:step");
    cmd->add_option("--target-pga", a->target_pga, "target PGA levels for every record: v1,v2,... or start:stop:step");
    cmd->add_option("--target-pga-unit", a->target_pga_unit, "unit of --target-pga, required with it: m/s^2, gal or g")->check(CLI::IsMember({"m/s^2", "gal", "g"}));
    cmd->add_option("--record-key", a->record_keys, "a record key for every record, e.g. duration=20 (repeatable)");
    cmd->add_option("--out,-o", a->out, "output folder (a rerun with the same folder resumes)")->required()->check(output_folder());
    cmd->add_option("--threads,-j", a->threads, "threads per process (default: all cores; 1 per rank under mpirun)")
        ->check(whole_number_in(1, max_threads));
    cmd->add_flag("--histories", a->histories, "also write cases/<id>/history.csv for every case");
    cmd->add_option("--solver", a->solver, "dem, or housner: the independent equation-of-motion solver for one rectangular block")
        ->check(CLI::IsMember({"dem", "housner"}))->capture_default_str();
    cmd->add_option("--housner-dt", a->housner_dt_s, "[s] RK4 step of --solver housner")->capture_default_str();
    cmd->add_option("--housner-restitution", a->housner_restitution, "r per impact for --solver housner (default: 1 - 1.5 sin^2 alpha)");
    cmd->add_flag("--keep-going", a->keep_going, "run overturned cases to the end (default: stop once every block is down)");
    cmd->add_flag("--quiet,-q", a->quiet, "no progress lines");
    cmd->callback([a] {
        sweep::SweepRequest request = make_request(*a, describe_command(*a));
        if (!a->quiet) request.on_progress = progress_printer();
        // mpirun ends a job on Ctrl-C itself; a plain run stops cleanly and keeps what is done.
        if (!sweep::started_by_mpi_launcher()) request.cancel = &install_stop_handlers();
        const sweep::SweepOutcome outcome = sweep::run_sweep(request);
        if (!outcome.reporting_rank) return;
        print_outcome(outcome, a->out);
        if (!outcome.complete() && stop_exit_status() != 0) throw ExitStatus{stop_exit_status()};
    });
}

}  // namespace blockdem::cli
