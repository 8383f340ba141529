#pragma once
// ParaView output of a 3-D run: VTK XML PolyData in DIR/vtk/, every body's faces as polygons
// (PolyData, not an UnstructuredGrid of VTK_POLYHEDRON cells: polygons need no face-stream
// encoding, every VTK reader since 5.x draws them, and a convex body is exactly its faces):
//   bodies_NNNNNN.vtp  the faces of every body at one time, cell data per face: body (index),
//                      tilt_rad and speed_m_s of its body;
//   contacts_NNNNNN.vtp  (vtk_contacts, as in 2-D) every contact point as a vertex: point data
//                      normal_force_n, shear_force_n, overlap_m, sliding, body_a, body_b, and
//                      the vectors normal (from a to b) and force_n (on b);
//   bodies.pvd, contacts.pvd   the frames with their times, so that ParaView plays them as a series.
// ASCII, as the 2-D writer (io/vtk_writer.hpp). The run calls record at its output times; a
// frame is taken at the first of them at or after each multiple of the frame interval.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "world/response_monitor_3d.hpp"

namespace blockdem {

/// The VTK XML text of one frame of contact points (exposed for the tests).
std::string vtk_contacts_3d_polydata(const World3d& w);

class Vtk3dWriter {
public:
    /// Creates dir (DIR/vtk); throws InputError when it cannot.
    Vtk3dWriter(std::filesystem::path dir, double frame_interval_s, bool contacts = true);
    /// Writes a frame when w.time_s has reached the next frame time.
    void record(const World3d& w, const ResponseMonitor3d& monitor);
    /// Writes bodies.pvd (and contacts.pvd).
    void finish();
    std::size_t frames_written() const { return times_s_.size(); }
    /// [s] the frames' times, in order (a state file keeps them).
    const std::vector<double>& frame_times_s() const { return times_s_; }
    /// A restarted run: the frames written before its state stay listed, the next is numbered after them.
    void continue_after(std::vector<double> times_s) { times_s_ = std::move(times_s); }

private:
    std::filesystem::path dir_;
    double frame_interval_s_;
    bool contacts_;
    std::vector<double> times_s_;
};

}  // namespace blockdem
