// JMA strong-motion CSV as published on the JMA website: "KEY= value" metadata lines (SITE CODE,
// LAT., LON., SAMPLING RATE= 100Hz, UNIT = gal(cm/s/s), INITIAL TIME), then a column line
// "NS,EW,UD" and rows of three accelerations in gal. Trailing empty CSV fields and CRLF occur.
// Only the layout described in the project's format notes was checked, on a synthetic sample.
#include <fmt/format.h>

#include "motion/records/record_readers.hpp"

namespace blockdem::records {
namespace {

struct Metadata {
    std::string key;
    std::string value;
    std::size_t line = 0;
};

std::optional<Metadata> metadata(const RecordText& text, std::size_t end, std::initializer_list<std::string_view> keys) {
    for (std::size_t i = 0; i < end; ++i) {
        const std::string& line = text.lines[i];
        const auto eq = line.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = squeeze_blanks(line.substr(0, eq));
        for (auto k : keys)
            if (to_lower(key) == to_lower(k)) {
                std::string value = line.substr(eq + 1);
                while (!value.empty() && (value.back() == ',' || value.back() == ' ')) value.pop_back();
                return Metadata{key, trim(value), i};
            }
    }
    return std::nullopt;
}

}  // namespace

GroundMotionRecord read_jma_csv(const RecordText& text, const RecordReadOptions& options) {
    const NumericRows rows = read_numeric_rows(text, 0);
    const std::size_t header_end = rows.first_line;
    const auto rate = metadata(text, header_end, {"SAMPLING RATE", "Sampling Freq"});
    if (!rate) fail_at(text, 0, "no 'SAMPLING RATE= 100Hz' line in this JMA CSV header");
    std::string rate_text = rate->value;
    if (to_lower(rate_text).ends_with("hz")) rate_text.resize(rate_text.size() - 2);
    const auto rate_hz = parse_fortran_number(trim(rate_text));
    if (!rate_hz || !(*rate_hz > 0.0)) fail_at(text, rate->line, fmt::format("sampling rate '{}' is not a positive number", excerpt(rate->value)));
    GroundMotionRecord record;
    record.file = text.file;
    record.format = RecordFormat::jma_csv;
    record.dt_s = 1.0 / *rate_hz;
    check_sample_interval(text, rate->line, record.dt_s);
    if (const auto site = metadata(text, header_end, {"SITE CODE"})) record.station = site->value;
    if (const auto start = metadata(text, header_end, {"INITIAL TIME"})) record.event = "record start " + start->value + " JST";
    const auto unit = metadata(text, header_end, {"UNIT"});
    std::string unit_text = unit ? unit->value : std::string("gal");
    if (const auto paren = unit_text.find('('); paren != std::string::npos) unit_text = trim(unit_text.substr(0, paren));
    record.units_in_file = unit ? unit->value : "gal (JMA convention, no UNIT line)";
    const double to_m_s2 = resolve_units(text, options, unit_text, unit ? unit->line : 0);
    const auto names = header_end > 0 ? split_fields(text.lines[header_end - 1]) : std::vector<std::string_view>{};
    const std::size_t columns = rows.rows.front().size();
    if (names.size() != columns) fail_at(text, header_end, fmt::format("{} values per row but the column line names {}", columns, names.size()));
    std::size_t column = 0;
    if (options.component.empty()) {
        record.notes.push_back(fmt::format("no component asked for: the first column ({}) is used", names[0]));
    } else {
        while (column < columns && !same_component(std::string(names[column]), options.component)) ++column;
        if (column == columns)
            fail_at(text, header_end - 1, fmt::format("no column '{}'; columns: {}", options.component, fmt::join(names, ", ")));
    }
    record.component = std::string(names[column]);
    for (std::size_t k = 0; k < rows.rows.size(); ++k) {
        if (rows.rows[k].size() != columns)
            fail_at(text, rows.row_lines[k], fmt::format("{} values on this row, {} expected", rows.rows[k].size(), columns));
        record.acceleration_m_s2.push_back(rows.rows[k][column]);
    }
    if (record.npts() < 2) fail_at(text, rows.first_line, "a record needs at least 2 samples");
    convert_to_si(text, record, to_m_s2, [&](std::size_t k) { return rows.row_lines[k]; });
    return record;
}

}  // namespace blockdem::records
