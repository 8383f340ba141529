#include "sweep/sweep.hpp"

#include <exception>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/output_folder.hpp"
#include "sweep/mpi_cases.hpp"
#include "sweep/results_table.hpp"

namespace blockdem::sweep {
namespace {

// FNV-1a, 64 bit: stable across runs and machines (std::hash is not).
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char ch : text) {
        h ^= ch;
        h *= 1099511628211ull;
    }
    return h;
}

std::string column_unit(const std::string& column) {
    for (const auto& [suffix, unit] : std::vector<std::pair<std::string, std::string>>{
             {"_m_s2", "m/s^2"}, {"_rad", "rad"}, {"_deg", "deg"}, {"_s", "s"}, {"_m", "m"}, {"_ratio", "-"}})
        if (column.ends_with(suffix)) return unit;
    return "";
}

nlohmann::json columns_json(const std::vector<std::string>& columns) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& c : columns) out.push_back({{"name", c}, {"unit", column_unit(c)}});
    return out;
}

struct Setup {
    SweepScenario scenario;
    CaseOptions options;
    std::int64_t total = 0;
    std::string header;
    std::size_t status_column = 0;
    std::string fingerprint;
};

Setup common_setup(const SweepRequest& request) {
    Setup s;
    s.scenario = load_sweep_scenario(request.scenario);
    s.total = request.plan.case_count();
    check_axes_readable(s.scenario, request.plan);
    s.options = request.options;
    if (request.histories) s.options.histories_dir = request.out_dir / "cases";
    const std::vector<std::string> columns = result_columns(request.plan, s.scenario.body_names);
    s.header = fmt::format("{}", fmt::join(columns, ","));
    s.status_column = 1 + request.plan.value_columns().size();
    s.fingerprint = plan_fingerprint(s.scenario, request.plan, s.options);
    return s;
}

// The out folder must be new or hold this very sweep (same fingerprint), and no other sweep may
// be writing there (two would mix their results): the sweep holds the folder while it runs.
RunFolderLock check_out_folder(const SweepRequest& request, const Setup& s) {
    std::error_code ec;
    std::filesystem::create_directories(request.out_dir, ec);
    if (ec) throw OutputError(fmt::format("{}: cannot create the folder: {}", request.out_dir.string(), ec.message()));
    RunFolderLock lock = RunFolderLock::take(request.out_dir);
    // A sweep killed while it replaced a file leaves the temporary behind; the log is the state.
    for (const char* name : {"sweep.json.tmp", "results.csv.tmp"}) std::filesystem::remove(request.out_dir / name, ec);
    const auto manifest = request.out_dir / "sweep.json";
    if (!std::filesystem::exists(manifest)) {
        if (holds_run(request.out_dir))
            throw InputError({request.out_dir.string(), "", 0, 0},
                             "the folder holds a run of `blockdem run` (summary.json); give the sweep another --out");
        return lock;
    }
    std::ifstream in(manifest);
    const nlohmann::json old = nlohmann::json::parse(in, nullptr, false);
    if (old.is_discarded() || old.value("fingerprint", "") != s.fingerprint)
        throw InputError({request.out_dir.string(), "", 0, 0},
                         "the folder holds a different sweep (other scenario, values, records or solver); use "
                         "another --out, or delete it");
    return lock;
}

void write_manifest(const SweepRequest& request, const Setup& s, const SweepProgress& p, const std::string& status) {
    nlohmann::json j;
    j["scenario"] = request.scenario.string();
    j["command"] = request.command_line;
    j["fingerprint"] = s.fingerprint;
    j["solver"] = s.options.solver == Solver::housner ? "housner" : "dem";
    j["cases"] = s.total;
    j["done"] = p.done;
    j["failed"] = p.failed;
    j["status"] = status;
    j["bodies"] = s.scenario.body_names;
    j["value_columns"] = request.plan.value_columns();
    std::istringstream header(s.header);
    std::vector<std::string> columns;
    for (std::string c; std::getline(header, c, ',');) columns.push_back(c);
    j["columns"] = columns_json(columns);
    write_file_atomically(request.out_dir / "sweep.json", j.dump(2) + "\n");
}

std::vector<std::int64_t> missing_cases(std::int64_t total, const FinishedCasesLog& log) {
    std::vector<std::int64_t> pending;
    for (std::int64_t id = 0; id < total; ++id)
        if (!log.rows().count(id)) pending.push_back(id);
    return pending;
}

std::string run_row(const SweepRequest& request, const Setup& s, std::int64_t id) {
    const SweepCase c = make_case(request.plan, id);
    return format_row(c, run_case(s.scenario, request.plan, c, s.options, request.cancel));
}

