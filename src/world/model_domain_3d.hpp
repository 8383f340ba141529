#pragma once
// The model's extent in 3-D, and the bodies that leave it: world/model_domain.hpp's rule in three
// dimensions. A block that slides off a pier or the table's edge would otherwise fall for the rest
// of the run (kilometres, an energy ledger dominated by one body in free fall); once nothing in
// the model can catch it, it is taken out of the step: frozen where it left, in no candidate pair
// (so in no contact), with no more terms in the energy ledger (its kinetic and gravitational
// energy at that step move to EnergyLedger::removed_j, so the balance still closes).
//
// The extent is [simulation] domain = [[x, y, z], [x, y, z]] when the scenario gives one.
// Otherwise it is derived at t = 0: the bounding box of the fixed bodies, of the driven bodies
// over the whole table motion (their box swept by the range of the table's displacement), and of
// the dynamic bodies at the start, grown on every side by the largest dynamic body's bounding
// diameter, with no top (a body thrown upwards comes back down).
//
// A body has left when its bounding box lies wholly outside the extent. The 3-D broad phase
// boxes every body at every step, so the test is one box comparison a body a step, made where
// the step sums the bodies' energies (world/step_3d.cpp).
#include <cstdint>
#include <optional>
#include <vector>

#include "broad_phase/grid_broad_phase_3d.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

struct World3d;

struct BodyLeftModel3d {
    std::uint32_t body = 0;
    double time_s = 0.0;       ///< [s]
    Vec3 position_m;           ///< [m] centroid when it left
    Vec3 velocity_m_s;         ///< [m/s] at t when it left
};

struct ModelDomain3d {
    bool active = false;        ///< false until init_model_domain_3d
    bool from_scenario = false; ///< [simulation] domain was given
    Aabb3d box_m;               ///< [m] the extent; hi.z is +infinity when derived
    double margin_m = 0.0;      ///< [m] the derived extent's margin (0 when given)
    std::vector<BodyLeftModel3d> left;   ///< in the order they left
    std::vector<std::uint8_t> taken_out; ///< per body: 1 once it left (sized by init_model_domain_3d)
};

/// Sets w.domain from `given`, or derives it (see above) over the table motion until
/// w.duration_s. Throws ModelError naming the body when a given extent does not contain a body
/// at t = 0.
void init_model_domain_3d(World3d& w, const std::optional<Aabb3d>& given);

/// True for a body taken out of the step.
inline bool is_taken_out(const ModelDomain3d& d, std::size_t i) { return !d.taken_out.empty() && d.taken_out[i]; }

/// True when a dynamic body's box (posed this step) lies wholly outside the extent.
bool is_outside(const ModelDomain3d& d, const Aabb3d& box_m);

/// Marks body i as taken out at the world's time and freezes it (velocities zero); the caller
/// books its energy. Called in body order, so `left` has one order at any thread count.
void take_out(World3d& w, std::uint32_t i);

/// Marks the bodies of w.domain.left taken out (a state file's list, on a restart).
void mark_taken_out(World3d& w);

}  // namespace blockdem
