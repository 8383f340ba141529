#pragma once
// Interfaces: what happens between two bodies in contact, as a joint, measured at every step.
//
// An interface is a pair of bodies (body_a, body_b) with at least one contact point at some
// time. Its frame: the normal n is the contact normal turned to point from body_a into body_b,
// the tangent s is n turned clockwise (so that for body_b resting on body_a, n = +y and
// s = +x). At each step, while the pair touches:
//   normal_force_n  N = sum of the points' normal forces on body_b along n (compression > 0);
//   shear_force_n   S = sum of the points' shear forces on body_b along s;
//   points          the number of active contact points (0, 1 or 2 for convex bodies; a
//                   concave body touching through several of its parts sums them all);
//   opening_m       the gap at the far corner: the two facing edges are, on each body, the edge
//                   whose outward normal points most nearly towards the other body; the
//                   opening is the largest distance of the two end corners of the shorter edge
//                   (body_b's when equal) from the line of the longer one, measured along the
//                   longer edge's outward normal, and 0 when both corners touch (a rocking block
//                   lifts one corner: the opening is that corner's height);
//   bonded_points, broken_points: the active points whose bond is intact, and whose bond has
//                   broken (laws/mohr_coulomb_joint.hpp); first_break_time_s: when the first
//                   broken point was seen (a broken point that opens is dropped with its
//                   history, so the counts are of the points in contact now);
//   slip_m          accumulated slip: the integral over the time in contact of body_b's velocity
//                   relative to body_a at the centre of the active points, along s. It holds the
//                   elastic shear deformation of the contacts as well as sliding; it stops
//                   growing while the pair is apart (in flight).
// Which pairs: every pair that touches (discovered as it first touches; body_a is then the body
// the normal leaves upwards, the lower body, or the one on the left of a vertical interface),
// or only the pairs named in [output] interfaces (in the order given; body_a is the first name).
//
// The whole state of an interface is one plain struct (InterfaceState), so that a state file can
// save and restore it; the monitor's lookup index is rebuilt from the list.
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "world/world.hpp"

namespace blockdem {

/// One interface's state now and what it has seen.
struct InterfaceState {
    std::uint32_t body_a = 0;         ///< the body the normal leaves
    std::uint32_t body_b = 0;
    bool touching = false;            ///< at least one contact point now
    std::uint32_t points = 0;         ///< active contact points now
    double normal_force_n = 0.0;      ///< [N] now, compression > 0
    double shear_force_n = 0.0;       ///< [N] now, on body_b along s
    double opening_m = 0.0;           ///< [m] now (0 while apart: not measured)
    double slip_m = 0.0;              ///< [m] accumulated along s
    double peak_abs_slip_m = 0.0;     ///< [m]
    double peak_opening_m = 0.0;      ///< [m]
    double first_touch_time_s = -1.0; ///< [s] -1: never touched
    std::uint32_t bonded_points = 0;  ///< points whose bond is intact now
    std::uint32_t broken_points = 0;  ///< points whose bond has broken, among the active ones now
    double first_break_time_s = -1.0; ///< [s] when a broken bond was first seen here; -1: never
};

/// Which interfaces a run follows.
struct InterfaceSelection {
    bool all = false;                                               ///< every pair that touches
    std::vector<std::pair<std::uint32_t, std::uint32_t>> named;     ///< (body_a, body_b) when not all
    bool any() const { return all || !named.empty(); }
};

class InterfaceMonitor {
public:
    explicit InterfaceMonitor(const InterfaceSelection& selection);
    /// Reads the state at t; call once per step.
    void observe(const World& w);
    const std::vector<InterfaceState>& interfaces() const { return states_; }
    /// Whether every touching pair is followed (discovered as they touch).
    bool follows_all() const { return all_; }
    /// Continues from saved interfaces() (a state file); named pairs must be this monitor's,
    /// in order (std::invalid_argument otherwise).
    void restore(std::vector<InterfaceState> states);

private:
    std::size_t find_or_add(const World& w, const PairContact& pair);

    bool all_ = false;
    std::vector<InterfaceState> states_;
    std::unordered_map<std::uint64_t, std::size_t> index_;   ///< (min id, max id) -> states_ entry
    // Scratch of observe(), per interface: the sums over its part pairs this step.
    std::vector<Vec2> centre_sum_m_;      ///< [m] sum of the active points
    std::vector<double> shear_ccw_sum_n_; ///< [N] sum of the points' shear forces along the contact tangent
    std::vector<Vec2> normal_now_;        ///< from body_a into body_b
};

/// The opening of a touching pair (see above) with normal n from body a into body b.
double interface_opening_m(const Bodies& bodies, std::uint32_t a, std::uint32_t b, Vec2 n);

}  // namespace blockdem
