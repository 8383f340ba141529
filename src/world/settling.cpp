#include "world/settling.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dynamics/central_difference.hpp"
#include "world/model_domain.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// Kinetic energy [J] of body i at t (its velocity at t must be up to date).
double kinetic_energy_j(const Bodies& b, std::size_t i) {
    const Vec2 v = b.velocity_at_t_m_s[i];
    const double omega = b.angular_velocity_at_t_rad_s[i];
    return 0.5 * b.mass_kg[i] * dot(v, v) + 0.5 * b.inertia_kg_m2[i] * omega * omega;
}

LeastSettled least_settled(const World& w) {
    const Bodies& b = w.bodies;
    LeastSettled worst;
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic) continue;
        const double kinetic_j = kinetic_energy_j(b, i);
        // Without gravity the scale is 0: any motion is then "not settled", rest is settled.
        // (The magnitude: the tilt does not change the work of lifting a body by its size.)
        const double scale_j = b.mass_kg[i] * w.settings.gravity_m_s2 * b.bounding_radius_m[i];
        const double ratio = kinetic_j > 0.0 ? kinetic_j / scale_j : 0.0;
        if (ratio > worst.ratio) worst = {ratio, i, kinetic_j};
    }
    return worst;
}

void restart_clock(World& w) {
    w.time_s = 0.0;
    w.step_index = 0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies.kind[i] == BodyKind::dynamic) w.bodies.initial_position_m[i] = w.bodies.position_m[i];
    place_driven_bodies(w, 0.0);
    w.energy = EnergyLedger{};
    initialise_energy(w);
}

// While settling: the table at rest, the tilt held at its start, and (friction = "held")
// every contact sticking. The scenario's values come back when settling ends.
struct HeldWhileSettling {
    TableMotion shaking;
    double tilt_rate_rad_s;
    std::vector<double> mu;
};

HeldWhileSettling hold(World& w, const SettlingSettings& settings) {
    HeldWhileSettling held{w.table_motion, w.settings.tilt_rate_rad_s, {}};
    w.table_motion = TableMotion{};
    w.settings.tilt_rate_rad_s = 0.0;
    for (const ContactParameters& p : w.contact.parameters) held.mu.push_back(p.mu);
    // Dilating joints are not held: they settle under their own friction and dilation. Held,
    // a joint's shear spring takes loads beyond its Coulomb cone with no slip and so no
    // dilation (and it cannot be held with its dilation: against a cap of 1e6 x F_n a joint's
    // return to the cap is all dilation), a state its own law never reaches; released at t = 0,
    // the associative wall with a window then collapsed 13.5 % under the LP, against 1.9 %
    // settled under its own law and 2.0 % as built (docs/limit_analysis.md). The limit
    // theorems make the collapse independent of the start only from states inside the yield
    // surface.
    if (settings.friction == SettlingFriction::held)
        for (ContactParameters& p : w.contact.parameters)
            if (p.tan_dilation == 0.0) p.mu = held_friction_mu;
    return held;
}

void release(World& w, const HeldWhileSettling& held) {
    w.table_motion = held.shaking;
    w.settings.tilt_rate_rad_s = held.tilt_rate_rad_s;
    for (std::size_t k = 0; k < held.mu.size(); ++k) w.contact.parameters[k].mu = held.mu[k];
}

// The largest displacement and rotation of any dynamic body since settling started.
void note_largest_motion(const Bodies& b, const std::vector<Vec2>& start_m, const std::vector<double>& start_rad,
                         SettlingReport& report) {
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic) continue;
        const double moved_m = length(b.position_m[i] - start_m[i]);
        const double turned_rad = std::abs(b.rotation_rad[i] - start_rad[i]);
        if (moved_m > report.largest_move_m || report.largest_move_body.empty()) {
            report.largest_move_m = moved_m;
            report.largest_move_body = b.name[i];
        }
        if (turned_rad > report.largest_turn_rad || report.largest_turn_body.empty()) {
            report.largest_turn_rad = turned_rad;
            report.largest_turn_body = b.name[i];
        }
    }
}

}  // namespace

SettlingWindow::SettlingWindow(const SettlingSettings& settings, double dt_s)
    : kinetic_ratio_(settings.kinetic_ratio),
      // Clamped as a double before the cast (window = 1e300 s).
      steps_per_window_(static_cast<std::int64_t>(std::clamp(std::round(settings.window_s / dt_s), 1.0, 1e18))) {}

