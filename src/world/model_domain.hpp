#pragma once
// The model's extent, and the bodies that leave it. A block that falls off the edge of the table
// would otherwise fall for the rest of the run (hundreds of metres, a growing broad-phase grid,
// an energy ledger dominated by one body in free fall); once nothing in the model can catch it,
// it is taken out of the step: frozen where it left, in no candidate pair (so in no contact),
// and with no more terms in the energy ledger (its kinetic and gravitational energy at that
// moment move to EnergyLedger::removed_j, so the balance still closes).
//
// The extent is [simulation] domain when the scenario gives one. Otherwise it is derived at
// t = 0: the bounding box of the fixed bodies, of the driven bodies over the whole table motion
// (their box swept by the range of the table's displacement), and of the dynamic bodies at the
// start, grown on every side by a margin of the largest dynamic body's bounding diameter, with
// no top (a body thrown upwards comes back down). The margin is one body size because a body can
// rest on another that overhangs a support; a box a whole body size beyond every support and
// every start position is clear of anything that could hold it.
//
// A body has left when its bounding box lies wholly outside the extent. The check runs at each
// broad-phase rebuild (step.cpp, rebuild_candidate_pairs): a body cannot move more than half
// the broad-phase margin without causing one, so a leaver is caught within that distance, and
// a run in which nothing leaves pays one box test per body per rebuild.
#include <cstdint>
#include <vector>

#include "broad_phase/grid_broad_phase.hpp"

namespace blockdem {

struct World;
struct Bodies;

struct BodyLeftModel {
    std::uint32_t body = 0;
    double time_s = 0.0;       ///< [s]
    Vec2 position_m;           ///< [m] centroid when it left
    Vec2 velocity_m_s;         ///< [m/s] when it left
};

struct ModelDomain {
    bool active = false;        ///< false until init_model_domain (while the world is built)
    bool from_scenario = false; ///< [simulation] domain was given
    Aabb box_m;                 ///< [m] the extent; hi.y is +infinity when derived
    double margin_m = 0.0;      ///< [m] the derived extent's margin (0 when given)
    std::vector<BodyLeftModel> left;  ///< in the order they left
};

/// Sets w.domain from w.settings.domain, or derives it (see above); needs the bodies' boxes at
/// t = 0. Throws ModelError naming the body when a given extent does not contain a body.
void init_model_domain(World& w);

/// True for a dynamic body that has been taken out of the step.
bool is_taken_out(const Bodies& b, std::size_t i);

/// Takes out the dynamic bodies whose box lies outside the extent, and removes every candidate
/// pair of a taken-out body (call after the broad phase, before the pairs are merged into the
/// contact table). Returns how many bodies left now.
std::size_t take_out_bodies_outside_domain(World& w);

}  // namespace blockdem
