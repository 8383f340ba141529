#include "motion/records/ground_motion_record.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "motion/records/record_readers.hpp"

namespace blockdem {
namespace records {

RecordFormat detect_record_format(const RecordText& text) {
    const auto& lines = text.lines;
    if (lines.empty()) fail_file(text, "the file is empty");
    if (cosmos_text_line_count(lines[0], true)) return RecordFormat::cosmos_v2;
    if (starts_with_nocase(lines[0], "Origin Time") && lines.size() > 13 && starts_with_nocase(lines[13], "Scale Factor"))
        return RecordFormat::knet;
    for (std::size_t i = 0; i < std::min<std::size_t>(lines.size(), 10); ++i)
        if (starts_with_nocase(trim(lines[i]), "SITE CODE")) return RecordFormat::jma_csv;
    for (std::size_t i = 0; i < std::min<std::size_t>(lines.size(), 20); ++i)
        if (find_npts_dt_phrase(lines[i])) return RecordFormat::peer_at2;
    return RecordFormat::plain_text;
}

double resolve_units(const RecordText& text, const RecordReadOptions& options, const std::string& file_units,
                     std::size_t line) {
    if (!options.units.empty()) {
        const auto factor = acceleration_unit_factor(options.units);
        if (!factor)
            throw InputError({text.file, "units", 0, 0},
                             fmt::format("unknown units '{}'; use one of: {}", options.units, acceleration_unit_names));
        return *factor;
    }
    const auto factor = acceleration_unit_factor(file_units);
    if (!factor)
        fail_at(text, line, fmt::format("unknown acceleration units '{}' (known: {}, cm/s^2, mg); give units to override",
                                        excerpt(file_units), acceleration_unit_names));
    return *factor;
}

namespace {

// Lower case, letters and digits only, and numbers without leading zeros ("067" -> "67").
std::string component_key(const std::string& name) {
    std::string out;
    for (char c : name)
        if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool digits = !out.empty() && std::all_of(out.begin(), out.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (digits) {
        out.erase(0, std::min(out.find_first_not_of('0'), out.size() - 1));
    }
    return out;
}

}  // namespace

bool same_component(const std::string& a, const std::string& b) { return component_key(a) == component_key(b); }

}  // namespace records

bool is_vertical_component(const std::string& component) {
    const std::string key = records::component_key(component);
    for (const char* vertical : {"up", "ud", "updown", "u", "dn", "dwn", "down", "v", "ver", "vert", "vertical", "z"})
        if (key == vertical) return true;
    // SEED channel codes: band, instrument, then the orientation (Z vertical; N, E, 1, 2 horizontal).
    return key.size() == 3 && std::isalpha(static_cast<unsigned char>(key[0])) &&
           std::isalpha(static_cast<unsigned char>(key[1])) && key[2] == 'z';
}

namespace records {

void check_sample_interval(const RecordText& text, std::size_t line, double dt_s) {
    if (!(dt_s >= min_record_dt_s && dt_s <= max_record_dt_s))
        fail_at(text, line, fmt::format("a sample interval of {:g} s is outside the accepted {:g} s to {:g} s", dt_s,
                                        min_record_dt_s, max_record_dt_s));
}

void check_component(const RecordText& text, const RecordReadOptions& options, const std::string& header_component,
                     std::size_t line) {
    if (options.component.empty() || header_component.empty()) return;
    if (!same_component(header_component, options.component))
        fail_at(text, line, fmt::format("component '{}' was asked for but this file holds component '{}'", options.component,
                                        excerpt(header_component)));
}

void check_si_range(const RecordText& text, const std::vector<double>& in_file, double to_m_s2,
                    const std::function<std::size_t(std::size_t)>& line_of) {
    for (std::size_t k = 0; k < in_file.size(); ++k)
        if (!std::isfinite(in_file[k] * to_m_s2))
            fail_at(text, line_of(k),
                    fmt::format("sample {} ({:g} in the file's units, {} m/s^2 each) is beyond the range of a number in "
                                "m/s^2: the value or the units are wrong",
                                k + 1, in_file[k], to_m_s2));
}

void convert_to_si(const RecordText& text, GroundMotionRecord& record, double to_m_s2,
                   const std::function<std::size_t(std::size_t)>& line_of) {
    check_si_range(text, record.acceleration_m_s2, to_m_s2, line_of);
    record.to_m_s2 = to_m_s2;
    for (double& a : record.acceleration_m_s2) a *= to_m_s2;
}

}  // namespace records

GroundMotionRecord read_ground_motion_record(const std::filesystem::path& file, const RecordReadOptions& options) {
    if (options.dt_s != 0.0 && !(options.dt_s >= min_record_dt_s && options.dt_s <= max_record_dt_s))
        throw InputError({file.string(), "dt", 0, 0}, fmt::format("dt = {:g} s is outside the accepted {:g} s to {:g} s",
                                                                 options.dt_s, min_record_dt_s, max_record_dt_s));
    const records::RecordText text = records::read_record_text(file);
    RecordFormat format = options.format;
    if (format == RecordFormat::automatic) format = records::detect_record_format(text);
    switch (format) {
        case RecordFormat::peer_at2: return records::read_peer_at2(text, options);
        case RecordFormat::knet: return records::read_knet(text, options);
        case RecordFormat::cosmos_v2: return records::read_cosmos_v2(text, options);
        case RecordFormat::jma_csv: return records::read_jma_csv(text, options);
        case RecordFormat::plain_text:
        case RecordFormat::automatic: break;
    }
    return records::read_plain_text(text, options);
}

namespace {

struct FormatName {
    RecordFormat format;
    std::string_view name;
};
constexpr std::array format_names{
    FormatName{RecordFormat::automatic, "auto"},     FormatName{RecordFormat::peer_at2, "peer-at2"},
    FormatName{RecordFormat::knet, "knet"},          FormatName{RecordFormat::cosmos_v2, "cosmos-v2"},
    FormatName{RecordFormat::jma_csv, "jma-csv"},    FormatName{RecordFormat::plain_text, "plain"},
    FormatName{RecordFormat::peer_at2, "at2"},       FormatName{RecordFormat::knet, "kiknet"},
    FormatName{RecordFormat::cosmos_v2, "cosmos"},   FormatName{RecordFormat::jma_csv, "jma"},
    FormatName{RecordFormat::plain_text, "csv"},     FormatName{RecordFormat::plain_text, "text"},
};

}  // namespace

std::string_view record_format_name(RecordFormat format) {
    for (const auto& f : format_names)
        if (f.format == format) return f.name;
    return "unknown";
}

std::string record_format_names() { return "auto, peer-at2, knet, cosmos-v2, jma-csv, plain"; }

RecordFormat parse_record_format(std::string_view name) {
    const std::string key = records::to_lower(name);
    for (const auto& f : format_names)
        if (f.name == key) return f.format;
    throw std::invalid_argument(fmt::format("unknown record format '{}'; use one of: {}", name, record_format_names()));
}

}  // namespace blockdem
