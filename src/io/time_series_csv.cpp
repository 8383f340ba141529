#include "io/time_series_csv.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/records/record_text.hpp"

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

// The index of a column in a file whose first row (header or data) has `columns` fields.
std::size_t column_index(const CsvColumn& column, const std::vector<std::string>& header, std::size_t columns,
                         const InputLocation& where) {
    if (column.index) {
        if (*column.index >= columns)
            throw InputError(where, fmt::format("{} = {} asks for column {} (0-based) but this line has {} column{}", column.key,
                                                *column.index, *column.index, columns, columns == 1 ? "" : "s"));
        return *column.index;
    }
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == column.name) return i;
    throw InputError(where, fmt::format("{} = \"{}\": no column of that name (header: {})", column.key, column.name,
                                        header.empty() ? "none" : fmt::format("{}", fmt::join(header, ", "))));
}

// A header that names a time: "t", "time", "time_s", "t [s]", "Time(s)", "sec", "seconds", in
// any case: the names the record reader's plain-text files use for time
// (motion/records/plain_text_reader.cpp), and "t_s", "t (s)".
bool is_time_name(const std::string& header) {
    std::string name;
    for (char c : header) name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == "t" || name.starts_with("time") || name.starts_with("sec")) return true;
    return name.size() > 1 && name[0] == 't' && std::string_view("_[( ").find(name[1]) != std::string_view::npos;
}

// Reading the time column as acceleration (dt given and the default column 0 of a "t,a" file)
// would drive the table with a ramp: refused.
void check_not_time(const CsvSeriesSpec& spec, const std::vector<std::string>& header, std::size_t a_col,
                    const InputLocation& where) {
    if (a_col >= header.size() || !is_time_name(header[a_col])) return;
    throw InputError(where, fmt::format("{} selects column {} ('{}'), which by its header holds time, as the acceleration: "
                                        "pick the acceleration column with `column` (a header name or 0-based index){}",
                                        spec.acceleration_column.key, a_col, header[a_col],
                                        spec.dt_s ? " or drop `dt` to take the times from the file" : ""));
}

// Every row has the columns of the first (header or data): a longer or shorter one has a value
// too many or missing, and the columns after it may be shifted.
void check_row_width(std::size_t fields, std::size_t columns, bool has_header, const InputLocation& where) {
    if (fields == columns) return;
    throw InputError(where, fmt::format("this line has {} column{} but the {} has {}", fields, fields == 1 ? "" : "s",
                                        has_header ? "header" : "first row", columns));
}

// A field that is not a number, as a message shows it: quoted, or said to be no text when it
// holds control or non-ASCII bytes (a binary file's, which were echoed to the terminal).
std::string not_a_number(const std::string& field) {
    const bool text = std::all_of(field.begin(), field.end(), [](char c) { return c >= 0x20 && c < 0x7f; });
    return text ? fmt::format("'{}' is not a finite number", field)
                : std::string("a field of bytes that are not text, not a number (is this a binary file?)");
}

// The time of a row, which must increase and not be negative: a motion starts at rest at its
// first sample, and one that started before t = 0 would have the table moving when the run
// begins. (A record's time column is instead taken to start at 0: records count time from a
// trigger; a CSV series is the motion's own schedule, and a first time above 0 delays it.)
double row_time(const std::string& field, const std::vector<double>& time_s, const InputLocation& where) {
    const auto t = to_number(field);
    if (!t) throw InputError(where, not_a_number(field));
    if (*t < 0.0)
        throw InputError(where, fmt::format("time {} s is before 0: a motion starts at rest at its first sample, and one "
                                            "that started before t = 0 would have the table already moving when the run "
                                            "begins; shift the times to start at 0 or later",
                                            *t));
    if (!time_s.empty() && !(*t > time_s.back()))
        throw InputError(where, fmt::format("time {} s does not increase (previous {} s)", *t, time_s.back()));
    return *t;
}

}  // namespace