int default_threads(int ranks) {
    if (ranks > 1) return 1;  // one rank per core is the usual mpirun layout
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Rank 0: local threads run cases while the main thread serves the other ranks.
void run_on_rank0(const SweepRequest& request, const Setup& s, CaseQueue& queue, ResultCollector& collector,
                  int threads, std::optional<MpiSession>& session, std::int64_t remote_workers) {
    auto work = [&](std::int64_t id) { collector.record(id, run_row(request, s, id)); };
    if (!session || session->size() == 1) {
        run_on_threads(threads, queue, work);
        return;
    }
    std::exception_ptr local_error;
    std::thread local([&] {
        try {
            run_on_threads(threads, queue, work);
        } catch (...) {
            local_error = std::current_exception();
        }
    });
    serve_remote_workers(queue, collector, remote_workers);
    local.join();
    if (local_error) std::rethrow_exception(local_error);
}

}  // namespace

std::string plan_fingerprint(const SweepScenario& scenario, const SweepPlan& plan, const CaseOptions& options) {
    std::ostringstream text;
    text << scenario.root << "\n--\n";
    for (const auto& axis : plan.axes) {
        text << fmt::format("axis {}\n", fmt::join(axis.keys, "|"));
        for (const auto& p : axis.points) text << fmt::format("  {}\n", fmt::join(p, "|"));
    }
    for (const auto& r : plan.suite.records) {
        text << "record " << r.file.string();
        for (const auto& k : r.keys) text << ' ' << k.key << '=' << k.value;
        text << '\n';
    }
    for (const auto& k : plan.suite.common_keys) text << "record_key " << k.key << '=' << k.value << '\n';
    text << fmt::format("levels {} {} {}\n", static_cast<int>(plan.suite.scaling), plan.suite.pga_unit,
                        fmt::join(plan.suite.levels, "|"));
    text << fmt::format("solver {} stop {} housner {} {}\n", static_cast<int>(options.solver),
                        options.stop_when_overturned, options.housner_dt_s, options.housner_restitution);
    return fmt::format("{:016x}", fnv1a(text.str()));
}

SweepOutcome run_sweep(const SweepRequest& request) {
    std::optional<MpiSession> session;
    if (started_by_mpi_launcher()) {
        if (!mpi_built())
            throw std::runtime_error("started by mpirun, but this blockdem was built without MPI (install libopenmpi-dev and rebuild)");
        session.emplace();
    }
    const int rank = session ? session->rank() : 0;
    const int ranks = session ? session->size() : 1;

    // Every rank reads the scenario and the plan; rank 0 also opens the out folder. All agree
    // before any case starts, so that a bad plan stops every rank instead of leaving them waiting.
    std::optional<Setup> setup;
    std::unique_ptr<FinishedCasesLog> log;
    std::exception_ptr setup_error;
    RunFolderLock folder_lock;
    try {
        setup = common_setup(request);
        if (rank == 0) {
            folder_lock = check_out_folder(request, *setup);
            log = std::make_unique<FinishedCasesLog>(request.out_dir / "finished_cases.csv", setup->header);
        }
    } catch (...) {
        setup_error = std::current_exception();
    }
    const bool everyone_ready = session ? session->all_true(!setup_error) : !setup_error;
    if (setup_error) std::rethrow_exception(setup_error);
    if (!everyone_ready) throw std::runtime_error("another MPI rank could not set up the sweep (see its message)");

    int threads = request.threads > 0 ? request.threads : default_threads(ranks);
    if (rank > 0 && session && !session->threads_may_call()) threads = 1;
    const std::int64_t remote_workers = session ? session->sum(rank == 0 ? 0 : threads) : 0;

    SweepOutcome outcome;
    outcome.ranks = ranks;
    outcome.threads_per_rank = threads;
    if (rank > 0) {
        outcome.reporting_rank = false;
        work_for_rank0(threads, [&](std::int64_t id) {
            try {
                return run_row(request, *setup, id);
            } catch (const CaseCancelled&) {
                return std::string();
            }
        });
        return outcome;
    }

    const Setup& s = *setup;
    CaseQueue queue(missing_cases(s.total, *log), request.cancel);
    ResultCollector collector(*log, s.total, s.status_column, request.on_progress);
    write_manifest(request, s, collector.progress(), "running");
    run_on_rank0(request, s, queue, collector, threads, session, remote_workers);
    collector.finish();
    const SweepProgress p = collector.progress();
    write_sorted_results(request.out_dir / "results.csv", s.header, log->rows());
    // Only a stop request leaves cases undone (a failing case is recorded as failed).
    write_manifest(request, s, p, p.done == p.total ? "complete" : "interrupted");
    outcome.total = p.total;
    outcome.done = p.done;
    outcome.failed = p.failed;
    outcome.ran_now = p.done_this_run;
    outcome.wall_s = p.elapsed_s;
    return outcome;
}

}  // namespace blockdem::sweep
