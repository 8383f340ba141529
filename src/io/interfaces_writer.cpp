#include "io/interfaces_writer.hpp"

#include <iterator>

#include <fmt/format.h>

namespace blockdem {

InterfacesWriter::InterfacesWriter(const std::filesystem::path& file, const InterfaceSelection& selection,
                                   OutputFile::Mode mode)
    : monitor_(selection), out_(file, mode) {
    if (mode == OutputFile::Mode::append) return;
    out_.append(
        "# interfaces.csv (docs/outputs.md): one row per (time, interface). normal n from body_a into body_b, tangent s = n "
        "turned clockwise (+x for body_b resting on body_a). normal_force_n [N] on body_b along n, compression > 0; "
        "shear_force_n [N] on body_b along s; points: active contact points; opening_m [m]: gap at the far corner; "
        "slip_m [m]: accumulated slip of body_b on body_a along s; bonded_points, broken_points: active points whose bond is "
        "intact, broken\n"
        "t,body_a,body_b,normal_force_n,shear_force_n,points,opening_m,slip_m,bonded_points,broken_points\n");
    out_.flush();
}

void InterfacesWriter::record(const World& w) {
    std::string rows;
    std::int64_t count = 0;
    for (const InterfaceState& s : monitor_.interfaces()) {
        if (monitor_.follows_all() && !s.touching) continue;
        ++count;
        fmt::format_to(std::back_inserter(rows), "{:.9g},{},{},{:.9g},{:.9g},{},{:.9g},{:.9g},{},{}\n", w.time_s,
                       w.bodies.name[s.body_a], w.bodies.name[s.body_b], s.normal_force_n, s.shear_force_n, s.points,
                       s.opening_m, s.slip_m, s.bonded_points, s.broken_points);
    }
    out_.append(rows);
    if (w.step_index % steps_per_output(w) == 0 || w.step_index == total_steps(w)) output_time_rows_ += count;
    if (++rows_ % 200 == 0) out_.flush();
}

void InterfacesWriter::restore(std::vector<InterfaceState> states, std::int64_t output_time_rows) {
    monitor_.restore(std::move(states));
    output_time_rows_ = output_time_rows;
}

void InterfacesWriter::finish(const World&) { out_.close(); }

nlohmann::json interfaces_summary(const World& w, const InterfaceMonitor& monitor) {
    nlohmann::json list = nlohmann::json::array();
    for (const InterfaceState& s : monitor.interfaces())
        list.push_back({{"body_a", w.bodies.name[s.body_a]},
                        {"body_b", w.bodies.name[s.body_b]},
                        {"first_touch_time_s", s.first_touch_time_s >= 0.0 ? nlohmann::json(s.first_touch_time_s) : nlohmann::json(nullptr)},
                        {"touching_at_end", s.touching},
                        {"peak_abs_slip_m", s.peak_abs_slip_m},
                        {"residual_slip_m", s.slip_m},
                        {"peak_opening_m", s.peak_opening_m},
                        {"bonded_points_at_end", s.bonded_points},
                        {"broken_points_at_end", s.broken_points},
                        {"first_break_time_s", s.first_break_time_s >= 0.0 ? nlohmann::json(s.first_break_time_s) : nlohmann::json(nullptr)}});
    return {{"selection", monitor.follows_all() ? "every touching pair" : "named pairs"}, {"list", list}};
}

}  // namespace blockdem
