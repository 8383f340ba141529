// COSMOS Strong Motion Data Format v1.20, Volume 2 (processed acceleration). A file holds one or
// more channel blocks: T text lines (T stated on line 1), an integer header and a real header
// whose counts and Fortran formats are stated on their own first lines, NC comment lines, a data
// header "42000 acceleration pts, approx 210 secs, units=cm/sec2(04),Format=(1E15.6)", NPTS
// values in that fixed-width format, and an "End-of-data" trailer. dt is real header #62 in
// milliseconds. Fixed-width fields may touch, so values are cut by column, never split on blanks.
#include <regex>

#include <fmt/format.h>

#include "motion/records/record_readers.hpp"

namespace blockdem::records {
namespace {

// 1-based header indices used (COSMOS v1.20 tables).
constexpr std::size_t int_azimuth = 54;      // sensor azimuth, 400/402 up ...
constexpr std::size_t real_dt_ms = 62;       // [ms] sample interval
constexpr double unknown_value = -999.0;

struct FortranLayout {
    std::size_t per_line = 0;
    std::size_t width = 0;
};

// "(10I8)", "(5F15.6)", "(1E15.6)": count per line and field width.
FortranLayout parse_fortran_format(const RecordText& text, std::size_t line) {
    static const std::regex pattern(R"(\(\s*(\d*)\s*[IFEGD](\d+)(\.\d+)?\s*\))", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(text.lines[line], m, pattern))
        fail_at(text, line, "no Fortran format such as '(5F15.6)' on this line");
    const std::size_t count = m[1].str().empty() ? 1 : std::stoul(m[1].str());
    return {count, std::stoul(m[2].str())};
}

// A header section "N ... values follow on L lines, Format= (...)": returns the values.
std::vector<double> read_header_values(const RecordText& text, std::size_t& line, std::string_view what) {
    static const std::regex pattern(R"(^\s*(\d+)\s+\w+-header values follow on\s+(\d+)\s+lines)", std::regex::icase);
    if (line >= text.lines.size()) fail_at(text, line - 1, fmt::format("the file ends before the {} header", what));
    std::smatch m;
    if (!std::regex_search(text.lines[line], m, pattern))
        fail_at(text, line, fmt::format("expected the {} header line 'N {}-header values follow on L lines, Format= (...)'",
                                        what, what));
    const std::size_t count = std::stoul(m[1].str());
    const FortranLayout layout = parse_fortran_format(text, line);
    ValueBlock block = read_fixed_values(text, line + 1, count, layout.per_line, layout.width);
    line = block.next_line;
    return std::move(block.values);
}

struct DataHeader {
    std::size_t npts = 0;
    std::string quantity;  // "acceleration"
    std::string units;     // "cm/sec2"
    FortranLayout layout;
};

DataHeader read_data_header(const RecordText& text, std::size_t line) {
    static const std::regex pattern(R"(^\s*(\d+)\s+(\w+)\s+pts.*units\s*=\s*([^,(]+))", std::regex::icase);
    std::smatch m;
    if (line >= text.lines.size() || !std::regex_search(text.lines[line], m, pattern))
        fail_at(text, std::min(line, text.lines.size() - 1),
                "expected the data header 'NPTS acceleration pts, approx S secs, units=cm/sec2(04),Format=(...)'");
    return {std::stoul(m[1].str()), to_lower(m[2].str()), trim(m[3].str()), parse_fortran_format(text, line)};
}

std::string after_label(const std::string& line, std::string_view label) {
    const auto at = to_lower(line).find(to_lower(label));
    return at == std::string::npos ? std::string{} : squeeze_blanks(std::string_view(line).substr(at + label.size()));
}

// Channel code from "| RcrdId: US.1000hyfh.AK.BMR.BNZ.--" or the trailer "End-of-data for ChanBNZ ...".
std::string channel_code(const RecordText& text, std::size_t comments_begin, std::size_t trailer) {
    static const std::regex trailer_pattern(R"(End-of-data for Chan\s*(\S+))", std::regex::icase);
    std::smatch m;
    if (trailer < text.lines.size() && std::regex_search(text.lines[trailer], m, trailer_pattern)) return m[1].str();
    for (std::size_t i = comments_begin; i < trailer && i < text.lines.size(); ++i) {
        const std::string id = after_label(text.lines[i], "RcrdId:");  // NET.EVENT.NET.STA.CHAN.LOC or similar
        if (id.empty()) continue;
        std::vector<std::string> parts;
        for (std::size_t b = 0, e = 0; e != std::string::npos; b = e + 1) {
            e = id.find('.', b);
            parts.push_back(id.substr(b, e == std::string::npos ? e : e - b));
        }
        return parts.size() >= 5 ? parts[4] : id;
    }
    return "";
}

std::string azimuth_text(double code) {
    if (code >= 1.0 && code <= 360.0) return fmt::format("azimuth {:g}", code);
    if (code == 400.0 || code == 402.0) return "up";
    if (code == 401.0) return "down";
    return "";  // 0, -999 and the other codes: trust the channel code instead
}

struct Block {
    GroundMotionRecord record;
    std::size_t next_line = 0;
};

Block read_block(const RecordText& text, std::size_t first, const RecordReadOptions& options) {
    static const std::regex title(R"(with\s+(\d+)\s+text\s+lines)", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(text.lines[first], m, title))
        fail_at(text, first, "a COSMOS block starts with '<data type> (Format v01.20 with N text lines)'");
    const std::string data_type = to_lower(trim(text.lines[first].substr(0, std::min<std::size_t>(25, text.lines[first].size()))));
    if (data_type.find("acceleration") == std::string::npos || data_type.find("counts") != std::string::npos)
        fail_at(text, first, fmt::format("'{}' is not a corrected or uncorrected acceleration (V1/V2) block", data_type));
    const std::size_t text_lines = std::stoul(m[1].str());
    std::size_t line = first + text_lines;
    if (line > text.lines.size()) fail_at(text, text.lines.size() - 1, "the file ends inside the text header");
    const auto ints = read_header_values(text, line, "Integer");
    const auto reals = read_header_values(text, line, "Real");
    static const std::regex comments(R"(^\s*(\d+)\s+Comment line)", std::regex::icase);
    if (line >= text.lines.size() || !std::regex_search(text.lines[line], m, comments))
        fail_at(text, std::min(line, text.lines.size() - 1), "expected 'NC Comment line(s) follow'");
    const std::size_t comments_begin = line + 1;
    line = comments_begin + std::stoul(m[1].str());
    const DataHeader data = read_data_header(text, line);
    if (data.quantity != "acceleration")
        fail_at(text, line, fmt::format("this block holds {}, not acceleration", data.quantity));
    if (reals.size() < real_dt_ms || reals[real_dt_ms - 1] <= 0.0 || reals[real_dt_ms - 1] == unknown_value)
        fail_at(text, line, "real header #62 (sample interval in ms) is missing or unknown");
    GroundMotionRecord record;
    record.file = text.file;
    record.format = RecordFormat::cosmos_v2;
    record.dt_s = reals[real_dt_ms - 1] * 1e-3;
    record.event = after_label(text.lines[first + 1], "Record of");
    record.station = after_label(text.lines[first + 4], "Code:");
    record.units_in_file = data.units;
    const double to_m_s2 = resolve_units(text, options, data.units, line);
    ValueBlock values = read_fixed_values(text, line + 1, data.npts, data.layout.per_line, data.layout.width);
    const std::string channel = channel_code(text, comments_begin, values.next_line);
    const std::string azimuth = ints.size() >= int_azimuth ? azimuth_text(ints[int_azimuth - 1]) : "";
    record.component = azimuth.empty() ? channel : fmt::format("{} ({})", channel, azimuth);
    record.acceleration_m_s2 = std::move(values.values);
    convert_to_si(record, to_m_s2);
    std::size_t next = values.next_line;
    if (next < text.lines.size() && contains_nocase(text.lines[next], "End-of-data")) ++next;
    return {std::move(record), next};
}

bool wanted(const GroundMotionRecord& record, const RecordReadOptions& options) {
    if (options.component.empty()) return true;
    const auto fields = split_fields(record.component);
    const std::string code = fields.empty() ? std::string{} : std::string(fields[0]);
    return same_component(code, options.component) || same_component(record.component, options.component);
}

}  // namespace

GroundMotionRecord read_cosmos_v2(const RecordText& text, const RecordReadOptions& options) {
    std::vector<std::string> seen;
    std::size_t line = 0;
    while (line < text.lines.size()) {
        if (trim(text.lines[line]).empty()) {
            ++line;
            continue;
        }
        Block block = read_block(text, line, options);
        if (wanted(block.record, options)) return std::move(block.record);
        seen.push_back(block.record.component);
        line = block.next_line;
    }
    if (seen.empty()) fail_file(text, "no COSMOS channel block in this file");
    fail_file(text, fmt::format("no channel '{}' in this COSMOS file; it holds: {}", options.component, fmt::join(seen, ", ")));
}

}  // namespace blockdem::records
