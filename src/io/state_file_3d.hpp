#pragma once
// The state of a 3-D run in a state file (io/state_file.hpp, attribute dimension = 3), taken
// between two steps (after step_end, before the next step_begin: world/step_3d.hpp), where
// nothing is half-computed. What the next step reads and the scenario does not give:
//   /bodies3d   per body: centroid, orientation (unit quaternion), velocity and angular momentum
//               at t - dt/2, the body-frame angular velocity of the last step, the velocities at
//               t (output and the kinetic energy), and name, kind and vertex count, to
//               recognise the scenario's bodies;
//   /contacts3d the contact table, sorted by key: each point's feature key (body a, body b,
//               feature of a, feature of b), geometry, the normal dashpot force and the shear
//               spring and dashpot vectors it carries to the next step (the history);
//   /energy     the ledger (the 2-D group);
//   /stability3d the live stable step seen so far (world/run_checks_3d.hpp);
//   /external_loads3d a caller's loads and held velocities, while there are any
//               (io/external_loads_state.hpp);
// and the root's time_s and step_index. Vectors are n x 3 arrays and quaternions n x 4 (w, x, y,
// z), every dataset with its unit in its name. The table motion is a function of time, so it has
// no state; the broad phase is rebuilt from the positions at every step.
// The run's parts beside the world (the response monitor, the VTK frame list) are StateParts
// below, as in 2-D (io/run_state_parts.hpp).
#include <filesystem>
#include <optional>

#include "io/state_file.hpp"
#include "io/vtk_3d_writer.hpp"
#include "world/response_monitor_3d.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// Writes w's groups into a state file's root (write_state_file's write_world).
void write_world_3d(StateGroup& root, const World3d& w);

/// Puts w, built from the scenario the state was saved with and with the same dt, in the state
/// of file: clock, bodies, contacts, ledger, stability watch and a caller's external loads. Throws InputError naming the file
/// and the scenario when the state is not a 3-D one, or its bodies, dt or time do not fit w.
void restore_world_3d(const StateFile& file, World3d& w, const std::filesystem::path& scenario);

/// Starts a new run from a saved state (a settled assembly: [simulation] initial_state, as in
/// 2-D): the bodies' poses, their velocities at the state's time and the contacts with their
/// history come from the file; the clock restarts at t = 0 with those velocities as the initial
/// ones, and the ledger starts again. The time step may differ from the state's. A caller's loads
/// in the state are not taken (the new run's caller sets its own). Refused as
/// restore_world_3d refuses a state of another scenario.
void start_from_state_3d(const StateFile& file, World3d& w, const std::filesystem::path& scenario);

/// /monitor3d: each body's start pose, overturning angle and peaks (summary.json).
class Monitor3dStatePart : public StatePart {
public:
    explicit Monitor3dStatePart(ResponseMonitor3d& monitor) : monitor_(monitor) {}
    std::string state_group() const override { return "monitor3d"; }
    void save_state(StateGroup& group) const override;
    void restore_state(const StateGroup& group) override;

private:
    ResponseMonitor3d& monitor_;
};

/// /settling: what settling did before t = 0 (io/state_file.hpp's record), so that a restarted
/// run's summary reports it.
class Settling3dStatePart : public StatePart {
public:
    explicit Settling3dStatePart(std::optional<SettlingRecord>& record) : record_(record) {}
    std::string state_group() const override { return "settling"; }
    void save_state(StateGroup& group) const override { write_settling(group, *record_); }
    void restore_state(const StateGroup& group) override { record_ = read_settling(group); }

private:
    std::optional<SettlingRecord>& record_;
};

/// /vtk3d: the frames written so far. On restore the frames at times before the state's are kept
/// (an interrupted run wrote one more, at the time it stopped); the rest are written again.
class Vtk3dStatePart : public StatePart {
public:
    Vtk3dStatePart(Vtk3dWriter& writer, const World3d& w) : writer_(writer), world_(w) {}
    std::string state_group() const override { return "vtk3d"; }
    void save_state(StateGroup& group) const override;
    void restore_state(const StateGroup& group) override;

private:
    Vtk3dWriter& writer_;
    const World3d& world_;   ///< restored before the parts: its time places the frames
};

}  // namespace blockdem