AccelerationSeries read_time_series_csv(const CsvSeriesSpec& spec) {
    std::error_code size_error;
    const std::uintmax_t bytes = std::filesystem::file_size(spec.file, size_error);
    if (!size_error && bytes > records::max_record_file_bytes)  // refused before reading it
        throw InputError({spec.file.string(), "", 0, 0}, fmt::format("the file holds {} bytes; a time-series file may have at most {}",
                                                                     bytes, records::max_record_file_bytes));
    if (std::filesystem::is_directory(spec.file))
        throw InputError({spec.file.string(), "", 0, 0}, "a folder, not a time-series file");
    std::ifstream in(spec.file);
    if (!in) throw InputError({spec.file.string(), "", 0, 0}, "cannot open the time-series file");
    std::vector<double> time_s;
    std::vector<double> acc_m_s2;
    std::vector<std::string> header;
    std::size_t t_col = 0;
    std::size_t a_col = 0;
    std::size_t columns = 0;  // of the first row, header or data; 0 until it is read
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        const InputLocation where{spec.file.string(), "", line_no, 0};
        auto fields = split_fields(line);
        // Empty fields at a line's end are no column (a spreadsheet's export may end rows with a
        // comma): not counted in the row's width.
        while (fields.size() > 1 && fields.back().empty()) fields.pop_back();
        if (fields.empty() || (!fields[0].empty() && fields[0][0] == '#')) continue;
        if (columns == 0) {
            const bool is_header = !to_number(fields[0]);
            if (is_header) header = fields;
            columns = fields.size();
            a_col = column_index(spec.acceleration_column, header, columns, where);
            check_not_time(spec, header, a_col, where);
            if (!spec.dt_s) t_col = column_index(spec.time_column, header, columns, where);
            if (is_header) continue;
        }
        check_row_width(fields.size(), columns, !header.empty(), where);
        const auto a = to_number(fields[a_col]);
        if (!a) throw InputError(where, not_a_number(fields[a_col]));
        const double t = spec.dt_s ? static_cast<double>(acc_m_s2.size()) * *spec.dt_s : row_time(fields[t_col], time_s, where);
        if (acc_m_s2.size() == max_record_samples)
            throw InputError(where, fmt::format("a motion may have at most {} samples", max_record_samples));
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
    // A column is named by its header text or by its 0-based index, given as a TOML integer or
    // as a string of digits ("1"); anything else that looks like a number ("-1", "1e30", "1.5")
    // is neither and is refused here, with the key, rather than read as a wrapped index.
    auto column = [&](const char* key, std::size_t fallback) -> CsvColumn {
        if (!keys.has(key)) return {"", fallback, key};
        const toml::node& node = *keys.raw().get(key);
        const std::string range = fmt::format("0 to {}", max_csv_columns - 1);
        if (auto name = node.value_exact<std::string>()) {
            std::size_t index = 0;
            const char* end = name->data() + name->size();
            const auto digits = std::from_chars(name->data(), end, index);
            if (!name->empty() && std::isdigit(static_cast<unsigned char>(name->front())) && digits.ptr == end) {
                if (digits.ec != std::errc{} || index >= max_csv_columns)
                    keys.fail(key, fmt::format("column index \"{}\" is beyond the {} columns a CSV file may have ({})", *name,
                                               max_csv_columns, spec.file.string()));
                return {"", index, key};
            }
            if (to_number(*name))
                keys.fail(key, fmt::format("\"{}\" is neither a column name of {} nor a 0-based column index (a whole number, {})",
                                           *name, spec.file.string(), range));
            return {*name, std::nullopt, key};
        }
        if (!node.is_number()) keys.fail(key, "must be a column name (string) or a 0-based column index");
        const auto index = keys.optional_whole_number(key, 0, static_cast<std::int64_t>(max_csv_columns) - 1);
        return {"", static_cast<std::size_t>(*index), key};
    };
    spec.time_column = column("time_column", 0);
    spec.acceleration_column = column("column", spec.dt_s ? 0 : 1);
    // One column read as both: its times taken as accelerations (reported as times that do not
    // increase, or as a ramp).
    const bool same = spec.time_column.name == spec.acceleration_column.name &&
                      spec.time_column.index == spec.acceleration_column.index;
    if (!spec.dt_s && same) keys.fail(keys.has("column") ? "column" : "time_column", "names the same column as time_column and column");
    keys.reject_unknown_keys();
    try {
        return read_time_series_csv(spec);
    } catch (const std::invalid_argument& e) {
        keys.fail("file", e.what());
    }
}

}  // namespace blockdem
