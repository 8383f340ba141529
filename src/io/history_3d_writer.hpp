#pragma once
// history.csv of a 3-D run: one row per output time, per body (fixed ones left out) its centroid,
// its turn since t = 0 as a unit quaternion and as a rotation vector (axis times angle), its
// tilt (world/response_monitor_3d.hpp) and its velocity. Columns "<body>.<quantity>_<unit>":
//   t_s, then per body x_m, y_m, z_m, qw, qx, qy, qz, rx_rad, ry_rad, rz_rad, tilt_rad,
//   vx_m_s, vy_m_s, vz_m_s.
// The quaternion is the turn since the start (identity at t = 0), not the principal frame's
// orientation, so that a body standing still reads (1, 0, 0, 0) whatever its shape.
#include <filesystem>
#include <vector>

#include "io/output_file.hpp"
#include "world/response_monitor_3d.hpp"

namespace blockdem {

class History3dWriter {
public:
    /// mode append: the file already holds the header and the rows before a restart.
    History3dWriter(const std::filesystem::path& file, const World3d& w, OutputFile::Mode mode = OutputFile::Mode::replace);
    void record(const World3d& w, const ResponseMonitor3d& monitor);
    void finish() { out_.close(); }
    /// Writes the rows buffered so far (before a state file is saved).
    void flush() { out_.flush(); }

private:
    OutputFile out_;
    std::vector<std::size_t> bodies_;
};

}  // namespace blockdem
