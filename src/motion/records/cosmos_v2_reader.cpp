// COSMOS Strong Motion Data Format v1.20, Volume 2 (processed acceleration). A file holds one or
// more channel blocks: T text lines (T stated on line 1), an integer header and a real header
// whose counts and Fortran formats are stated on their own first lines, NC comment lines, a data
// header "42000 acceleration pts, approx 210 secs, units=cm/sec2(04),Format=(1E15.6)", NPTS
// values in that fixed-width format, and an "End-of-data" trailer. dt is real header #62 in
// milliseconds. Fixed-width fields may touch, so values are cut by column, never split on blanks.
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

// "(10I8)", "(5F15.6)", "(1E15.6)": count per line and field width, i.e.
// "\(\s*(\d*)\s*[IFEGD](\d+)(\.\d+)?\s*\)" searched along the line.
FortranLayout parse_fortran_format(const RecordText& text, std::size_t line) {
    const std::string_view row = text.lines[line];
    for (std::size_t at = row.find('('); at != std::string_view::npos; at = row.find('(', at + 1)) {
        LineScanner s(row, at + 1);
        s.blanks();
        const auto count = s.digits();
        s.blanks();
        if (!s.one_of("IFEGD")) continue;
        const auto width = s.digits();
        if (!width) continue;
        if (s.literal(".") && !s.digits()) continue;
        s.blanks();
        if (!s.literal(")")) continue;
        const FortranLayout layout{count ? parse_count(text, line, *count, "the Fortran repeat count", max_record_line_chars) : 1,
                                   parse_count(text, line, *width, "the Fortran field width", max_record_line_chars)};
        if (layout.per_line == 0 || layout.width == 0)
            fail_at(text, line, fmt::format("the Fortran format '{}' has no field", excerpt(row.substr(at, s.position() - at))));
        return layout;
    }
    fail_at(text, line, "no Fortran format such as '(5F15.6)' on this line");
}

// A header section "N ... values follow on L lines, Format= (...)": returns the values.
std::vector<double> read_header_values(const RecordText& text, std::size_t& line, std::string_view what) {
    if (line >= text.lines.size()) fail_at(text, line - 1, fmt::format("the file ends before the {} header", what));
    // "^\s*(\d+)\s+\w+-header values follow on\s+(\d+)\s+lines"
    LineScanner s(text.lines[line]);
    s.blanks();
    const auto count = s.digits();
    const bool matched = count && s.some_blanks() && s.word() && s.literal("-header values follow on") && s.some_blanks() &&
                         s.digits() && s.some_blanks() && s.literal("lines");
    if (!matched)
        fail_at(text, line, fmt::format("expected the {} header line 'N {}-header values follow on L lines, Format= (...)'",
                                        what, what));
    const FortranLayout layout = parse_fortran_format(text, line);
    const std::size_t n = parse_count(text, line, *count, fmt::format("the {} header count", what), max_record_samples);
    check_count_fits(text, line, n, fixed_values_capacity(text, line + 1), fmt::format("{} header", what));
    ValueBlock block = read_fixed_values(text, line + 1, n, layout.per_line, layout.width);
    line = block.next_line;
    return std::move(block.values);
}

struct DataHeader {
    std::size_t npts = 0;
    std::string quantity;  // "acceleration"
    std::string units;     // "cm/sec2"
    FortranLayout layout;
};

// "^\s*(\d+)\s+(\w+)\s+pts.*units\s*=\s*([^,(]+)": the last "units=" after "pts".
DataHeader read_data_header(const RecordText& text, std::size_t line) {
    const std::string_view row = line < text.lines.size() ? std::string_view(text.lines[line]) : std::string_view{};
    LineScanner s(row);
    s.blanks();
    const auto npts = s.digits();
    const bool some = npts && s.some_blanks();
    const auto quantity = some ? s.word() : std::nullopt;
    const bool pts = quantity && s.some_blanks() && s.literal("pts");
    std::optional<std::string> units;
    for (std::size_t at = pts ? find_nocase(row, "units", s.position()) : std::string_view::npos; at != std::string_view::npos;
         at = find_nocase(row, "units", at + 1)) {
        LineScanner u(row, at + 5);
        u.blanks();
        if (!u.literal("=")) continue;
        u.blanks();
        const std::string unit = trim(u.until_any(",("));
        if (!unit.empty()) units = unit;
    }
    if (!units)
        fail_at(text, std::min(line, text.lines.size() - 1),
                "expected the data header 'NPTS acceleration pts, approx S secs, units=cm/sec2(04),Format=(...)'");
    const FortranLayout layout = parse_fortran_format(text, line);
    const std::size_t n = parse_count(text, line, *npts, "the number of points", max_record_samples);
    check_count_fits(text, line, n, fixed_values_capacity(text, line + 1), "the number of points");
    return {n, to_lower(*quantity), *units, layout};
}

std::string after_label(const std::string& line, std::string_view label) {
    const auto at = to_lower(line).find(to_lower(label));
    return at == std::string::npos ? std::string{} : squeeze_blanks(std::string_view(line).substr(at + label.size()));
}

