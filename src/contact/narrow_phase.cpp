#include "contact/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

#include "contact/narrow_phase_pair.hpp"
#include "world/parallel.hpp"

namespace blockdem {
using narrow_phase_detail::pair_contact;
using narrow_phase_detail::part_view;

OpenedPoints update_pair_contact(World& w, std::size_t p) { return pair_contact<false>(w, p); }

OpenedPoints update_joint_pair_contact(World& w, std::size_t p) { return pair_contact<true>(w, p); }

bool collide_parts(const World& w, const PairContact& pair, std::uint32_t reference, ContactManifold& manifold,
                   AxisCache* cache, double gap_m) {
    const Bodies& b = w.bodies;
    const PolygonView a = part_view(b, pair.part_a);
    const PolygonView c = part_view(b, pair.part_b);
    if (w.contact.rounding_m > 0.0) {
        AxisCache unused;
        return collide_rounded(a, c, w.contact.rounding_m, reference, manifold, cache != nullptr ? *cache : unused, gap_m,
                               b.part_count[pair.a] > 1 ? &b.seam_corner[b.part_vertex_begin[pair.part_a]] : nullptr,
                               b.part_count[pair.b] > 1 ? &b.seam_corner[b.part_vertex_begin[pair.part_b]] : nullptr);
    }
    return collide_polygons(a, c, reference, manifold, cache, gap_m);
}

double part_match_distance_m(const Bodies& b, const PairContact& pair) {
    return 0.05 * std::min(b.part_radius_m[pair.part_a], b.part_radius_m[pair.part_b]);
}

void update_contact_geometry(World& w) {
    parallel_for(static_cast<std::ptrdiff_t>(w.contacts.size()),
                 [&](std::ptrdiff_t p) { update_pair_contact(w, static_cast<std::size_t>(p)); });
}

}  // namespace blockdem
