#pragma once
// The saved times of a finished run folder and the blocks at one of them, for
// `blockdem export --dxf` (docs/drawings.md): the VTK frames (vtk/bodies.pvd: each body's
// displacement and rotation to 9 significant digits) and the state files (state/t_*.h5: exact).
// bodies.json gives each body's corners about its centroid, its centroid at t = 0, and its kind
// and assembly, which name the layer it is exported on.
#include <filesystem>
#include <optional>
#include <vector>

#include "io/dxf_writer.hpp"

namespace blockdem {

/// One saved time of a run.
struct RunFrame {
    double time_s = 0.0;              ///< [s] as listed (the .pvd time, or the state file's name)
    std::filesystem::path file;       ///< a vtk/bodies_NNNNNN.vtp or a state/t_*.h5
    bool state_file = false;
};

/// The run's saved times, in increasing time (a state file after a VTK frame of the same time).
/// Throws InputError naming run_dir when it has none, or when it is not a run folder.
std::vector<RunFrame> run_frames(const std::filesystem::path& run_dir);

/// The frame nearest t_s (the state file on a tie: it is exact), or the last without t_s.
const RunFrame& nearest_frame(const std::vector<RunFrame>& frames, std::optional<double> t_s);

/// Every body of the run at frame, on the layer named by its assembly, or by its kind
/// ("dynamic", "fixed", "driven") for a body of [[bodies]]. Throws InputError naming the file.
std::vector<LayerPolygon> frame_blocks(const std::filesystem::path& run_dir, const RunFrame& frame);

}  // namespace blockdem
