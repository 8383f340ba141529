#pragma once
// ParaView output: VTK XML PolyData files, one pair per frame, in DIR/vtk/:
//   bodies_NNNNNN.vtp    every body as a polygon; cell data per body, point data per corner;
//   contacts_NNNNNN.vtp  every active contact point as a vertex with its forces;
//   bodies.pvd, contacts.pvd   collections listing the frames with their times, so that
//                              ParaView plays them as one time series.
// ASCII, so that the files can be read by any tool (and by eye). Field names carry their units
// (docs/outputs-visual.md). Frames are taken at the first output time at or after each
// multiple of the frame interval, so the interval is effectively rounded up to a multiple of
// [simulation] output_interval.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "world/simulation.hpp"

namespace blockdem {

struct VtkSettings {
    double frame_interval_s = 0.04;  ///< [s] between frames
    bool contacts = true;            ///< write contacts_NNNNNN.vtp
};

class VtkWriter : public Recorder {
public:
    /// Creates dir (DIR/vtk); throws InputError when it cannot.
    VtkWriter(std::filesystem::path dir, VtkSettings settings);
    void record(const World& w) override;
    /// Writes the .pvd collections (also after a run stopped on an error or a signal). A frame
    /// whose write failed is removed and not listed, so the collection names only whole files.
    void finish(const World& w) override;
    std::int64_t frames_written() const { return static_cast<std::int64_t>(times_s_.size()); }
    /// [s] the time of each frame written (a state file keeps them: io/run_state_parts.hpp).
    const std::vector<double>& frame_times_s() const { return times_s_; }
    /// Goes on after the frames at times_s, written earlier by the same run (a restart).
    void resume(std::vector<double> times_s, double dt_s);

private:
    std::filesystem::path dir_;
    VtkSettings settings_;
    std::int64_t next_frame_ = 0;   ///< index of the next frame due
    std::vector<double> times_s_;   ///< [s] time of each written frame
};

/// Writes a .pvd collection listing PREFIX_NNNNNN.vtp for each time (both dimensions).
void write_vtk_collection(const std::filesystem::path& file, const std::string& prefix, const std::vector<double>& times_s);

/// The VTK XML text of one frame of bodies / of contact points (exposed for the tests).
std::string vtk_bodies_polydata(const World& w);
std::string vtk_contacts_polydata(const World& w);

}  // namespace blockdem
