#include "io/sensors_writer.hpp"

#include <iterator>

#include <fmt/format.h>

namespace blockdem {

std::string sensors_csv_header(const World& w, const SensorBank& bank) {
    std::string text =
        "# sensors.csv (docs/outputs.md): t [s]; point sensors <name>.ax, .ay [m/s^2], .vx, .vy [m/s], .x, .y [m], "
        "absolute in the ground's frame, gravity not included; relative sensors <name>.dx, .dy [m], point minus point2 "
        "from the start\n";
    for (std::size_t s = 0; s < bank.sensors().size(); ++s) {
        const SensorDef& d = bank.sensors()[s];
        const std::string where =
            d.kind == SensorKind::point
                ? fmt::format("point [{:g}, {:g}] m of '{}'", d.point_m.x, d.point_m.y, w.bodies.name[d.body])
                : fmt::format("point [{:g}, {:g}] m of '{}' relative to point [{:g}, {:g}] m of '{}'", d.point_m.x, d.point_m.y,
                              w.bodies.name[d.body], d.point2_m.x, d.point2_m.y, w.bodies.name[d.body2]);
        const std::string filter =
            bank.design(s) ? fmt::format("Butterworth low-pass {:g} Hz, order {}, causal, applied at every step (dt {:.4g} s); "
                                         "group delay at low frequency {:.4g} s",
                                         d.lowpass_hz, d.order, w.dt_s, dc_group_delay_s(*bank.design(s)))
                           : std::string("unfiltered");
        fmt::format_to(std::back_inserter(text), "# {}: {}; {}\n", d.name, where, filter);
    }
    text += "t";
    for (const SensorDef& d : bank.sensors())
        for (const auto& [suffix, unit] : sensor_columns(d.kind)) fmt::format_to(std::back_inserter(text), ",{}.{}", d.name, suffix);
    text += '\n';
    return text;
}

SensorsWriter::SensorsWriter(const std::filesystem::path& file, const World& w, std::vector<SensorDef> sensors,
                             OutputFile::Mode mode)
    : bank_(std::move(sensors), w.dt_s), out_(file, mode) {
    if (mode == OutputFile::Mode::append) return;
    out_.append(sensors_csv_header(w, bank_));
    out_.flush();
}

void SensorsWriter::record(const World& w) {
    std::string row = fmt::format("{:.9g}", w.time_s);
    for (double v : bank_.values()) fmt::format_to(std::back_inserter(row), ",{:.9g}", v);
    row += '\n';
    out_.append(row);
    if (++rows_ % 200 == 0) out_.flush();
}

void SensorsWriter::finish(const World&) { out_.close(); }

}  // namespace blockdem
