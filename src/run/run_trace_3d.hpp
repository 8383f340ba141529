#pragma once
// The history and energy rows of a 3-D run kept in memory, for the Python module
// (Simulation3d.history()): the same output times and bodies as history.csv (every body but the
// fixed ones, io/history_3d_writer.hpp), at full double precision.
#include <cstdint>
#include <vector>

#include "world/energy_ledger.hpp"
#include "world/response_monitor_3d.hpp"
#include "world/simulation.hpp"

namespace blockdem {

class RunTrace3d : public Recorder3d {
public:
    RunTrace3d(const World3d& w, const ResponseMonitor3d& monitor);
    void record(const World3d& w) override;

    std::size_t rows() const { return time_s.size(); }
    /// Ids of the recorded bodies: the columns of the per-body rows below.
    std::vector<std::uint32_t> bodies;
    std::vector<double> time_s;                   ///< [s] one per row
    // Row-major, rows() x bodies.size():
    std::vector<double> x_m, y_m, z_m;            ///< [m] centroid
    std::vector<double> qw, qx, qy, qz;           ///< the turn since t = 0, a unit quaternion
    std::vector<double> tilt_rad;                 ///< [rad] tilt about any horizontal axis
    std::vector<double> vx_m_s, vy_m_s, vz_m_s;   ///< [m/s] at t
    std::vector<double> wx_rad_s, wy_rad_s, wz_rad_s;  ///< [rad/s] at t, world frame
    std::vector<EnergyLedger> energy;             ///< one per row

private:
    const ResponseMonitor3d& monitor_;
};

}  // namespace blockdem
