#include "sweep/results_table.hpp"

#include <algorithm>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "io/output_file.hpp"

namespace blockdem::sweep {
namespace {

const std::vector<std::string> body_columns{"overturned",     "overturning_time_s", "peak_rotation_rad",
                                            "peak_sliding_m", "residual_sliding_m", "mode",
                                            "rocking_period_ratio", "phase_lag_deg",
                                            // world/outcome.hpp; failed = overturned, fell or left_model
                                            "outcome", "outcome_time_s", "failed"};

std::string number(double v) { return fmt::format("{:.10g}", v); }

OutputError system_error(const std::string& what, const std::filesystem::path& file) {
    return OutputError(fmt::format("{}: {}: {}", file.string(), what, std::strerror(errno)));
}

void write_all(int fd, const std::string& text, const std::filesystem::path& file) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw system_error("cannot write", file);
        done += static_cast<std::size_t>(n);
    }
}

void sync_directory(const std::filesystem::path& dir) {
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;  // not fatal: the data itself is synced
    ::fsync(fd);
    ::close(fd);
}

std::string read_whole(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string body_fields(const std::optional<BodyOutcome>& o) {
    // (The empty fields of a case without results: one comma fewer than columns.)
    if (!o) return std::string(std::max<std::size_t>(body_columns.size(), 1) - 1, ',');
    return fmt::format("{},{},{},{},{},{},{},{},{},{},{}", o->overturned ? 1 : 0,
                       o->overturned ? number(o->overturning_time_s) : std::string(), number(o->peak_rotation_rad),
                       number(o->peak_sliding_m), number(o->residual_sliding_m), o->mode, o->rocking_period_ratio,
                       number(o->phase_lag_deg), o->outcome,
                       o->outcome_time_s >= 0.0 ? number(o->outcome_time_s) : std::string(), o->failed ? 1 : 0);
}

}  // namespace

std::int64_t leading_id(const std::string& row) { return std::stoll(row.substr(0, row.find(','))); }

std::vector<std::string> result_columns(const SweepPlan& plan, const std::vector<std::string>& body_names) {
    std::vector<std::string> columns{"case_id"};
    for (const auto& c : plan.value_columns()) columns.push_back(c);
    columns.insert(columns.end(), {"status", "error", "table_pga_m_s2"});
    for (const auto& b : body_names)
        for (const auto& c : body_columns) columns.push_back(b + "." + c);
    columns.push_back("wall_time_s");
    return columns;
}

std::string csv_field(const std::string& text) {
    std::string clean = text;
    for (char& ch : clean)
        if (ch == '\n' || ch == '\r') ch = ' ';
    if (clean.find_first_of(",\"") == std::string::npos) return clean;
    std::string quoted = "\"";
    for (char ch : clean) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
}

std::string format_row(const SweepCase& c, const CaseResult& r) {
    std::string row = std::to_string(c.id);
    for (const auto& v : c.column_values) {
        row += ',';
        row += csv_field(v);
    }
    row += fmt::format(",{},{},{}", r.status, csv_field(r.error), r.status == "error" ? "" : number(r.table_pga_m_s2));
    for (const auto& b : r.bodies) {
        row += ',';
        row += body_fields(b);
    }
    row += fmt::format(",{:.4f}", r.wall_s);
    return row;
}

FinishedCasesLog::FinishedCasesLog(const std::filesystem::path& file, const std::string& header) : file_(file) {
    std::string text = std::filesystem::exists(file) ? read_whole(file) : std::string();
    // A torn last line (the process died inside write()) is cut off; the case reruns.
    const std::size_t complete = text.rfind('\n');
    text.resize(complete == std::string::npos ? 0 : complete + 1);
    std::istringstream lines(text);
    std::string line;
    if (std::getline(lines, line) && line != header)
        throw std::runtime_error(fmt::format("{}: it was written by a sweep with other columns; use another --out", file.string()));
    while (std::getline(lines, line))
        if (!line.empty()) rows_[leading_id(line)] = line;
    fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT, 0644);
    if (fd_ < 0) throw system_error("cannot open", file);
    if (::ftruncate(fd_, static_cast<off_t>(text.size())) != 0 || ::lseek(fd_, 0, SEEK_END) < 0)
        throw system_error("cannot truncate", file);
    if (text.empty()) {
        write_all(fd_, header + "\n", file_);
        ::fsync(fd_);
        sync_directory(file.parent_path());
    }
}

FinishedCasesLog::~FinishedCasesLog() {
    if (fd_ >= 0) ::close(fd_);
}

void FinishedCasesLog::append(std::int64_t id, const std::string& row) {
    write_all(fd_, row + "\n", file_);  // one write: a crash leaves a whole row or a torn last one
    rows_[id] = row;
}

void FinishedCasesLog::sync() const {
    if (::fsync(fd_) != 0) throw system_error("cannot sync", file_);
}

void write_file_atomically(const std::filesystem::path& file, const std::string& text) {
    const std::filesystem::path temporary = file.string() + ".tmp";
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) throw system_error("cannot write", temporary);
    try {
        write_all(fd, text, temporary);
    } catch (const OutputError&) {
        ::close(fd);
        ::unlink(temporary.c_str());  // the old file stays whole; no temporary is left behind
        throw;
    }
    ::fsync(fd);
    if (::close(fd) != 0) {
        const OutputError error = system_error("cannot close", temporary);
        ::unlink(temporary.c_str());
        throw error;
    }
    std::filesystem::rename(temporary, file);
    sync_directory(file.parent_path());
}

void write_sorted_results(const std::filesystem::path& file, const std::string& header,
                          const std::map<std::int64_t, std::string>& rows) {
    std::string text = header + "\n";
    for (const auto& [id, row] : rows) text += row + "\n";
    write_file_atomically(file, text);
}

}  // namespace blockdem::sweep
