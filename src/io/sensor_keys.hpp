#pragma once
// Measurement keys of a scenario (docs/scenario.md, "Sensors and interfaces"), read once the
// world is built, because they name its bodies and their filters depend on its time step:
//
//   [[sensors]]                      an accelerometer (with velocity and position) at a point
//   name = "top"                     column prefix in sensors.csv
//   body = "block"
//   point = [0.0, 0.5]               [m] in the body's own frame, from its centroid
//   lowpass_hz = 50.0                optional Butterworth cut-off [Hz] (< 1 / (2 dt))
//   order = 4                        optional, 1 to 8 (default 4; needs lowpass_hz)
//
//   [[sensors]]                      an LVDT: displacement of point on body relative to point2
//   name = "slip"                    on body2 (any body: the table, a fixed frame)
//   kind = "relative"
//   body = "block"  ,  point = [...]
//   body2 = "table" ,  point2 = [...]
//
//   [output]
//   interfaces = "auto" | "all" | "none" | [["a", "b"], ...]
//
// A point outside its body is refused (a sensor is mounted on the body; a point off it is a
// typo of a coordinate, most likely given in the world frame rather than from the centroid).
#include <cstddef>
#include <vector>

#include "io/toml_reader.hpp"
#include "world/interface_monitor.hpp"
#include "world/sensor.hpp"
#include "world/world.hpp"

namespace blockdem {

/// "auto" follows every touching pair in models of at most this many bodies, and none in larger
/// ones (a wall of 1e4 bricks has some 2e4 interfaces: name the ones wanted).
inline constexpr std::size_t interfaces_auto_max_bodies = 100;

struct MeasurementSettings {
    std::vector<SensorDef> sensors;
    InterfaceSelection interfaces;
};

/// Reads [[sensors]] and [output] interfaces from the scenario's root table.
MeasurementSettings read_measurement_keys(TableReader& root, const World& w);

}  // namespace blockdem
