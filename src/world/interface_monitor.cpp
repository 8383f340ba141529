#include "world/interface_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "world/sensor.hpp"

namespace blockdem {
namespace {

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

struct Edge {
    Vec2 from_m, to_m;   ///< [m]
    Vec2 outward;
};

// The body's edge whose outward normal is most nearly along direction; of a concave outline's
// edges facing alike (a Pi-shaped block's leg soles and the underside of its arch), the one
// farthest out along direction.
Edge facing_edge(const Bodies& b, std::uint32_t i, Vec2 direction) {
    const std::uint32_t first = b.vertex_begin[i];
    const std::uint32_t count = b.vertex_count[i];
    const bool concave = b.part_count[i] > 1;
    std::uint32_t best = 0;
    for (std::uint32_t k = 1; k < count; ++k) {
        const double facing = dot(b.world_normals[first + k], direction);
        const double best_facing = dot(b.world_normals[first + best], direction);
        if (facing > best_facing ||
            (concave && facing == best_facing &&
             dot(b.world_vertices_m[first + k], direction) > dot(b.world_vertices_m[first + best], direction)))
            best = k;
    }
    return {b.world_vertices_m[first + best], b.world_vertices_m[first + (best + 1) % count], b.world_normals[first + best]};
}

}  // namespace

double interface_opening_m(const Bodies& bodies, std::uint32_t a, std::uint32_t b, Vec2 n) {
    const Edge on_a = facing_edge(bodies, a, n);
    const Edge on_b = facing_edge(bodies, b, -n);
    const bool b_shorter = length(on_b.to_m - on_b.from_m) <= length(on_a.to_m - on_a.from_m) * (1.0 + 1e-9);
    const Edge& line = b_shorter ? on_a : on_b;
    const Edge& corners = b_shorter ? on_b : on_a;
    const double gap = std::max(dot(corners.from_m - line.from_m, line.outward), dot(corners.to_m - line.from_m, line.outward));
    return std::max(0.0, gap);
}

InterfaceMonitor::InterfaceMonitor(const InterfaceSelection& selection) : all_(selection.all) {
    if (all_) return;
    for (const auto& [a, b] : selection.named) {
        index_.emplace(pair_key(a, b), states_.size());
        InterfaceState s;
        s.body_a = a;
        s.body_b = b;
        states_.push_back(s);
    }
}

std::size_t InterfaceMonitor::find_or_add(const World& w, const PairContact& pair) {
    const auto found = index_.find(pair_key(pair.a, pair.b));
    if (found != index_.end()) return found->second;
    if (!all_) return states_.size();
    // Discovered now: body_a is the lower body (the normal leaves it upwards), or for a
    // vertical interface the one on the left. Fixed from here on, so signs stay consistent.
    InterfaceState s;
    const bool flip = pair.normal.y < -1e-9 || (std::abs(pair.normal.y) <= 1e-9 && pair.normal.x < 0.0);
    s.body_a = flip ? pair.b : pair.a;
    s.body_b = flip ? pair.a : pair.b;
    s.first_touch_time_s = w.time_s;
    index_.emplace(pair_key(pair.a, pair.b), states_.size());
    states_.push_back(s);
    return states_.size() - 1;
}

void InterfaceMonitor::observe(const World& w) {
    const Bodies& b = w.bodies;
    // A concave body may touch another through several of its parts: each part pair is an entry
    // of the table, and the interface of the two bodies sums them (points, forces, their centre).
    centre_sum_m_.assign(states_.size(), Vec2{});
    shear_ccw_sum_n_.assign(states_.size(), 0.0);
    normal_now_.assign(states_.size(), Vec2{});
    for (InterfaceState& s : states_) {
        s.touching = false;
        s.points = s.bonded_points = s.broken_points = 0;
        s.normal_force_n = s.shear_force_n = s.opening_m = 0.0;
    }
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const PairContact& pair = w.contacts[i];
        if (pair.count == 0) continue;
        const std::size_t k = find_or_add(w, pair);
        if (k == states_.size()) continue;
        if (centre_sum_m_.size() < states_.size()) {  // (an interface discovered now)
            centre_sum_m_.resize(states_.size());
            shear_ccw_sum_n_.resize(states_.size(), 0.0);
            normal_now_.resize(states_.size());
        }
        InterfaceState& s = states_[k];
        // Both N and the shear along s = -(the contact tangent) come out the same whichever
        // body of the pair is body_a (interface_monitor.hpp).
        // (The pair's own points, then its sub-contacts' interior points: contact/sub_contacts.hpp.)
        const std::uint32_t interior = i < w.sub_contacts.size() ? w.sub_contacts[i].count : 0;
        for (std::uint32_t p = 0; p < pair.count + interior; ++p) {
            const ContactPoint& point = p < pair.count ? pair.points[p] : w.sub_contacts[i].points[p - pair.count];
            s.normal_force_n += point.normal_force_n;
            shear_ccw_sum_n_[k] += point.shear_force_n;
            centre_sum_m_[k] += point.point_m;
            s.bonded_points += point.bond == BondState::intact ? 1 : 0;
            s.broken_points += is_broken(point.bond) ? 1 : 0;
        }
        if (s.broken_points > 0 && s.first_break_time_s < 0.0) s.first_break_time_s = w.time_s;
        s.points += pair.count + interior;
        // (The first part pair's normal: the parts of one interface face the same way.)
        if (!s.touching) normal_now_[k] = s.body_a != pair.a ? -pair.normal : pair.normal;
        s.touching = true;
    }
    for (std::size_t k = 0; k < states_.size(); ++k) {
        InterfaceState& s = states_[k];
        if (!s.touching) continue;
        const Vec2 n = normal_now_[k];
        const Vec2 tangent{n.y, -n.x};   // n turned clockwise
        const Vec2 centre_m = (1.0 / s.points) * centre_sum_m_[k];
        s.shear_force_n = -shear_ccw_sum_n_[k];
        if (s.first_touch_time_s < 0.0) s.first_touch_time_s = w.time_s;
        auto velocity_at = [&](std::uint32_t i) {
            const Vec2 r = centre_m - b.position_m[i];
            return b.velocity_at_t_m_s[i] + cross(b.angular_velocity_at_t_rad_s[i], r);
        };
        s.slip_m += dot(velocity_at(s.body_b) - velocity_at(s.body_a), tangent) * w.dt_s;
        s.peak_abs_slip_m = std::max(s.peak_abs_slip_m, std::abs(s.slip_m));
        s.opening_m = interface_opening_m(b, s.body_a, s.body_b, n);
        s.peak_opening_m = std::max(s.peak_opening_m, s.opening_m);
    }
}

void InterfaceMonitor::restore(std::vector<InterfaceState> states) {
    if (!all_) {
        bool same = states.size() == states_.size();
        for (std::size_t k = 0; same && k < states.size(); ++k)
            same = states[k].body_a == states_[k].body_a && states[k].body_b == states_[k].body_b;
        if (!same) throw std::invalid_argument("the saved interfaces are not the pairs named in [output] interfaces");
    }
    states_ = std::move(states);
    index_.clear();
    for (std::size_t k = 0; k < states_.size(); ++k) index_.emplace(pair_key(states_[k].body_a, states_[k].body_b), k);
}

}  // namespace blockdem
