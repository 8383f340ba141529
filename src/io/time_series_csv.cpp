#include "io/time_series_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/scenario.hpp"

namespace blockdem {
namespace {

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Comma- or semicolon-separated fields keep their empty fields (so "0.1,,0.5" is an error, not
// a shifted column); otherwise fields are separated by white space.
std::vector<std::string> split_fields(const std::string& line) {
    std::vector<std::string> fields;
    const bool delimited = line.find_first_of(",;") != std::string::npos;
    std::string current;
    for (char c : line) {
        const bool separator = delimited ? (c == ',' || c == ';') : (c == ' ' || c == '\t' || c == '\r');
        if (separator) {
            if (delimited || !current.empty()) fields.push_back(trim(current));
            current.clear();
        } else {
            current += c;
        }
    }
    if (delimited || !trim(current).empty()) fields.push_back(trim(current));
    if (fields.size() == 1 && fields[0].empty()) fields.clear();
    return fields;
}

std::optional<double> to_number(const std::string& text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::size_t column_index(const std::string& wanted, const std::vector<std::string>& header, const InputLocation& where) {
    if (auto index = to_number(wanted)) return static_cast<std::size_t>(*index);
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == wanted) return i;
    throw InputError(where, fmt::format("no column named '{}' (header: {})", wanted, fmt::join(header, ", ")));
}

}  // namespace

AccelerationSeries read_time_series_csv(const CsvSeriesSpec& spec) {
    std::ifstream in(spec.file);
    if (!in) throw InputError({spec.file.string(), "", 0, 0}, "cannot open the time-series file");
    std::vector<double> time_s;
    std::vector<double> acc_m_s2;
    std::vector<std::string> header;
    std::size_t t_col = 0;
    std::size_t a_col = 0;
    bool columns_known = false;
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        const InputLocation where{spec.file.string(), "", line_no, 0};
        const auto fields = split_fields(line);
        if (fields.empty() || (!fields[0].empty() && fields[0][0] == '#')) continue;
        if (!columns_known) {
            const bool is_header = !to_number(fields[0]);
            if (is_header) header = fields;
            a_col = column_index(spec.acceleration_column, header, where);
            if (!spec.dt_s) t_col = column_index(spec.time_column, header, where);
            columns_known = true;
            if (is_header) continue;
        }
        const std::size_t needed = std::max(a_col, spec.dt_s ? 0 : t_col) + 1;
        if (fields.size() < needed)
            throw InputError(where, fmt::format("expected at least {} columns, found {}", needed, fields.size()));
        const auto a = to_number(fields[a_col]);
        if (!a) throw InputError(where, fmt::format("'{}' is not a finite number", fields[a_col]));
        double t = 0.0;
        if (spec.dt_s) {
            t = static_cast<double>(acc_m_s2.size()) * *spec.dt_s;
        } else {
            const auto tv = to_number(fields[t_col]);
            if (!tv) throw InputError(where, fmt::format("'{}' is not a finite number", fields[t_col]));
            t = *tv;
            if (!time_s.empty() && !(t > time_s.back()))
                throw InputError(where, fmt::format("time {} s does not increase (previous {} s)", t, time_s.back()));
        }
        time_s.push_back(t);
        acc_m_s2.push_back(*a * spec.unit_factor);
    }
    if (acc_m_s2.size() < 2) throw InputError({spec.file.string(), "", line_no, 0}, "needs at least 2 samples");
    return make_acceleration_series(std::move(time_s), std::move(acc_m_s2), spec.file.string());
}

AccelerationSeries read_time_series_csv_keys(TableReader& keys, const std::filesystem::path& scenario_dir) {
    CsvSeriesSpec spec;
    spec.file = scenario_dir / keys.string("file");
    spec.dt_s = keys.optional_positive("dt");
    spec.unit_factor = acceleration_unit_factor(keys) * keys.number_or("scale", 1.0);
    // A column is named by its header text or by its 0-based index.
    auto column = [&](const char* key, const std::string& fallback) -> std::string {
        if (!keys.has(key)) return fallback;
        const toml::node& node = *keys.raw().get(key);
        if (auto name = node.value<std::string>()) return *name;
        if (auto index = node.value<std::int64_t>(); index && *index >= 0) return fmt::format("{}", *index);
        keys.fail(key, "must be a column name (string) or a 0-based column index");
    };
    spec.time_column = column("time_column", "0");
    spec.acceleration_column = column("column", spec.dt_s ? "0" : "1");
    keys.reject_unknown_keys();
    try {
        return read_time_series_csv(spec);
    } catch (const std::invalid_argument& e) {
        keys.fail("file", e.what());
    }
}

}  // namespace blockdem
