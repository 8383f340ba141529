// PEER NGA .AT2 reader. A nominal 4-line header (banner; "event, date, station, component";
// "ACCELERATION TIME HISTORY IN UNITS OF G"; the NPTS/DT line), then NPTS values in g, free
// format, 5 per line, last line partial. The NPTS/DT line exists in two families: "NPTS= 4000,
// DT= .0100 SEC" (with or without SEC, lower-case dt, trailing filter text) and the NGA-West1
// "4096  0.0100  NPTS, DT"; some files have a longer header, so the line is searched for.
#include <regex>

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

std::optional<NptsDt> find_npts_dt(const RecordText& text) {
    static const std::regex labelled(R"(NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([-+0-9.EeDd]+))", std::regex::icase);
    static const std::regex numbers_first(R"(^\s*(\d+)\s+([-+0-9.EeDd]+)\s+NPTS\s*,\s*DT)", std::regex::icase);
    const std::size_t n = std::min(text.lines.size(), header_search_lines);
    for (std::size_t i = 0; i < n; ++i) {
        std::smatch m;
        if (std::regex_search(text.lines[i], m, labelled) || std::regex_search(text.lines[i], m, numbers_first)) {
            const auto dt = parse_fortran_number(m[2].str());
            if (!dt || !(*dt > 0.0)) fail_at(text, i, fmt::format("DT '{}' is not a positive number", m[2].str()));
            return NptsDt{i, std::stoul(m[1].str()), *dt};
        }
    }
    return std::nullopt;
}

// "UNITS OF G" on a header line before the NPTS line; velocity/displacement files are refused.
std::string header_units(const RecordText& text, std::size_t npts_line, std::size_t& units_line) {
    static const std::regex units(R"(UNITS\s+OF\s+([A-Za-z/^0-9]+))", std::regex::icase);
    for (std::size_t i = 0; i < npts_line; ++i) {
        std::smatch m;
        const std::string& line = text.lines[i];
        if (!std::regex_search(line, m, units)) continue;
        units_line = i;
        if (contains_nocase(line, "VELOCITY") || contains_nocase(line, "DISPLACEMENT"))
            fail_at(text, i, "this is a velocity or displacement file (VT2/DT2); an acceleration record (.AT2) is needed");
        std::string unit = m[1].str();
        while (!unit.empty() && unit.back() == '.') unit.pop_back();  // "UNITS OF G." ends a sentence
        return unit;
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
    std::string unit = header_units(text, header->line, units_line);
    if (unit.empty()) {
        unit = "g";
        record.notes.push_back("the header states no units; AT2 files are in g");
    }
    record.units_in_file = unit;
    const double to_m_s2 = resolve_units(text, options, unit, units_line);
    check_component(text, options, record.component, 1);
    const ValueBlock block = read_free_values(text, header->line + 1, header->npts);
    if (block.extra_values > 0)  // NPTS wrong or two records run together: either way the file is not what it says
        fail_at(text, block.extra_line,
                fmt::format("the file holds {} more values than the NPTS = {} of line {}", block.extra_values, header->npts,
                            header->line + 1));
    record.acceleration_m_s2 = block.values;
    convert_to_si(record, to_m_s2);
    return record;
}

}  // namespace blockdem::records
