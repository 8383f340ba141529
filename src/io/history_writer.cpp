#include "io/history_writer.hpp"

#include <iterator>

#include <fmt/format.h>

namespace blockdem {

const std::vector<std::pair<const char*, const char*>>& history_column_units() {
    static const std::vector<std::pair<const char*, const char*>> units = {
        {"x", "m"},      {"y", "m"},      {"rot", "rad"},    {"vx", "m/s"},     {"vy", "m/s"},
        {"vrot", "rad/s"}, {"ax", "m/s^2"}, {"ay", "m/s^2"}, {"arot", "rad/s^2"}};
    return units;
}

HistoryWriter::HistoryWriter(const std::filesystem::path& file, const World& w, OutputFile::Mode mode) : out_(file, mode) {
    std::string header = "t";
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i) {
        if (!w.bodies.record[i]) continue;
        bodies_.push_back(i);
        for (const auto& [suffix, unit] : history_column_units())
            fmt::format_to(std::back_inserter(header), ",{}.{}", w.bodies.name[i], suffix);
    }
    header += '\n';
    if (mode == OutputFile::Mode::append) return;
    out_.append(header);
    out_.flush();
}

void HistoryWriter::record(const World& w) {
    const Bodies& b = w.bodies;
    std::string row = fmt::format("{:.9g}", w.time_s);
    for (std::uint32_t i : bodies_) {
        fmt::format_to(std::back_inserter(row), ",{:.12g},{:.12g},{:.12g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}",
                       b.position_m[i].x, b.position_m[i].y, b.rotation_rad[i], b.velocity_at_t_m_s[i].x,
                       b.velocity_at_t_m_s[i].y, b.angular_velocity_at_t_rad_s[i], b.acceleration_m_s2[i].x,
                       b.acceleration_m_s2[i].y, b.angular_acceleration_rad_s2[i]);
    }
    row += '\n';
    out_.append(row);
    if (++rows_ % 200 == 0) out_.flush();
}

void HistoryWriter::finish(const World&) { out_.close(); }

}  // namespace blockdem
