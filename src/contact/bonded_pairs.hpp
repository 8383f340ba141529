#pragma once
// Bonded joints (mortar, intact rock bridges): which contact points start bonded, and how the
// narrow phase keeps a bonded pair's points while the joint opens within what the bond carries.
// The bond itself, its strengths and its breaking, are the joint law's
// (laws/mohr_coulomb_joint.hpp); a point's bond state travels with its history
// (contact/contact_table.hpp).
#include <algorithm>
#include <cstddef>

#include "laws/mohr_coulomb_joint.hpp"
#include "world/world.hpp"

namespace blockdem {

/// Bonds every pair of bodies of one nonzero bond group that touch at the start (within
/// round-off): their contact points are made and marked intact. Call on a world whose contact
/// table is built (the start overlap check). Returns the number of bonded points.
std::size_t bond_touching_pairs(World& w);

/// How far the points of a pair that holds an intact bond may open and still be kept, with a
/// negative overlap, by the narrow phase [m]: twice the bond's tensile opening sigma_t / JKN
/// (so that the law, not the geometry, decides when the bond breaks), plus round-off.
double bonded_gap_m(const World& w, const PairContact& pair);

/// What "touching" means at the start [m]: apart by no more than round-off of the body size
/// (the start overlap check allows as much the other way).
inline double touching_gap_m(const Bodies& b, const PairContact& pair) {
    return 1e-9 * std::min(b.bounding_radius_m[pair.a], b.bounding_radius_m[pair.b]);
}

/// bonded_gap_m with the pair's contact parameters already looked up (inline: the narrow phase
/// asks it for every bonded pair at every step).
inline double bonded_gap_m(const Bodies& b, const PairContact& pair, const ContactParameters& params) {
    return 2.0 * bond_opening_m(params) + touching_gap_m(b, pair);
}

}  // namespace blockdem