// Channel code from "| RcrdId: US.1000hyfh.AK.BMR.BNZ.--" or the trailer "End-of-data for ChanBNZ ...".
std::string channel_code(const RecordText& text, std::size_t comments_begin, std::size_t trailer) {
    if (trailer < text.lines.size()) {
        const std::string_view row = text.lines[trailer];
        if (const auto at = find_nocase(row, "End-of-data for Chan"); at != std::string_view::npos) {
            LineScanner s(row, at + 20);
            s.blanks();
            const std::string_view code = s.until_any(" \t\r\f\v");
            if (!code.empty()) return std::string(code);
        }
    }
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
    const auto title_count = cosmos_text_line_count(text.lines[first], false);
    if (!title_count)
        fail_at(text, first, "a COSMOS block starts with '<data type> (Format v01.20 with N text lines)'");
    const std::string data_type = to_lower(trim(text.lines[first].substr(0, std::min<std::size_t>(25, text.lines[first].size()))));
    if (data_type.find("acceleration") == std::string::npos || data_type.find("counts") != std::string::npos)
        fail_at(text, first, fmt::format("'{}' is not a corrected or uncorrected acceleration (V1/V2) block", data_type));
    const std::size_t text_lines = parse_count(text, first, *title_count, "the number of text lines", max_record_lines);
    if (text_lines < 5) fail_at(text, first, fmt::format("a COSMOS text header has at least 5 lines; this one states {}", text_lines));
    if (text_lines >= text.lines.size() - first)
        fail_at(text, text.lines.size() - 1,
                fmt::format("the file ends inside the text header of {} lines announced at line {}", text_lines, first + 1));
    std::size_t line = first + text_lines;
    const auto ints = read_header_values(text, line, "Integer");
    const auto reals = read_header_values(text, line, "Real");
    // "^\s*(\d+)\s+Comment line"
    LineScanner c(line < text.lines.size() ? std::string_view(text.lines[line]) : std::string_view{});
    c.blanks();
    const auto comment_count = c.digits();
    if (!comment_count || !c.some_blanks() || !c.literal("Comment line"))
        fail_at(text, std::min(line, text.lines.size() - 1), "expected 'NC Comment line(s) follow'");
    const std::size_t comments_begin = line + 1;
    const std::size_t comment_lines = parse_count(text, line, *comment_count, "the number of comment lines", max_record_lines);
    if (comment_lines >= text.lines.size() - comments_begin)
        fail_at(text, line, fmt::format("{} comment lines are announced but the file ends {} lines later", comment_lines,
                                        text.lines.size() - comments_begin));
    line = comments_begin + comment_lines;
    const DataHeader data = read_data_header(text, line);
    if (data.quantity != "acceleration")
        fail_at(text, line, fmt::format("this block holds {}, not acceleration", data.quantity));
    if (reals.size() < real_dt_ms || reals[real_dt_ms - 1] <= 0.0 || reals[real_dt_ms - 1] == unknown_value)
        fail_at(text, line, "real header #62 (sample interval in ms) is missing or unknown");
    GroundMotionRecord record;
    record.file = text.file;
    record.format = RecordFormat::cosmos_v2;
    record.dt_s = reals[real_dt_ms - 1] * 1e-3;
    check_sample_interval(text, line, record.dt_s);
    record.event = after_label(text.lines[first + 1], "Record of");
    record.station = after_label(text.lines[first + 4], "Code:");
    record.units_in_file = data.units;
    const double to_m_s2 = resolve_units(text, options, data.units, line);
    ValueBlock values = read_fixed_values(text, line + 1, data.npts, data.layout.per_line, data.layout.width);
    const std::string channel = channel_code(text, comments_begin, values.next_line);
    const std::string azimuth = ints.size() >= int_azimuth ? azimuth_text(ints[int_azimuth - 1]) : "";
    record.component = azimuth.empty() ? channel : fmt::format("{} ({})", channel, azimuth);
    record.acceleration_m_s2 = std::move(values.values);
    convert_to_si(text, record, to_m_s2, [&](std::size_t k) {
        return fixed_value_line(text, line + 1, k, data.layout.per_line, data.layout.width);
    });
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

std::optional<std::string_view> cosmos_text_line_count(std::string_view line, bool need_version) {
    // "Format\s+v\d+\.\d+\s+" (when asked) then "with\s+(\d+)\s+text\s+lines", searched along the line.
    const std::string_view start = need_version ? "Format" : "with";
    for (std::size_t at = find_nocase(line, start); at != std::string_view::npos; at = find_nocase(line, start, at + 1)) {
        LineScanner s(line, at);
        if (need_version &&
            !(s.literal("Format") && s.some_blanks() && s.literal("v") && s.digits() && s.literal(".") && s.digits() && s.some_blanks()))
            continue;
        if (!s.literal("with") || !s.some_blanks()) continue;
        const auto count = s.digits();
        if (count && s.some_blanks() && s.literal("text") && s.some_blanks() && s.literal("lines")) return count;
    }
    return std::nullopt;
}

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
