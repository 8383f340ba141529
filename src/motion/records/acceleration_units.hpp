#pragma once
// Acceleration units met in record files and scenario keys, converted once to m/s^2.
#include <optional>
#include <string_view>

namespace blockdem {

/// Standard gravity [m/s^2]: the value behind "g" in every record and key (COSMOS files record
/// the same 980.665 cm/s^2). It is independent of the scenario's [simulation] gravity.
inline constexpr double standard_gravity_m_s2 = 9.80665;

/// m/s^2 per unit of `unit`, case-insensitive: "m/s^2" (also m/s2, m/s/s, m/sec2) = 1,
/// "gal" (also cm/s^2, cm/s2, cm/s/s, cm/sec2, cm/sec/sec) = 0.01, "g" = 9.80665,
/// "mg" = 9.80665e-3. nullopt for anything else.
std::optional<double> acceleration_unit_factor(std::string_view unit);

/// The unit names accepted in scenario keys and on the command line.
inline constexpr const char* acceleration_unit_names = "m/s^2, gal, g";

}  // namespace blockdem
