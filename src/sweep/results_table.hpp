#pragma once
// The results of a sweep, as CSV. Two files in the output folder:
//   finished_cases.csv  every case as it finishes, in finishing order, appended with one
//                       write() and fsync'd: what a crash, a kill or Ctrl-C leaves behind;
//   results.csv         the same rows sorted by case id (rewritten atomically at the end), so
//                       that the table is the same whatever the thread or rank count.
// A column name carries its unit as a suffix (_s, _rad, _m, _m_s2, _deg); a varied value keeps
// the key's own name (its unit is the scenario's, see docs/sweeps.md).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sweep/case_runner.hpp"
#include "sweep/sweep_plan.hpp"

namespace blockdem::sweep {

/// Column names, in order: case_id, the varied values, status, error, table_pga_m_s2, per body
/// the outcome columns, and wall_time_s last (the one column that differs between reruns).
std::vector<std::string> result_columns(const SweepPlan& plan, const std::vector<std::string>& body_names);

/// One CSV row (no newline) for a finished case.
std::string format_row(const SweepCase& c, const CaseResult& r);

/// A CSV field, quoted when it holds a comma, a quote or a line break (line breaks become spaces).
std::string csv_field(const std::string& text);

/// The append-only file of finished cases.
class FinishedCasesLog {
public:
    /// Opens or creates the log. An existing log must have this header (else std::runtime_error);
    /// a torn last line (killed mid-write) is cut off. The rows already there are loaded.
    FinishedCasesLog(const std::filesystem::path& file, const std::string& header);
    ~FinishedCasesLog();
    FinishedCasesLog(const FinishedCasesLog&) = delete;
    FinishedCasesLog& operator=(const FinishedCasesLog&) = delete;

    /// Appends one row with a single write() (so that a killed process leaves it whole) and
    /// keeps it. Not thread safe: callers lock. Follow with sync() to make it durable.
    void append(std::int64_t id, const std::string& row);
    /// fsync: the rows appended so far survive a crash of the machine. Thread safe, and may
    /// run while another thread appends.
    void sync() const;
    /// Finished rows by case id.
    const std::map<std::int64_t, std::string>& rows() const { return rows_; }

private:
    std::filesystem::path file_;
    int fd_ = -1;
    std::map<std::int64_t, std::string> rows_;
};

/// The case id a results row starts with (its first field).
std::int64_t leading_id(const std::string& row);

/// Writes header + rows sorted by case id to file, through a temporary file and a rename.
void write_sorted_results(const std::filesystem::path& file, const std::string& header,
                          const std::map<std::int64_t, std::string>& rows);

/// Writes text to file atomically (temporary file, fsync, rename).
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace blockdem::sweep
