#pragma once
// Sensors: what a shake-table test measures on its specimen, read from the world at every step.
//
// A point sensor (an accelerometer with its integrals) sits at a point fixed in a body. For a
// rigid body with centroid c, rotation theta, angular velocity omega and angular acceleration
// alpha, the point at r = R(theta) r0 (r0 given in the body's own frame: from the centroid,
// axes as the body was laid out at the start) has
//     position      x = c + r
//     velocity      v = v_c + omega x r
//     acceleration  a = a_c + alpha x r - omega^2 r
// all absolute, in the ground's (inertial) frame, which is what an accelerometer on a shake
// table measures; gravity is not part of a (a body at rest reads 0, not +g).
//
// A relative sensor (an LVDT or a string potentiometer) gives the displacement of a point on
// one body relative to a point on another (possibly the table or a fixed body), from the start:
// d = (x1(t) - x2(t)) - (x1(0) - x2(0)).
//
// Optionally each channel is low-pass filtered with a Butterworth filter (signal/butterworth.hpp)
// at every time step, before the output decimates the signal, so that the filter sees the
// impact spikes it is meant to remove instead of an aliased sample of them.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"
#include "signal/butterworth.hpp"
#include "world/world.hpp"

namespace blockdem {

enum class SensorKind : std::uint8_t { point, relative };

/// One [[sensors]] entry, resolved to body ids.
struct SensorDef {
    std::string name;
    SensorKind kind = SensorKind::point;
    std::uint32_t body = 0;
    Vec2 point_m;                  ///< [m] in body's own frame, from its centroid
    std::uint32_t body2 = 0;       ///< relative sensors: the reference body
    Vec2 point2_m;                 ///< [m] relative sensors: in body2's frame, from its centroid
    double lowpass_hz = 0.0;       ///< [Hz] Butterworth cut-off; 0: unfiltered
    int order = 4;                 ///< Butterworth order
};

/// The state of a point fixed in a body, in the ground's frame.
struct PointKinematics {
    Vec2 position_m;        ///< [m]
    Vec2 velocity_m_s;      ///< [m/s]
    Vec2 acceleration_m_s2; ///< [m/s^2]
};

/// Kinematics of the point r0 (body frame, from the centroid) of body i at the world's time t.
PointKinematics point_kinematics(const Bodies& b, std::uint32_t i, Vec2 r0_m);

/// Number of output channels of a sensor: 6 (ax, ay, vx, vy, x, y) or 2 (dx, dy).
std::size_t sensor_channel_count(SensorKind kind);
/// Column suffixes and their units, in channel order.
const std::vector<std::pair<const char*, const char*>>& sensor_columns(SensorKind kind);

/// What a SensorBank carries from one step to the next (a state file saves it): every filtered
/// channel's running state, and each relative sensor's reading at the start.
struct SensorBankState {
    std::vector<double> filter_state;         ///< the filters' states, filter by filter (two per section)
    std::vector<std::uint8_t> filter_started; ///< per filter: 1 once it has had its first sample
    std::vector<Vec2> relative_start_m;       ///< [m] per sensor: x1(0) - x2(0) (0 for point sensors)
    bool started = false;                     ///< the first step has been observed
};

/// Every sensor of a run, updated at every step; values() holds the latest filtered channels.
class SensorBank {
public:
    /// dt_s: the time step (the filters' sample interval).
    SensorBank(std::vector<SensorDef> sensors, double dt_s);
    /// Reads the state at t; call once per step.
    void observe(const World& w);
    const std::vector<SensorDef>& sensors() const { return sensors_; }
    /// Latest channel values, sensor by sensor in the order of sensor_columns().
    const std::vector<double>& values() const { return values_; }
    /// The filter of sensor s (nullopt when unfiltered).
    const std::optional<ButterworthDesign>& design(std::size_t s) const { return designs_[s]; }
    SensorBankState state() const;
    /// Continues from a saved state() of a bank with the same sensors; std::invalid_argument
    /// when its sizes are not this bank's.
    void restore(const SensorBankState& state);

private:
    std::vector<SensorDef> sensors_;
    std::vector<std::optional<ButterworthDesign>> designs_;
    std::vector<std::size_t> first_channel_;
    std::vector<ButterworthChannel> filters_;   ///< one per channel of the filtered sensors
    std::vector<std::int64_t> filter_of_channel_;  ///< index into filters_, -1: unfiltered
    std::vector<Vec2> relative_start_m_;       ///< [m] x1(0) - x2(0) per sensor (relative only)
    std::vector<double> raw_;
    std::vector<double> values_;
    bool started_ = false;
};

}  // namespace blockdem
