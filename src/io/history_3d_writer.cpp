#include "io/history_3d_writer.hpp"

#include <iterator>

#include <fmt/format.h>

namespace blockdem {

History3dWriter::History3dWriter(const std::filesystem::path& file, const World3d& w, OutputFile::Mode mode)
    : out_(file, mode) {
    std::string header = "t_s";
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] == BodyKind3d::fixed) continue;
        bodies_.push_back(i);
        for (const char* column : {"x_m", "y_m", "z_m", "qw", "qx", "qy", "qz", "rx_rad", "ry_rad", "rz_rad", "tilt_rad",
                                   "vx_m_s", "vy_m_s", "vz_m_s"})
            fmt::format_to(std::back_inserter(header), ",{}.{}", w.bodies[i].name, column);
    }
    if (mode == OutputFile::Mode::replace) out_.append(header + "\n");
}

void History3dWriter::record(const World3d& w, const ResponseMonitor3d& monitor) {
    std::string row = fmt::format("{:.9g}", w.time_s);
    for (std::size_t i : bodies_) {
        const Quaternion q = turn_since_start(w, monitor.bodies()[i], i);
        const Vec3 r = rotation_vector(q);
        const Vec3 x = position_now_m(w, i);
        const Vec3 v = velocity_now_m_s(w, i);
        fmt::format_to(std::back_inserter(row), ",{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.9g},{:.9g},{:.9g},"
                                                "{:.9g},{:.9g},{:.9g},{:.9g}",
                       x.x, x.y, x.z, q.w, q.x, q.y, q.z, r.x, r.y, r.z, tilt_rad(q),
                       v.x, v.y, v.z);
    }
    out_.append(row + "\n");
}

}  // namespace blockdem
