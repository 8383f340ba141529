#pragma once
// The settling stage: bodies laid exactly touching (hand-written [[bodies]], bricks of a
// generated wall, blocks cut from a rock mass) are not yet in equilibrium: their contacts carry
// no load. Before the shaking starts the model is stepped under gravity with the table at rest
// until it is still, and then the clock is set back to zero, keeping the contacts and their
// shear history.
//
// Criterion, body by body: every dynamic body's kinetic energy stays below kinetic_ratio times
// m g L, with m its mass and L its size (its largest centroid-to-corner distance), over a whole
// window of window_s. The scale m g L is the work of lifting the body by its own size: it cannot
// vanish or change sign as the body moves (a potential energy measured from a datum can: a body
// falling below the datum made the old ratio meaningless), and one body still moving in a large,
// quiet assembly is not averaged away. A window, not one sample: an oscillating contact passes
// through zero kinetic energy twice a period.
//
// Friction while settling (SettlingSettings::friction): "held" (the default) raises every
// contact's mu to held_friction_mu, so that no contact slides: each is loaded in place, its shear
// spring taking whatever the weight asks. At t = 0 the scenario's mu applies again, so that a
// contact whose shear exceeds mu N slides from the first step: a block on a slope steeper than
// its friction angle starts with its contacts loaded, not by falling onto the slope, and a block
// on a gentler slope starts in equilibrium, with no release transient that the rigid-plastic
// reference lacks. Joints that dilate (tan_dilation > 0) are not held: they settle under their
// own law (settling.cpp, hold: why). "actual" keeps mu, so bodies may slide into place while settling (and a body
// that cannot stand does not settle). The tilt does not grow while settling (tilt_rate applies
// from t = 0).
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "world/world.hpp"

namespace blockdem {

struct SettlingReport {
    bool settled = false;            ///< the criterion was met before max_time_s
    bool stopped = false;            ///< a stop request (Ctrl-C, SIGTERM) ended it first
    double time_s = 0.0;             ///< [s] of simulated settling
    std::int64_t steps = 0;
    double kinetic_ratio = 0.0;      ///< [-] largest kinetic energy / (m g L) of any body over the last window
    // The least settled body: the one that set kinetic_ratio.
    std::string body;                ///< its name
    double body_kinetic_j = 0.0;     ///< [J] its kinetic energy then
    double body_size_m = 0.0;        ///< [m] its L
    double body_moved_m = 0.0;       ///< [m] how far its centroid moved from where settling started, at the end
    double body_turned_rad = 0.0;    ///< [rad] how far it turned, at the end
    // Over every dynamic body, at the end: how much the settling moved the model.
    double largest_move_m = 0.0;     ///< [m] the largest centroid displacement
    std::string largest_move_body;   ///< which body
    double largest_turn_rad = 0.0;   ///< [rad] the largest |rotation|
    std::string largest_turn_body;   ///< which body
    /// A body that fell out of the model's extent while settling (world/model_domain.hpp): the
    /// set-up lost it before any shaking, so settling failed; body names it.
    bool left_model = false;
    double left_time_s = 0.0;        ///< [s] of settling when it left
    std::vector<double> left_position_m;  ///< [m] where: (x, y) in 2-D, (x, y, z) in 3-D
};

/// The least settled dynamic body at a step: the largest kinetic energy / (m g L).
struct LeastSettled {
    double ratio = 0.0;       ///< [-]
    std::size_t body = 0;
    double kinetic_j = 0.0;   ///< [J]
};

/// The criterion's window, in both dimensions: fed the least settled body at every step, it
/// judges each whole window of window_s.
class SettlingWindow {
public:
    SettlingWindow(const SettlingSettings& settings, double dt_s);
    void note(const LeastSettled& now) {
        if (now.ratio >= worst_.ratio) worst_ = now;
    }
    /// After step n (from 1): at a window's end, its least settled body and whether the window
    /// met the criterion go into report and reported_body, and the next window starts.
    void close_if_due(std::int64_t n, SettlingReport& report, std::size_t& reported_body);
    /// Settling cut short (max_time) after n steps, before its first whole window: the least
    /// settled body so far.
    void report_partial(std::int64_t n, SettlingReport& report, std::size_t& reported_body) const;

private:
    double kinetic_ratio_;
    std::int64_t steps_per_window_;
    LeastSettled worst_;
};

/// A stop request (Ctrl-C, SIGTERM) that came while the model settled, before anything was written.
/// Its message says how far settling got and that nothing was written.
class SettlingStopped : public std::runtime_error {
public:
    explicit SettlingStopped(const SettlingReport& stopped);
};

/// Settles the world in place (table at rest), then restarts the clock at t = 0: time, step
/// count and energy ledger are reset and the settled positions become the initial positions.
/// A stop request (stop_requested set, checked between steps) ends it with report.stopped.
SettlingReport settle(World& w, const SettlingSettings& settings, const std::atomic<bool>* stop_requested = nullptr);

/// What the summary and check report of a settling stage.
SettlingRecord settling_record(const SettlingReport& report, const SettlingSettings& settings);

/// The message for a settling that failed: the criterion, and which body did not settle.
std::string settling_failure(const SettlingReport& report, const SettlingSettings& settings);

}  // namespace blockdem
