#pragma once
// The state a run keeps outside the world, as groups of its state files (io/state_file.hpp):
//   /monitor  the response monitor behind summary.json (peaks, onsets, supporters, outcomes);
//   /vtk      the times of the VTK frames written so far.
// A recorder or monitor added later with state of its own writes a StatePart like these and
// adds it to the run's list in run/scenario_run.cpp.
#include "io/state_file.hpp"
#include "io/vtk_writer.hpp"
#include "world/response_monitor.hpp"

namespace blockdem {

class MonitorStatePart : public StatePart {
public:
    explicit MonitorStatePart(ResponseMonitor& monitor) : monitor_(monitor) {}
    std::string state_group() const override { return "monitor"; }
    void save_state(StateGroup& group) const override;
    void restore_state(const StateGroup& group) override;

private:
    ResponseMonitor& monitor_;
};

/// The frames listed in the .pvd collections. On restore only the frames taken at output times
/// before the state's step are kept (an interrupted run wrote one more, at the time it stopped);
/// the frames after it are written again as the run goes on.
class VtkStatePart : public StatePart {
public:
    VtkStatePart(VtkWriter& writer, const World& w) : writer_(writer), world_(w) {}
    std::string state_group() const override { return "vtk"; }
    void save_state(StateGroup& group) const override;
    void restore_state(const StateGroup& group) override;

private:
    VtkWriter& writer_;
    const World& world_;   ///< restored before the parts: its step index and dt place the frames
};

}  // namespace blockdem
