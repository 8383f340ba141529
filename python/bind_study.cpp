// blockdem._core.sweep_table: a parameter study run in memory, the same plan, cases and rows as
// `blockdem sweep` (src/sweep, docs/sweeps.md). The Python function blockdem.sweep (study.py)
// turns its arguments into the plan below and the rows into numpy columns.
//
// Why rows of text: a case's row is format_row's, the line results.csv holds, so that a study
// run from Python and one run by the CLI give the same table, column for column. What the
// module leaves out is the out folder: no durable log, no resume (use the CLI for long sweeps).
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "python/bindings.hpp"
#include "python/scenario_source.hpp"
#include "run/run_request.hpp"
#include "sweep/case_queue.hpp"
#include "sweep/case_runner.hpp"
#include "sweep/results_table.hpp"
#include "sweep/sweep_plan.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace blockdem::python {
namespace {

using KeyValues = std::vector<std::pair<std::string, std::string>>;

sweep::Solver parse_solver(const std::string& name) {
    if (name == "dem") return sweep::Solver::dem;
    if (name == "housner") return sweep::Solver::housner;
    throw std::invalid_argument("solver: \"" + name + "\" is not one of dem, housner");
}

std::vector<sweep::Assignment> assignments(const KeyValues& pairs) {
    std::vector<sweep::Assignment> out;
    for (const auto& [key, value] : pairs) out.push_back({key, value});
    return out;
}

/// The record axis: a folder or list file (read_record_suite), or the files given one by one.
std::vector<sweep::RecordEntry> record_entries(const std::optional<fs::path>& suite, const std::vector<fs::path>& files) {
    if (suite) return sweep::read_record_suite(*suite);
    std::vector<sweep::RecordEntry> entries;
    for (const auto& f : files) entries.push_back({fs::absolute(f), f.filename().string(), {}});
    return entries;
}

struct SweepTable {
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;   ///< one per case, sorted by case id
    std::vector<std::string> bodies;
};

/// Every case of the plan on `threads` threads (dynamic scheduling, as `blockdem sweep`).
SweepTable run_plan(const sweep::SweepScenario& scenario, const sweep::SweepPlan& plan, const sweep::CaseOptions& options,
                    int threads) {
    const std::int64_t total = plan.case_count();
    std::vector<std::string> rows(static_cast<std::size_t>(total));
    std::vector<std::int64_t> ids(static_cast<std::size_t>(total));
    for (std::int64_t id = 0; id < total; ++id) ids[static_cast<std::size_t>(id)] = id;
    sweep::CaseQueue queue(std::move(ids), nullptr);
    const int workers = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    sweep::run_on_threads(workers, queue, [&](std::int64_t id) {
        const sweep::SweepCase c = sweep::make_case(plan, id);
        rows[static_cast<std::size_t>(id)] = sweep::format_row(c, sweep::run_case(scenario, plan, c, options, nullptr));
    });
    SweepTable table{sweep::result_columns(plan, scenario.body_names), {}, scenario.body_names};
    for (const auto& row : rows) table.rows.push_back(sweep::split_csv_line(row));
    return table;
}

}  // namespace

void bind_study(py::module_& m) {
    m.def("parse_value_list", &sweep::parse_value_list, py::arg("text"),
          "\"start:stop:step\" (inclusive) or \"v1,v2,...\" as `blockdem sweep --vary` reads them.");
    m.def(
        "sweep_table",
        [](const ScenarioSource& scenario, const std::vector<std::pair<std::vector<std::string>, std::vector<std::vector<std::string>>>>& axes,
           const std::optional<fs::path>& records, const std::vector<fs::path>& record_files,
           const std::optional<std::string>& scale, const std::optional<std::string>& target_pga,
           const std::optional<std::string>& target_pga_unit, const KeyValues& record_keys, const std::string& solver,
           bool stop_when_overturned, double housner_dt_s, double housner_restitution, int threads) {
            sweep::SweepPlan plan;
            for (const auto& [keys, points] : axes) plan.axes.push_back({keys, points});
            plan.suite.records = record_entries(records, record_files);
            if (scale && target_pga) throw std::invalid_argument("scale and target_pga: give one of them, not both");
            if (!plan.suite.records.empty() || scale || target_pga) {
                if (plan.suite.records.empty()) throw std::invalid_argument("scale / target_pga need records");
                if (target_pga) {
                    sweep::check_target_pga_unit(*target_pga, target_pga_unit.value_or(""));
                    plan.suite.scaling = sweep::RecordScaling::target_pga;
                    plan.suite.levels = sweep::parse_value_list(*target_pga);
                    plan.suite.pga_unit = *target_pga_unit;
                } else if (scale) {
                    plan.suite.levels = sweep::parse_value_list(*scale);
                }
                plan.suite.common_keys = assignments(record_keys);
            }
            if (threads < 0 || threads > max_threads)
                throw py::value_error(fmt::format("threads must be 0 (all cores) or 1 to {}, got {}", max_threads, threads));
            sweep::CaseOptions options;
            options.solver = parse_solver(solver);
            options.stop_when_overturned = stop_when_overturned;
            options.housner_dt_s = housner_dt_s;
            options.housner_restitution = housner_restitution;
            const sweep::SweepScenario base = sweep::load_sweep_scenario(scenario.parse(), scenario.file);
            SweepTable table;
            {
                py::gil_scoped_release release;
                table = run_plan(base, plan, options, threads);
            }
            py::dict out;
            out["columns"] = table.columns;
            out["rows"] = table.rows;
            out["bodies"] = table.bodies;
            return out;
        },
        py::arg("scenario"), py::arg("axes"), py::arg("records"), py::arg("record_files"), py::arg("scale"),
        py::arg("target_pga"), py::arg("target_pga_unit"), py::arg("record_keys"), py::arg("solver"),
        py::arg("stop_when_overturned"), py::arg("housner_dt_s"), py::arg("housner_restitution"), py::arg("threads"),
        "The rows of a sweep as results.csv holds them (use blockdem.sweep).");
}

}  // namespace blockdem::python
