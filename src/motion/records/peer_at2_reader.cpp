// PEER NGA .AT2 reader. A nominal 4-line header (banner; "event, date, station, component";
// "ACCELERATION TIME HISTORY IN UNITS OF G"; the NPTS/DT line), then NPTS values in g, free
// format, 5 per line, last line partial. The NPTS/DT line exists in two families: "NPTS= 4000,
// DT= .0100 SEC" (with or without SEC, lower-case dt, trailing filter text) and the NGA-West1
// "4096  0.0100  NPTS, DT"; some files have a longer header, so the line is searched for.

#include <fmt/format.h>

#include "motion/records/record_readers.hpp"

namespace blockdem::records {
namespace {

constexpr std::size_t header_search_lines = 20;

struct NptsDt {
    std::size_t line = 0;   // index of the NPTS/DT line
    std::size_t npts = 0;
    double dt_s = 0.0;      // [s]
};

constexpr std::string_view number_chars = "+-0123456789.ed";

// "NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([-+0-9.EeDd]*)" at `at`.
std::optional<NptsDtText> labelled_at(std::string_view line, std::size_t at) {
    LineScanner s(line, at);
    if (!s.literal("NPTS")) return std::nullopt;
    s.blanks();
    if (!s.literal("=")) return std::nullopt;
    s.blanks();
    const auto npts = s.digits();
    if (!npts) return std::nullopt;
    s.blanks();
    if (!s.literal(",")) return std::nullopt;
    s.blanks();
    if (!s.literal("DT")) return std::nullopt;
    s.blanks();
    if (!s.literal("=")) return std::nullopt;
    s.blanks();
    return NptsDtText{*npts, s.run_of(number_chars).value_or(std::string_view{})};
}

// "^\s*(\d+)\s+([-+0-9.EeDd]+)\s+NPTS\s*,\s*DT" (NGA-West1).
std::optional<NptsDtText> numbers_first(std::string_view line) {
    LineScanner s(line);
    s.blanks();
    const auto npts = s.digits();
    if (!npts || !s.some_blanks()) return std::nullopt;
    const auto dt = s.run_of(number_chars);
    if (!dt || !s.some_blanks() || !s.literal("NPTS")) return std::nullopt;
    s.blanks();
    if (!s.literal(",")) return std::nullopt;
    s.blanks();
    if (!s.literal("DT")) return std::nullopt;
    return NptsDtText{*npts, *dt};
}

std::optional<NptsDt> find_npts_dt(const RecordText& text) {
    const std::size_t n = std::min(text.lines.size(), header_search_lines);
    for (std::size_t i = 0; i < n; ++i) {
        const auto phrase = find_npts_dt_phrase(text.lines[i]);
        if (!phrase) continue;
        const auto dt = parse_fortran_number(phrase->dt);
        if (!dt || !(*dt > 0.0)) fail_at(text, i, fmt::format("DT '{}' is not a positive number", excerpt(phrase->dt)));
        check_sample_interval(text, i, *dt);
        const std::size_t npts = parse_count(text, i, phrase->npts, "NPTS", max_record_samples);
        check_count_fits(text, i, npts, free_values_capacity(text, i + 1), "NPTS");
        return NptsDt{i, npts, *dt};
    }
    return std::nullopt;
}

// "UNITS\s+OF\s+([A-Za-z/^0-9]+)", searched along the line.
std::optional<std::string> units_phrase(std::string_view line) {
    for (std::size_t at = find_nocase(line, "UNITS"); at != std::string_view::npos; at = find_nocase(line, "UNITS", at + 1)) {
        LineScanner s(line, at + 5);
        if (!s.some_blanks() || !s.literal("OF") || !s.some_blanks()) continue;
        if (const auto unit = s.run_of("abcdefghijklmnopqrstuvwxyz/^0123456789")) return std::string(*unit);
    }
    return std::nullopt;
}

// "UNITS OF G" on a header line before the NPTS line; velocity/displacement files are refused.
std::string header_units(const RecordText& text, std::size_t npts_line, std::size_t& units_line) {
    for (std::size_t i = 0; i < npts_line; ++i) {
        const std::string& line = text.lines[i];
        auto unit = units_phrase(line);
        if (!unit) continue;
        units_line = i;
        if (contains_nocase(line, "VELOCITY") || contains_nocase(line, "DISPLACEMENT"))
            fail_at(text, i, "this is a velocity or displacement file (VT2/DT2); an acceleration record (.AT2) is needed");
        while (!unit->empty() && unit->back() == '.') unit->pop_back();  // "UNITS OF G." ends a sentence
        return *unit;
    }
    units_line = npts_line;
    return "";
}

// Line 2: "EVENT [DATE], STATION, COMPONENT [(AGENCY ...)]": the last comma field is the
// component, the one before it the station, everything before that the event.
void read_event_line(const std::string& line, GroundMotionRecord& record) {
    std::vector<std::string> fields;
    std::size_t begin = 0;
    while (begin <= line.size()) {
        const std::size_t end = std::min(line.find(',', begin), line.size());
        fields.push_back(trim(std::string_view(line).substr(begin, end - begin)));
        begin = end + 1;
    }
    if (fields.size() < 3) {
        record.event = squeeze_blanks(line);
        return;
    }
    std::string component = fields.back();
    if (const auto paren = component.find('('); paren != std::string::npos) component = trim(component.substr(0, paren));
    record.component = component;
    record.station = fields[fields.size() - 2];
    record.event = fields[0];
    for (std::size_t i = 1; i + 2 < fields.size(); ++i) record.event += ", " + fields[i];
}

}  // namespace

std::optional<NptsDtText> find_npts_dt_phrase(std::string_view line) {
    for (std::size_t at = find_nocase(line, "NPTS"); at != std::string_view::npos; at = find_nocase(line, "NPTS", at + 1))
        if (auto phrase = labelled_at(line, at)) return phrase;
    return numbers_first(line);
}

GroundMotionRecord read_peer_at2(const RecordText& text, const RecordReadOptions& options) {
    const auto header = find_npts_dt(text);
    if (!header)
        fail_file(text, fmt::format("no 'NPTS= n, DT= dt' or 'n dt NPTS, DT' line in the first {} lines of this PEER AT2 file",
                                    header_search_lines));
    if (header->npts < 2) fail_at(text, header->line, fmt::format("NPTS = {} is too few points for a record", header->npts));
    GroundMotionRecord record;
    record.file = text.file;
    record.format = RecordFormat::peer_at2;
    record.dt_s = header->dt_s;
    if (header->line >= 2 && text.lines.size() > 1) read_event_line(text.lines[1], record);
    std::size_t units_line = 0;
    const std::string stated_unit = header_units(text, header->line, units_line);
    if (stated_unit.empty()) record.notes.push_back("the header states no units; AT2 files are in g");
    const std::string unit = stated_unit.empty() ? std::string("g") : stated_unit;
    record.units_in_file = unit;
    const double to_m_s2 = resolve_units(text, options, unit, units_line);
    check_component(text, options, record.component, 1);
    const ValueBlock block = read_free_values(text, header->line + 1, header->npts);
    if (block.extra_values > 0)  // NPTS wrong or two records run together: either way the file is not what it says
        fail_at(text, block.extra_line,
                fmt::format("the file holds {} more values than the NPTS = {} of line {}", block.extra_values, header->npts,
                            header->line + 1));
    record.acceleration_m_s2 = block.values;
    convert_to_si(text, record, to_m_s2, [&](std::size_t k) { return free_value_line(text, header->line + 1, k); });
    return record;
}

}  // namespace blockdem::records
