// NIED K-NET / KiK-net ASCII reader. 17 header lines, key in columns 1-18 and value from column
// 19, read by line number because the key spellings vary ("Long."/"Lon.", "Max. Acc."/"Max Acc.").
// Data are integer counts, 8 per line; gal = (numerator/denominator) * (count - mean count),
// with the "Scale Factor" "3920(gal)/6182761". The mean over the whole record is removed as the
// format's users do: the counts carry a large logger offset, and NIED's own "Max. Acc." header
// value is max |S (c - mean c)| (checked on 8 real files). Count = rate x duration exactly.
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "motion/records/record_readers.hpp"

namespace blockdem::records {
namespace {

constexpr std::size_t header_lines = 17;
constexpr std::size_t value_column = 18;  // 0-based start of the value

// Header line numbers (0-based) of the fields used.
enum HeaderLine : std::size_t {
    origin_time = 0,
    magnitude = 4,
    station_code = 5,
    record_time = 9,
    sampling_frequency = 10,
    duration_time = 11,
    direction = 12,
    scale_factor = 13,
};

std::string header_value(const RecordText& text, std::size_t line) {
    const std::string& s = text.lines[line];
    return s.size() > value_column ? trim(std::string_view(s).substr(value_column)) : std::string{};
}

double header_number(const RecordText& text, std::size_t line, std::string_view what, std::string_view suffix = {}) {
    std::string value = header_value(text, line);
    if (!suffix.empty() && to_lower(value).ends_with(to_lower(suffix))) value.resize(value.size() - suffix.size());
    const auto number = parse_fortran_number(trim(value));
    if (!number || !(*number > 0.0))
        fail_at(text, line, fmt::format("{} '{}' is not a positive number", what, excerpt(header_value(text, line))), value_column + 1);
    return *number;
}

// "3920(gal)/6182761": gal per count.
double scale_factor_gal_per_count(const RecordText& text) {
    const std::string value = header_value(text, scale_factor);
    constexpr std::string_view number_chars = "0123456789.e+-";
    LineScanner s(value);
    s.blanks();
    const auto numerator_text = s.run_of(number_chars);
    s.blanks();
    const bool open = numerator_text && s.literal("(");
    const std::string unit = open ? trim(s.until_any(")")) : std::string{};
    const bool close = open && s.literal(")");
    s.blanks();
    const bool slash = close && s.literal("/");
    s.blanks();
    const auto denominator_text = slash ? s.run_of(number_chars) : std::nullopt;
    s.blanks();
    if (!denominator_text || !s.at_end())
        fail_at(text, scale_factor,
                fmt::format("Scale Factor '{}' is not of the form '3920(gal)/6182761'", excerpt(value)),
                value_column + 1);
    if (to_lower(unit) != "gal") fail_at(text, scale_factor, fmt::format("Scale Factor unit '{}' is not gal", excerpt(unit)), value_column + 1);
    const auto numerator = parse_fortran_number(*numerator_text);
    const auto denominator = parse_fortran_number(*denominator_text);
    if (!numerator || !denominator || *denominator == 0.0)
        fail_at(text, scale_factor, fmt::format("Scale Factor '{}' has an invalid number", excerpt(value)), value_column + 1);
    return *numerator / *denominator;
}

void check_header_keys(const RecordText& text) {
    if (text.lines.size() < header_lines)
        fail_at(text, text.lines.empty() ? 0 : text.lines.size() - 1,
                fmt::format("a K-NET file has {} header lines; this one ends after {} lines", header_lines, text.lines.size()));
    if (!starts_with_nocase(text.lines[origin_time], "Origin Time"))
        fail_at(text, origin_time, "a K-NET file starts with 'Origin Time'");
    if (!starts_with_nocase(text.lines[scale_factor], "Scale Factor"))
        fail_at(text, scale_factor, "line 14 of a K-NET file is the 'Scale Factor'");
    if (!starts_with_nocase(text.lines[sampling_frequency], "Sampling Freq"))
        fail_at(text, sampling_frequency, "line 11 of a K-NET file is the 'Sampling Freq(Hz)'");
}

// KiK-net writes the channel number: 1-3 borehole N-S/E-W/U-D, 4-6 the same at the surface.
std::string direction_name(const std::string& dir) {
    static const char* const kiknet[] = {"N-S borehole", "E-W borehole", "U-D borehole",
                                         "N-S surface",  "E-W surface",  "U-D surface"};
    if (dir.size() == 1 && dir[0] >= '1' && dir[0] <= '6') return fmt::format("{} ({})", dir, kiknet[dir[0] - '1']);
    return dir;
}

}  // namespace

GroundMotionRecord read_knet(const RecordText& text, const RecordReadOptions& options) {
    check_header_keys(text);
    GroundMotionRecord record;
    record.file = text.file;
    record.format = RecordFormat::knet;
    record.event = fmt::format("origin {} JST, M {}", header_value(text, origin_time), header_value(text, magnitude));
    record.station = header_value(text, station_code);
    record.component = direction_name(header_value(text, direction));
    const double rate_hz = header_number(text, sampling_frequency, "Sampling Freq", "Hz");
    const double duration_s = header_number(text, duration_time, "Duration Time");
    record.dt_s = 1.0 / rate_hz;
    check_sample_interval(text, sampling_frequency, record.dt_s);
    const double gal_per_count = scale_factor_gal_per_count(text);
    record.units_in_file = fmt::format("counts x {} gal ({})", gal_per_count, header_value(text, scale_factor));
    check_component(text, options, header_value(text, direction), direction);
    // The count is checked as a real number first: a wrong header (1e18 Hz) must not reach a cast.
    const double announced = std::round(rate_hz * duration_s);
    const std::size_t capacity = free_values_capacity(text, header_lines);
    if (!(announced <= static_cast<double>(std::min(capacity, max_record_samples))))
        fail_at(text, duration_time,
                fmt::format("Sampling Freq x Duration Time ({} Hz x {} s) announce {:g} values, but the rest of the file "
                            "can hold at most {} (and a record at most {})",
                            rate_hz, duration_s, announced, capacity, max_record_samples));
    const auto expected = static_cast<std::size_t>(announced);
    if (expected < 2) fail_at(text, duration_time, fmt::format("{} Hz x {} s is fewer than the 2 samples a record needs", rate_hz, duration_s));
    const ValueBlock block = read_free_values(text, header_lines, expected);
    if (block.extra_values > 0)
        fail_at(text, block.extra_line,
                fmt::format("the file holds {} more than the {} values that Sampling Freq x Duration Time ({} Hz x {} s) announce",
                            block.extra_values, expected, rate_hz, duration_s));
    // Checked before the mean is removed, so that a bad count is found on its own line.
    const double to_m_s2 = resolve_units(text, options, "gal", scale_factor) * gal_per_count;
    const auto line_of = [&](std::size_t k) { return free_value_line(text, header_lines, k); };
    check_si_range(text, block.values, to_m_s2, line_of);
    const double mean = std::accumulate(block.values.begin(), block.values.end(), 0.0) / static_cast<double>(expected);
    record.acceleration_m_s2.reserve(expected);
    for (double c : block.values) record.acceleration_m_s2.push_back(c - mean);
    record.notes.push_back(fmt::format("mean count {:.2f} removed (K-NET convention); record starts 15 s before Record Time {}",
                                       mean, header_value(text, record_time)));
    convert_to_si(text, record, to_m_s2, line_of);
    return record;
}

}  // namespace blockdem::records
