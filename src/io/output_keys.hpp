#pragma once
// The [output] table of a scenario: which files a run writes besides history.csv,
// summary.json and energy.csv (always written). Read here, in io/, so that the physics never
// sees it. Keys (docs/outputs-visual.md):
//   vtk          = "auto" | true | false   ParaView frames in DIR/vtk/ (default "auto")
//   vtk_interval = 0.04                     [s] between frames
//   vtk_contacts = true                     also write the contact points of each frame
//   report       = false                    `blockdem run` ends by writing DIR/report.html
#include <cstddef>
#include <cstdint>
#include <optional>

#include "io/toml_reader.hpp"

namespace blockdem {

/// "auto" writes VTK frames only while bodies x frames stays at or below this number: ASCII
/// frames take about 1 kB per body and frame with its contacts, so the cap keeps a run's VTK
/// output near 200 MB. Writing itself costs little next to the steps between two frames; it is
/// the disk that large runs would fill.
inline constexpr std::int64_t vtk_auto_max_body_frames = 200'000;

struct OutputSettings {
    std::optional<bool> vtk;        ///< nullopt: "auto"
    double vtk_interval_s = 0.04;   ///< [s] between VTK frames (25 per simulated second)
    bool vtk_contacts = true;       ///< contact points alongside the bodies
    bool report = false;            ///< write report.html at the end of `blockdem run`
};

/// Reads [output]; rejects unknown keys.
OutputSettings read_output_settings(TableReader& keys);

/// Number of VTK frames a run of duration_s would write (the first at t = 0).
std::int64_t vtk_frame_count(const OutputSettings& s, double duration_s);

/// Whether VTK frames are written for a run with body_count bodies (applies the "auto" rule).
bool vtk_enabled(const OutputSettings& s, std::size_t body_count, double duration_s);

}  // namespace blockdem
