#pragma once
// The history and energy rows of a run kept in memory, for callers that want them as arrays and
// not as CSV (the Python module). It records at the same output times as history.csv and
// energy.csv, the same bodies as history.csv (Bodies::record), at full double precision.
#include <cstdint>
#include <vector>

#include "world/energy_ledger.hpp"
#include "world/simulation.hpp"

namespace blockdem {

class RunTrace : public Recorder {
public:
    explicit RunTrace(const World& w);
    void record(const World& w) override;

    std::size_t rows() const { return time_s.size(); }
    /// Ids of the recorded bodies: the columns of the per-body rows below.
    std::vector<std::uint32_t> bodies;
    std::vector<double> time_s;               ///< [s] one per row
    // Row-major, rows() x bodies.size():
    std::vector<double> x_m, y_m;             ///< [m] centroid
    std::vector<double> rotation_rad;         ///< [rad]
    std::vector<double> vx_m_s, vy_m_s;       ///< [m/s] at t
    std::vector<double> angular_velocity_rad_s;   ///< [rad/s] at t
    std::vector<double> ax_m_s2, ay_m_s2;     ///< [m/s^2]
    std::vector<double> angular_acceleration_rad_s2;  ///< [rad/s^2]
    std::vector<EnergyLedger> energy;         ///< one per row
};

}  // namespace blockdem
