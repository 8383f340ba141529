#include "world/settling_3d.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/rigid_body_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

// [m] the body's size L: its largest centroid-to-corner distance.
double size_m(const RigidBody3d& b) {
    double l = 0.0;
    for (const Vec3& v : b.shape.vertices_m) l = std::max(l, length(v));
    return l;
}

// The least settled dynamic body now (world/settling.hpp).
LeastSettled least_settled(const World3d& w, const std::vector<double>& sizes_m) {
    LeastSettled worst;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        const RigidBody3d& b = w.bodies[i];
        const double kinetic_j = kinetic_energy(b);
        // Without gravity the scale is 0: any motion is then "not settled", rest is settled.
        const double ratio = kinetic_j > 0.0 ? kinetic_j / (b.mass_kg * w.gravity_m_s2 * sizes_m[i]) : 0.0;
        if (ratio > worst.ratio) worst = {ratio, i, kinetic_j};
    }
    return worst;
}

// [rad] the angle body i turned since settling started.
double turned_rad(const World3d& w, const std::vector<Quaternion>& start, std::size_t i) {
    const Quaternion turn = normalized(w.bodies[i].orientation * conjugate(start[i]));
    return 2.0 * std::atan2(std::sqrt(turn.x * turn.x + turn.y * turn.y + turn.z * turn.z), std::abs(turn.w));
}

void note_motion(const World3d& w, const std::vector<Vec3>& start_m, const std::vector<Quaternion>& start_q,
                 std::size_t reported, SettlingReport& report) {
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        const double moved_m = length(w.bodies[i].position_m - start_m[i]);
        const double turned = turned_rad(w, start_q, i);
        if (i == reported) {
            report.body = w.bodies[i].name;
            report.body_size_m = size_m(w.bodies[i]);
            report.body_moved_m = moved_m;
            report.body_turned_rad = turned;
        }
        if (moved_m > report.largest_move_m || report.largest_move_body.empty()) {
            report.largest_move_m = moved_m;
            report.largest_move_body = w.bodies[i].name;
        }
        if (turned > report.largest_turn_rad || report.largest_turn_body.empty()) {
            report.largest_turn_rad = turned;
            report.largest_turn_body = w.bodies[i].name;
        }
    }
}

}  // namespace

SettlingReport settle_3d(World3d& w, const SettlingSettings& settings, const std::atomic<bool>* stop_requested) {
    const TableMotion3d shaking = w.table;
    const double mu = w.contact.mu;
    w.table = TableMotion3d{};
    if (settings.friction == SettlingFriction::held) w.contact.mu = held_friction_mu;
    std::vector<Vec3> start_m;
    std::vector<Quaternion> start_q;
    std::vector<double> sizes_m;  // [m] each body's L, taken once
    for (const RigidBody3d& b : w.bodies) {
        start_m.push_back(b.position_m);
        start_q.push_back(b.orientation);
        sizes_m.push_back(size_m(b));
    }
    SettlingWindow window(settings, w.dt_s);
    SettlingReport report;
    std::size_t reported = w.bodies.size();
    for (std::int64_t n = 1;; ++n) {
        if (stop_requested && stop_requested->load(std::memory_order_relaxed)) {
            report.stopped = true;
            report.steps = n - 1;
            report.time_s = w.time_s;
            break;
        }
        step_begin(w);
        if (!w.domain.left.empty()) {
            // Taken out of the step, it would read as still; the set-up has lost a body.
            const BodyLeftModel3d& left = w.domain.left.front();
            report.left_model = true;
            report.left_time_s = left.time_s;
            report.left_position_m = {left.position_m.x, left.position_m.y, left.position_m.z};
            report.steps = n;
            report.time_s = w.time_s;
            reported = left.body;
            break;
        }
        window.note(least_settled(w, sizes_m));
        step_end(w);
        window.close_if_due(n, report, reported);
        if (report.settled || w.time_s >= settings.max_time_s) {
            window.report_partial(n, report, reported);
            report.steps = n;
            report.time_s = w.time_s;
            break;
        }
    }
    note_motion(w, start_m, start_q, reported, report);
    w.table = shaking;
    w.contact.mu = mu;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.kinds[i] == BodyKind3d::dynamic) set_initial_velocity(w.bodies[i], {}, {});
    w.time_s = 0.0;
    w.steps = 0;
    w.ledger = EnergyLedger{};
    return report;
}

}  // namespace blockdem
