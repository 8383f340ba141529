#pragma once
// Sub-contacts of an edge-to-edge joint ([contact] sub_contacts = n, per-length stiffness only):
// the contact's two end points (the pair's own points, PairContact::points) plus n - 2 interior
// points spread evenly between them, so that the bending stress of a bonded joint is resolved
// along the joint instead of lumped at its two ends.
//
// Geometry: both faces of an edge-to-edge contact are straight, so the position and the
// overlap of the point at fraction s of the way from the first end to the second are the linear
// interpolation of the ends' (exact for rigid polygons); no narrow-phase work is added.
// Tributary lengths: the trapezoid rule along the overlap L, spacing L / (n - 1): each interior
// point L / (n - 1), each end half that (n = 2: L / 2 each, as without sub-contacts). A joint of
// depth h then has the second moment sum L_i x_i^2 = (h^3 / 12) (1 + 2 / (n - 1)^2), so its
// elastic moment capacity under the tension cut-off sigma_t at the extreme point is
// (sigma_t t h^2 / 6) (1 + 2 / (n - 1)^2): 3 times the continuous joint's for n = 2, 1.22 for 4,
// 1.04 for 8, 1.009 for 16 (docs/physics.md).
//
// Storage: the interior points live in a side array aligned with the contact table
// (World::sub_contacts), allocated only when n > 2 and carried through the table's merges, so
// the common two-point contact costs nothing more. Identity: the interior point k of a pair,
// counted from one end: kept from step to step when it is within the match distance of last
// step's point k counted from either end (the ends may swap their order or their owners' ids:
// contact_table.cpp), else new.
//
// Crack growth: a joint that holds an intact bond keeps all its n points while any of them is
// within the bond's gap. The narrow phase then finds the face's two ends up to face_gap_m apart
// instead of dropping an end that opened (keep_face_or_trim), so that each point along the
// joint keeps its own bond, intact or broken, and its shear history while the crack opens past
// it: a bonded joint cracks point by point. A point that is open (negative overlap) and not
// bonded carries nothing (contact_forces.cpp). Once no interior point is within the gap, or no
// bond is left, the face is an ordinary contact again (a dry face rocking onto one end is the
// one-point contact it was before) and the interior points are dropped (their dashpots' last half interval booked as for
// any opened point). Which of them were broken is remembered (broken_memory), as the pair
// remembers its broken corners, so that a crack that closes again is broken still: a broken
// point never bonds again.
#include <cstdint>
#include <vector>

#include "contact/contact_table.hpp"

namespace blockdem {

struct Bodies;

/// The most points an edge-to-edge contact may be discretised into ([contact] sub_contacts).
inline constexpr std::uint32_t max_sub_contacts = 16;

/// The interior points of one pair (the pair's ends are its own two points).
struct SubContacts {
    std::uint32_t count = 0;                       ///< interior points held: 0, or sub_contacts - 2
    Vec2 normal;                                   ///< the pair's unit normal when they were placed
    ContactPoint points[max_sub_contacts - 2];     ///< from the pair's points[0] towards points[1]
    /// The bonds of interior points that were dropped broken, 2 bits per point k (0: none, else
    /// the BondState broken_tension or broken_shear less 1), and where point 0 was then [m]:
    /// the order of the points when they are placed again.
    std::uint32_t broken_memory = 0;
    Vec2 memory_first_m;
};

/// The gap up to which the narrow phase finds the ends of a face with sub-contacts [m]: a
/// quarter of the smaller part's radius, far more than a crack opens while some of the face's
/// points still touch, and far less than the parts' size.
double face_gap_m(const Bodies& b, const PairContact& pair);

/// After the narrow phase of a face with sub-contacts found with face_gap_m: keeps both ends
/// when some interior point of n lies within gap_m (the pair's own gap: its bond's, or 0), else
/// drops the ends beyond gap_m as collide_polygons with gap_m would.
void keep_face_or_trim(ContactManifold& manifold, double gap_m, std::uint32_t n);

/// The feature id of interior point k (k = 0 next to points[0]): marks it as no corner.
constexpr std::uint32_t sub_point_feature(std::uint32_t k) { return 0x80000000u | (k + 1); }

/// True while some interior point holds an intact bond.
inline bool has_intact_bond(const SubContacts& sub) {
    for (std::uint32_t k = 0; k < sub.count; ++k)
        if (sub.points[k].bond == BondState::intact) return true;
    return false;
}

/// Fraction of the way from points[0] to points[1] of interior point k of n points in all.
inline double sub_point_fraction(std::uint32_t k, std::uint32_t n) {
    return static_cast<double>(k + 1) / static_cast<double>(n - 1);
}

/// Sets the interior points' geometry from the pair's two ends for a contact of n points in
/// all (n > 2, pair.count == 2), keeping each point's history when it matches last step's (see
/// above); points that did not match start fresh. Returns last step's points that were dropped
/// (their dashpots' last share of work is booked by the law). new_bond: the bond of a fresh
/// point (intact when the joint is bonded at the start, else none).
struct DroppedSubPoints {
    std::uint32_t count = 0;
    ContactPoint points[max_sub_contacts - 2];
};
DroppedSubPoints place_sub_points(SubContacts& sub, const PairContact& pair, std::uint32_t n, double match_distance_m,
                                  BondState new_bond = BondState::none);

/// Drops every interior point, returning them.
DroppedSubPoints drop_sub_points(SubContacts& sub);

/// Carries the interior points through a merge of the contact table: old_table and old_sub are
/// the table and side array before it, table the table after; new pairs start with none.
void carry_sub_contacts(const std::vector<PairContact>& old_table, const std::vector<SubContacts>& old_sub,
                        const std::vector<PairContact>& table, std::vector<SubContacts>& sub);

}  // namespace blockdem
