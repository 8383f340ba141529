#include "contact/bonded_pairs.hpp"

#include <algorithm>

#include "contact/contact_table.hpp"
#include "contact/narrow_phase.hpp"
#include "contact/sub_contacts.hpp"
#include "geometry/polygon_contact.hpp"
#include "laws/mohr_coulomb_joint.hpp"

namespace blockdem {

std::size_t bond_touching_pairs(World& w) {
    const Bodies& b = w.bodies;
    std::size_t bonded = 0;
    for (std::size_t p = 0; p < w.contacts.size(); ++p) {
        PairContact& pair = w.contacts[p];
        const std::uint32_t group = b.bond_group[pair.a];
        if (group == 0 || b.bond_group[pair.b] != group) continue;
        if (b.is_static[pair.a] && b.is_static[pair.b]) continue;  // nothing moves between them
        // (The scenario reader allows bonds only with per-length stiffness.)
        if (w.contact.at(b.material[pair.a], b.material[pair.b]).stiffness != StiffnessBasis::per_length) continue;
        // The points bonded are those the narrow phase will keep: those of the pair's two convex
        // parts (a concave body bonds along the parts that touch: an L on a block along one leg),
        // and with rounded corners those of the rounded outlines (the ends of the straight part
        // of the joint).
        ContactManifold manifold;
        if (!collide_parts(w, pair, no_reference, manifold, nullptr, touching_gap_m(b, pair))) continue;
        pair.axis_cache = AxisCache{};
        update_pair_geometry(pair, manifold, part_match_distance_m(b, pair));
        for (std::uint32_t k = 0; k < pair.count; ++k) pair.points[k].bond = BondState::intact;
        bonded += pair.count;
        // The interior points of an edge-to-edge joint are bonded with its ends (sub_contacts.hpp).
        if (pair.count == 2 && p < w.sub_contacts.size()) {
            place_sub_points(w.sub_contacts[p], pair, w.contact.sub_contacts, part_match_distance_m(b, pair),
                             BondState::intact);
            bonded += w.sub_contacts[p].count;
        }
    }
    return bonded;
}

double bonded_gap_m(const World& w, const PairContact& pair) {
    const Bodies& b = w.bodies;
    return bonded_gap_m(b, pair, w.contact.at(b.material[pair.a], b.material[pair.b]));
}

}  // namespace blockdem
