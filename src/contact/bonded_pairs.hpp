#pragma once
// Bonded joints (mortar, intact rock bridges): which contact points start bonded, and how the
// narrow phase keeps a bonded pair's points while the joint opens within what the bond carries.
// The bond itself, its strengths and its breaking, are the joint law's
// (laws/mohr_coulomb_joint.hpp); a point's bond state travels with its history
// (contact/contact_table.hpp).
#include <cstddef>

#include "world/world.hpp"

namespace blockdem {

/// Bonds every pair of bodies of one nonzero bond group that touch at the start (within
/// round-off): their contact points are made and marked intact. Call on a world whose contact
/// table is built (the start overlap check). Returns the number of bonded points.
std::size_t bond_touching_pairs(World& w);

/// The narrow phase of a pair that holds an intact bond: points apart by less than twice the
/// bond's tensile opening (sigma_t / JKN) are kept with a negative overlap, so that the law can
/// pull on them and decide when the bond breaks. Full separating-axis test (no axis cache: the
/// cache is reset, so the pair starts afresh once its bonds are gone).
OpenedPoints update_bonded_pair(World& w, std::size_t p);

}  // namespace blockdem
