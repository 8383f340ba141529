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

/// The narrow phase for every pair, without forces (the start-up overlap check uses it).
void update_contact_geometry(World& w);

}  // namespace blockdem
