// Plain-text and CSV records, which have no standard: a free-text header (any number of lines),
// then either a table with a time column ("time, acc" or "t, NS, EW, UD"), a table of named
// columns without time (dt given), or values only, any number per line (dt given). Separators:
// blanks, tabs, commas or semicolons. The units come from the header ("Accel[g]", "units of gal")
// or from the user; a file that states none must be given them: guessing g vs gal is a factor 980.
#include <cmath>

#include <fmt/format.h>

#include "motion/records/record_readers.hpp"

namespace blockdem::records {
namespace {

struct StatedUnits {
    std::string unit;       // "" when the header states none
    std::size_t line = 0;
};

// "acc\w*\s*[\[(]\s*([^\])]+?)\s*[\])]" searched along the line: "Accel[g]", "acc (gal)".
std::optional<std::string> bracketed_unit(std::string_view line) {
    for (std::size_t at = find_nocase(line, "acc"); at != std::string_view::npos; at = find_nocase(line, "acc", at + 1)) {
        LineScanner s(line, at + 3);
        s.word();
        s.blanks();
        if (!s.one_of("[(")) continue;
        const std::string unit = trim(s.until_any("])"));
        if (!s.at_end() && !unit.empty()) return unit;
    }
    return std::nullopt;
}

// "units?\s*(?:of|=|:)\s*([A-Za-z/^0-9]+)" searched along the line: "units of g", "Unit: gal".
std::optional<std::string> phrased_unit(std::string_view line) {
    for (std::size_t at = find_nocase(line, "unit"); at != std::string_view::npos; at = find_nocase(line, "unit", at + 1)) {
        LineScanner s(line, at + 4);
        s.literal("s");
        s.blanks();
        if (!s.literal("of") && !s.literal("=") && !s.literal(":")) continue;
        s.blanks();
        if (const auto unit = s.run_of("abcdefghijklmnopqrstuvwxyz/^0123456789")) return std::string(*unit);
    }
    return std::nullopt;
}

// "Accel[g]", "acc (gal)", "units of g", "units = cm/s^2", "Unit: gal".
StatedUnits header_units(const RecordText& text, std::size_t end) {
    for (std::size_t i = 0; i < end; ++i) {
        auto unit = bracketed_unit(text.lines[i]);
        if (!unit) unit = phrased_unit(text.lines[i]);
        if (!unit) continue;
        if (const auto paren = unit->find('('); paren != std::string::npos) unit->resize(paren);  // "gal(cm/s/s)"
        return {trim(*unit), i};
    }
    return {"", end};
}

// The names of the header line just above the data, when it has one name per column.
std::vector<std::string> column_names(const RecordText& text, const NumericRows& rows, std::size_t columns) {
    if (rows.first_line == 0) return {};
    const auto fields = split_fields(text.lines[rows.first_line - 1]);
    if (fields.size() != columns) return {};
    std::vector<std::string> names;
    for (auto f : fields) names.emplace_back(f);
    return names;
}

bool same_width(const NumericRows& rows) {
    for (const auto& r : rows.rows)
        if (r.size() != rows.rows.front().size()) return false;
    return true;
}

// dt from a time column when it increases with a constant step (to 0.1 % of the step).
std::optional<double> uniform_step(const NumericRows& rows) {
    if (rows.rows.size() < 2) return std::nullopt;
    const double t0 = rows.rows.front()[0];
    const double step = (rows.rows.back()[0] - t0) / static_cast<double>(rows.rows.size() - 1);
    if (!(step > 0.0)) return std::nullopt;
    for (std::size_t k = 0; k < rows.rows.size(); ++k)
        if (std::abs(rows.rows[k][0] - (t0 + static_cast<double>(k) * step)) > 1e-3 * step) return std::nullopt;
    return step;
}

bool is_time_name(const std::string& name) {
    const std::string n = to_lower(name);
    return n.starts_with("time") || n == "t" || n.starts_with("t[") || n.starts_with("t(") || n.starts_with("sec");
}

// Which column holds the acceleration: the only one besides time, or the one the user names
// (by header name or 1-based number).
std::size_t pick_column(const RecordText& text, const RecordReadOptions& options, const std::vector<std::string>& names,
                        std::size_t first, std::size_t columns, std::size_t header_line) {
    if (options.component.empty()) {
        if (columns - first == 1) return first;
        fail_at(text, header_line,
                fmt::format("the file has {} acceleration columns{}; say which with component", columns - first,
                            names.empty() ? "" : fmt::format(" ({})", fmt::join(names.begin() + first, names.end(), ", "))));
    }
    for (std::size_t c = first; c < names.size(); ++c)
        if (same_component(names[c], options.component)) return c;
    const auto number = parse_fortran_number(options.component);
    if (number && *number >= 1 && *number <= static_cast<double>(columns) && std::floor(*number) == *number)
        return static_cast<std::size_t>(*number) - 1;
    fail_at(text, header_line, fmt::format("no column '{}' in this file{}", options.component,
                                           names.empty() ? " (columns may be given by number, from 1)"
                                                         : fmt::format("; columns: {}", fmt::join(names, ", "))));
}

// A column named as time, or the first of two columns when it increases, must have a constant step.
void check_time_column(const RecordText& text, const NumericRows& rows, const std::vector<std::string>& names) {
    const bool looks_like_time = names.empty() ? rows.rows.front().size() == 2 && rows.rows[1][0] > rows.rows[0][0]
                                               : is_time_name(names[0]);
    if (!looks_like_time || rows.rows.size() < 3) return;
    const double step = rows.rows[1][0] - rows.rows[0][0];
    for (std::size_t k = 2; k < rows.rows.size(); ++k)
        if (std::abs(rows.rows[k][0] - rows.rows[k - 1][0] - step) > 1e-3 * std::abs(step))
            fail_at(text, rows.row_lines[k],
                    fmt::format("the time column is not equally spaced: {} s after {} s, where the step is {} s",
                                rows.rows[k][0], rows.rows[k - 1][0], step));
}

void read_table(const RecordText& text, const RecordReadOptions& options, const NumericRows& rows,
                GroundMotionRecord& record) {
    const std::size_t columns = rows.rows.front().size();
    const auto names = column_names(text, rows, columns);
    const auto step = uniform_step(rows);
    if (!step) check_time_column(text, rows, names);
    const bool has_time = step && (names.empty() || is_time_name(names[0]));
    if (has_time) {
        if (options.dt_s > 0.0 && std::abs(options.dt_s - *step) > 1e-3 * *step)
            fail_at(text, rows.first_line,
                    fmt::format("dt = {} s was given but the time column has a step of {} s", options.dt_s, *step));
        record.dt_s = *step;
        check_sample_interval(text, rows.first_line, record.dt_s);
        if (rows.rows.front()[0] != 0.0)
            record.notes.push_back(fmt::format("the time column starts at {} s; the record is taken to start at 0", rows.rows.front()[0]));
    } else {
        if (!(options.dt_s > 0.0))
            fail_at(text, rows.first_line, "the file has no time column: give the sample interval dt");
        record.dt_s = options.dt_s;
    }
    const std::size_t column = pick_column(text, options, names, has_time ? 1 : 0, columns,
                                           rows.first_line == 0 ? 0 : rows.first_line - 1);
    if (!names.empty() && columns - (has_time ? 1 : 0) > 1) record.component = names[column];
    for (const auto& r : rows.rows) record.acceleration_m_s2.push_back(r[column]);
}

void read_values_only(const RecordText& text, const RecordReadOptions& options, const NumericRows& rows,
                      GroundMotionRecord& record) {
    if (!(options.dt_s > 0.0))
        fail_at(text, rows.first_line, "the file holds values only (no time column): give the sample interval dt");
    record.dt_s = options.dt_s;
    std::size_t count = 0;
    for (const auto& r : rows.rows) count += r.size();
    if (count > max_record_samples)
        fail_at(text, rows.first_line, fmt::format("the file holds {} values; a record may have at most {}", count, max_record_samples));
    record.acceleration_m_s2.reserve(count);
    for (const auto& r : rows.rows) record.acceleration_m_s2.insert(record.acceleration_m_s2.end(), r.begin(), r.end());
}

}  // namespace

GroundMotionRecord read_plain_text(const RecordText& text, const RecordReadOptions& options) {
    const NumericRows rows = read_numeric_rows(text, 0);
    GroundMotionRecord record;
    record.file = text.file;
    record.format = RecordFormat::plain_text;
    const StatedUnits stated = header_units(text, rows.first_line);
    if (stated.unit.empty() && options.units.empty())
        fail_at(text, rows.first_line,
                fmt::format("the file does not state its units; give them ({})", acceleration_unit_names));
    record.units_in_file = stated.unit.empty() ? options.units : stated.unit;
    const double to_m_s2 = resolve_units(text, options, stated.unit, stated.line);
    if (rows.first_line > 0) record.event = squeeze_blanks(text.lines[0]);
    for (std::size_t i = 0; i < rows.first_line; ++i)
        if (const auto colon = text.lines[i].find(':'); colon != std::string::npos && contains_nocase(text.lines[i].substr(0, colon), "station"))
            record.station = squeeze_blanks(text.lines[i].substr(colon + 1));
    const std::size_t columns = rows.rows.front().size();
    const bool table = columns >= 2 && same_width(rows) && rows.rows.size() >= 2;  // else values only
    if (table)
        read_table(text, options, rows, record);
    else
        read_values_only(text, options, rows, record);
    if (record.npts() < 2) fail_at(text, rows.first_line, "a record needs at least 2 samples");
    if (rows.trailer_line > 0) record.notes.push_back(fmt::format("data end at the trailer on line {}", rows.trailer_line + 1));
    convert_to_si(text, record, to_m_s2, [&](std::size_t k) { return table ? rows.row_lines[k] : row_value_line(rows, k); });
    return record;
}

}  // namespace blockdem::records