void SettlingWindow::close_if_due(std::int64_t n, SettlingReport& report, std::size_t& reported_body) {
    if (n % steps_per_window_ != 0) return;
    report.kinetic_ratio = worst_.ratio;
    report.body_kinetic_j = worst_.kinetic_j;
    reported_body = worst_.body;
    report.settled = worst_.ratio < kinetic_ratio_;
    worst_ = LeastSettled{};
}

void SettlingWindow::report_partial(std::int64_t n, SettlingReport& report, std::size_t& reported_body) const {
    if (report.settled || n >= steps_per_window_) return;
    report.kinetic_ratio = worst_.ratio;
    report.body_kinetic_j = worst_.kinetic_j;
    reported_body = worst_.body;
}

SettlingStopped::SettlingStopped(const SettlingReport& r)
    : std::runtime_error(fmt::format("stopped while the model settled, after {:.4g} s of settling ({} steps): nothing was "
                                     "written; run again to settle and shake",
                                     r.time_s, r.steps)) {}

SettlingReport settle(World& w, const SettlingSettings& settings, const std::atomic<bool>* stop_requested) {
    const HeldWhileSettling held = hold(w, settings);
    update_body_geometry(w);
    const std::vector<Vec2> start_m = w.bodies.position_m;
    const std::vector<double> start_rad = w.bodies.rotation_rad;
    SettlingWindow window(settings, w.dt_s);
    SettlingReport report;
    std::size_t reported_body = 0;
    const std::size_t left_before = w.domain.left.size();
    for (std::int64_t n = 1;; ++n) {
        if (stop_requested && stop_requested->load(std::memory_order_relaxed)) {
            report.stopped = true;
            report.steps = n - 1;
            report.time_s = w.time_s;
            break;
        }
        step_begin(w);
        if (w.domain.left.size() > left_before) {
            // Taken out of the step, it would read as still; the set-up has lost a body.
            const BodyLeftModel& left = w.domain.left[left_before];
            report.left_model = true;
            report.left_time_s = left.time_s;
            report.left_position_m = {left.position_m.x, left.position_m.y};
            report.settled = false;
            report.steps = n;
            report.time_s = w.time_s;
            reported_body = left.body;
            break;
        }
        window.note(least_settled(w));
        step_end(w);
        window.close_if_due(n, report, reported_body);
        if (report.settled || w.time_s >= settings.max_time_s) {
            window.report_partial(n, report, reported_body);
            report.steps = n;
            report.time_s = w.time_s;
            break;
        }
    }
    const Bodies& b = w.bodies;
    if (reported_body < b.size()) {
        report.body = b.name[reported_body];
        report.body_size_m = b.bounding_radius_m[reported_body];
        report.body_moved_m = length(b.position_m[reported_body] - start_m[reported_body]);
        report.body_turned_rad = std::abs(b.rotation_rad[reported_body] - start_rad[reported_body]);
    }
    note_largest_motion(b, start_m, start_rad, report);
    release(w, held);
    restart_clock(w);
    return report;
}

SettlingRecord settling_record(const SettlingReport& r, const SettlingSettings& settings) {
    return {r.time_s,           r.steps,           settings.friction == SettlingFriction::held,
            r.kinetic_ratio,    r.largest_move_m,  r.largest_move_body,
            r.largest_turn_rad, r.largest_turn_body};
}

std::string settling_failure(const SettlingReport& r, const SettlingSettings& settings) {
    if (r.left_model)
        return fmt::format("the assembly did not settle: body '{}' left the model at t = {:.4g} s of settling, at "
                           "({:.4g}) m, so it had nothing to rest on (it moved {:.3g} m and turned {:.3g} rad since "
                           "settling started); support the body or move it",
                           r.body, r.left_time_s, fmt::join(r.left_position_m, ", "), r.body_moved_m,
                           r.body_turned_rad);
    return fmt::format("the assembly did not settle within {:g} s: body '{}' still moves (kinetic energy {:.3g} J = "
                       "{:.3g} x m g L, L = {:.3g} m its size; asked for < {:.3g} over {:g} s); it moved {:.3g} m and "
                       "turned {:.3g} rad since settling started. Raise settling.max_time or settling.kinetic_ratio, "
                       "or support the body",
                       settings.max_time_s, r.body, r.body_kinetic_j, r.kinetic_ratio, r.body_size_m,
                       settings.kinetic_ratio, settings.window_s, r.body_moved_m, r.body_turned_rad);
}

}  // namespace blockdem
