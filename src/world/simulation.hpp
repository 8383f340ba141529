#pragma once
// The run loop: steps a world from t = 0 to the end, calls the monitor at every step and the
// recorders at every output time, and reports progress through a callback (the library never
// prints). The state handed to observers is the complete state at t (see step.hpp). A stop
// request (a flag the app sets from SIGINT/SIGTERM) is honoured between two steps: the state
// reached is recorded and every recorder finished, so the files end at a whole output row.
// Save points (state files, io/state_file.hpp) fall between two steps, where the state is whole
// (world/world_state.hpp); a run restored from one goes on from its step index.
//
// The loop is written once for both dimensions: RunLoopOf<W> for W = World (2-D, step.hpp) and
// W = World3d (3-D, step_3d.hpp). What it needs of a world is its clock (step_index, time,
// duration and output interval, the overloads below) and its two half steps, step_begin and
// step_end; the 2-D names (Recorder, RunOptions, RunLoop) are the World instances.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "world/world.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// Something that reads the world at output times (writers).
template <class W>
class RecorderOf {
public:
    virtual ~RecorderOf() = default;
    virtual void record(const W& w) = 0;
    /// Called once after the last record, and also when the run stops on an error or a stop
    /// request. Throws when the output cannot be completed (a write fails).
    virtual void finish(const W&) {}
};
using Recorder = RecorderOf<World>;
using Recorder3d = RecorderOf<World3d>;

struct RunProgress {
    double time_s = 0.0;         ///< [s] simulated
    double end_time_s = 0.0;     ///< [s]
    std::int64_t steps = 0;
    double wall_s = 0.0;         ///< [s] elapsed
};

/// Why the run offers its state at a save point.
enum class SaveReason { at_time, every, stopped };

/// When to offer the state (RunOptions::on_save_point): before the step of each listed index,
/// every `every_steps` steps (0: never), and on a stop request.
struct SavePoints {
    std::vector<std::int64_t> steps;   ///< step indices, any order
    std::int64_t every_steps = 0;
};

template <class W>
struct RunOptionsOf {
    std::vector<RecorderOf<W>*> recorders;
    /// Every step, on the complete state at t, before the records (monitors and the run's
    /// guards, which throw SimulationError to stop the run).
    std::function<void(const W&)> on_step;
    std::function<void(const RunProgress&)> on_progress;    ///< about once per second of wall time
    const std::atomic<bool>* stop_requested = nullptr;      ///< checked between steps; may be null
    SavePoints save_points;
    /// Called with the whole state between two steps (see SavePoints). On a stop request it is
    /// the state after the step whose time was recorded last, so a run restored from it goes on
    /// with the next step. Not called again at the step a restored run starts from.
    std::function<void(const W&, SaveReason)> on_save_point;
};
using RunOptions = RunOptionsOf<World>;
using RunOptions3d = RunOptionsOf<World3d>;

enum class RunEnd { completed, stopped };

/// A world's clock as the loop reads it.
inline std::int64_t step_index(const World& w) { return w.step_index; }
inline std::int64_t step_index(const World3d& w) { return w.steps; }
inline double end_time_s(const World& w) { return w.settings.duration_s; }
inline double end_time_s(const World3d& w) { return w.duration_s; }
inline double output_interval_s(const World& w) { return w.settings.output_interval_s; }
inline double output_interval_s(const World3d& w) { return w.output_interval_s; }

/// Number of steps to cover the duration, and steps between outputs.
template <class W>
std::int64_t total_steps(const W& w);
template <class W>
std::int64_t steps_per_output(const W& w);
/// Output rows (history.csv, energy.csv) a run has written before the step of index n.
template <class W>
std::int64_t output_rows_before(const W& w, std::int64_t n);
/// The step index whose state is the time t_s (the nearest step, within the run).
template <class W>
std::int64_t step_at_time(const W& w, double t_s);

/// The run loop cut into pieces a caller can take one at a time (the Python module steps a run
/// n steps at a time and reads the world in between). It pauses where the state at t is
/// complete (after step_begin and the records of t, world/step.hpp), so that positions,
/// velocities and accelerations read between two calls are all at w.time_s.
template <class W>
class RunLoopOf {
public:
    /// The loop starts at w's step index (0, or where a restored state left off). Nothing runs yet.
    RunLoopOf(W& w, RunOptionsOf<W> options);
    /// Takes up to `steps` steps (0: only completes the state at the start), fewer at the end of
    /// the run or on a stop request. Returns the steps taken. An exception from the step or a
    /// recorder finishes every recorder (the first exception propagates) and fails the loop:
    /// advancing it again throws std::logic_error.
    std::int64_t advance(std::int64_t steps);
    /// Ends the run at the time reached, as a stop request does (RunEnd::stopped): the state at
    /// that time is the last record, and the state to go on from is offered as a save point.
    void stop();
    /// Finishes every recorder, once (the first exception propagates).
    void finish();
    bool ended() const { return ended_; }
    bool failed() const { return failed_; }
    RunEnd end() const { return end_; }

private:
    void begin_step();
    void end_step();
    void fail_and_rethrow();

    W& w_;
    RunOptionsOf<W> options_;
    std::int64_t steps_;         ///< total_steps(w)
    std::int64_t every_;         ///< steps_per_output(w)
    std::int64_t first_;         ///< the step index the loop started from
    bool begun_ = false;         ///< the state at w.step_index is complete (begin_step ran)
    bool output_now_ = false;    ///< that state was recorded
    bool ended_ = false;
    bool failed_ = false;
    bool finished_ = false;
    RunEnd end_ = RunEnd::completed;
    std::chrono::steady_clock::time_point started_;
    std::chrono::steady_clock::time_point last_report_;
};
using RunLoop = RunLoopOf<World>;
using RunLoop3d = RunLoopOf<World3d>;

/// Runs from w.step_index (0, or where a restored state left off) to the end, or until
/// *options.stop_requested turns true (RunEnd::stopped, after the current step, with a last
/// record at the time reached). Recorders are finished even when an
/// exception stops the run; the first exception is the one that propagates.
RunEnd run_simulation(World& w, const RunOptions& options);

}  // namespace blockdem
