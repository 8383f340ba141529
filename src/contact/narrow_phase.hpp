#pragma once
// The narrow phase of one step: for each candidate pair of the broad phase, this step's contact
// points (geometry/polygon_contact.hpp) matched with last step's, so that they keep their shear
// history (contact/contact_table.hpp). Cheap exits first: boxes apart, or still apart along the
// edge that separated the pair last step; a lasting contact then reuses its axis cache.
#include <cstddef>

#include "world/world.hpp"

namespace blockdem {

/// The narrow phase for pair p (contact points, history matched); touches only that pair, so
/// pairs may run in parallel. Returns last step's points that opened (for the energy ledger).
OpenedPoints update_pair_contact(World& w, std::size_t p);

/// update_pair_contact for a world whose material pairs all have per-length stiffness
/// (every_pair_per_length): the same results, with a pair's parameters looked up only when it
/// is bonded (the step's joints-only path: docs/performance.md, "Joints").
OpenedPoints update_joint_pair_contact(World& w, std::size_t p);

/// The contact points of pair p's two parts now (sharp or rounded, as [contact] rounding says),
/// without matching them to last step's: what update_pair_contact computes before the matching,
/// and what bonds are made on at the start (contact/bonded_pairs.cpp). reference: last step's
/// reference edge; cache: the pair's axis cache, or null with sharp corners (none kept).
bool collide_parts(const World& w, const PairContact& pair, std::uint32_t reference, ContactManifold& manifold,
                   AxisCache* cache, double gap_m);

/// Corners of one pair are at least a face apart, so 5% of the smaller part is "same place" [m].
double part_match_distance_m(const Bodies& b, const PairContact& pair);

/// The narrow phase for every pair, without forces (the start-up overlap check uses it).
void update_contact_geometry(World& w);

}  // namespace blockdem
