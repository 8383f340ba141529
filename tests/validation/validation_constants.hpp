#pragma once
// The constants the validation tests share (gravity, the degree), defined once here so that the
// files compiled in one unity unit (BLOCKDEM_UNITY_BUILD: eight files to a unit, one anonymous
// namespace) do not define them twice. A file names those it uses in its anonymous namespace
// (`using validation::g;`) and writes them unqualified, as the physics does.
#include <numbers>

namespace blockdem::validation {

inline constexpr double g = 9.81;                        // [m/s^2] gravity
inline constexpr double deg = std::numbers::pi / 180.0;  // [rad] one degree

}  // namespace blockdem::validation
