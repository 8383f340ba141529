#pragma once
// The contact table: one entry per candidate pair from the broad phase, holding that pair's
// contact points and the history they carry from step to step (the shear spring force).
// Entries are sorted by (a, b); a point is matched to last step's point with the same feature
// id (the corner it belongs to), so a contact keeps its history while it stays closed and
// starts from zero when it is new; a point that opened is dropped with its history.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "broad_phase/grid_broad_phase.hpp"
#include "geometry/polygon_contact.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/mohr_coulomb_joint.hpp"

namespace blockdem {

/// One contact point: its geometry, its forces and its history.
struct ContactPoint {
    // (The 4-byte and 1-byte members first, together: the struct stays 80 bytes with dilation_m.)
    std::uint32_t feature = 0;     ///< make_feature(owner, corner): the identity
    bool sliding = false;
    BondState bond = BondState::none;  ///< the point's bond (history; laws/mohr_coulomb_joint.hpp)
    Vec2 point_m;                  ///< [m] world position
    double overlap_m = 0.0;        ///< [m]
    double normal_force_n = 0.0;   ///< [N] on b along the pair normal (a dilating joint's law reads last step's)
    double shear_spring_n = 0.0;   ///< [N] shear spring force on b along the tangent (history)
    double shear_force_n = 0.0;    ///< [N] total shear force on b along the tangent
    double normal_dashpot_n = 0.0; ///< [N] the normal dashpot's part of normal_force_n (history)
    double shear_dashpot_n = 0.0;  ///< [N] the shear dashpot's part of shear_force_n (history)
    double dilation_m = 0.0;       ///< [m] accumulated joint dilation u_d (history; per-length joints only)

    /// What the contact law carries over to the next step (laws/linear_spring_dashpot.hpp).
    ContactHistory history() const { return {shear_spring_n, normal_dashpot_n, shear_dashpot_n}; }
    void keep_history_of(const ContactPoint& old) {
        shear_spring_n = old.shear_spring_n;
        normal_dashpot_n = old.normal_dashpot_n;
        shear_dashpot_n = old.shear_dashpot_n;
        bond = old.bond;
        normal_force_n = old.normal_force_n;
        dilation_m = old.dilation_m;
    }
};
static_assert(sizeof(ContactPoint) == 80, "the contact table's points: keep them at 80 bytes (cache lines)");

/// PairContact::broken_features: none; else the feature id, with broken_in_shear set for a
/// shear failure (feature ids use the low 17 bits: polygon_contact.hpp).
inline constexpr std::uint32_t no_feature = 0xffffffffu;
inline constexpr std::uint32_t broken_in_shear = 0x40000000u;

/// All contact points between part part_a of body a and part part_b of body b (a < b; a convex
/// body is one part, and then the part id is the body id while every body is convex). The law,
/// the ledger and the force sums read the bodies; the narrow phase reads the parts.
struct PairContact {
    // (What a pair that stays apart reads comes first, in the entry's first 32 bytes: most
    // candidate pairs of a large scene are apart or just touching, and the table outgrows the
    // caches, so those pairs should cost one cache line, not three.)
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::uint32_t part_a = 0;                 ///< a part of body a (world/world.hpp, Bodies)
    std::uint32_t part_b = 0;                 ///< a part of body b
    std::uint32_t count = 0;                  ///< active points (0 = apart)
    std::uint32_t reference = no_reference;   ///< reference edge last step (hysteresis)
    AxisCache axis_cache;                     ///< lets lasting contacts skip the full separating-axis test
    Vec2 normal;                              ///< unit, from a to b
    double stiffness_scale = 1.0;             ///< [-] softening of a shrinking overlap (polygon_contact.hpp)
    /// The corners whose broken bond left with their point when it opened (broken_memory below):
    /// a point that closes again there is broken still, with the residual friction.
    std::uint32_t broken_features[2] = {no_feature, no_feature};
    ContactPoint points[2];
};


/// Replaces the candidate pairs after a broad-phase rebuild, keeping the state of pairs that
/// remain candidates. pairs: pairs of parts of different bodies, sorted; part_body: each part's
/// body. The table is sorted by (part_a, part_b) too, so this is one linear merge.
void merge_candidate_pairs(std::vector<PairContact>& table, const std::vector<BodyPair>& pairs,
                           const std::vector<std::uint32_t>& part_body, std::vector<PairContact>& scratch);

/// One point of last step that opened: where it was and its last dashpot forces.
struct OpenedPoint {
    // (No default values, here and below but for count: the narrow phase hands an OpenedPoints
    // back for every pair at every step and almost never fills it; zeroing it showed in profiles.)
    double x_m, y_m;           ///< [m] where it was
    double normal_dashpot_n;   ///< [N] its last normal dashpot force on b
    double shear_dashpot_n;    ///< [N] its last shear dashpot force on b
};

/// Last step's points that did not close again this step, with what the energy ledger needs to
/// finish their account: their dashpots acted over the half of the last interval that the
/// trapezoid of the law books only at the next step (contact/contact_forces.cpp). Only the
/// first count points and, if count > 0, the normal are set.
struct OpenedPoints {
    std::uint32_t count = 0;
    double normal_x, normal_y;  ///< the pair's unit normal when they were last closed
    OpenedPoint points[2];
};

/// The opening [m] up to which the narrow phase keeps a dilating pair's points: twice their
/// largest accumulated dilation u_d. A point pushes while its faces are apart by less than its
/// u_d, and a sliding block rises in a step by about what the point dilated in the last one,
/// which the point's own law adds to u_d only after the narrow phase: kept to u_d alone, a
/// steadily rising joint lost its points once the rise per step passed its elastic closure.
/// (A point kept while open carries no force: laws/mohr_coulomb_joint.hpp.)
inline double dilated_gap_m(const PairContact& pair) {
    double largest_m = 0.0;
    for (std::uint32_t k = 0; k < pair.count; ++k) largest_m = std::max(largest_m, pair.points[k].dilation_m);
    return 2.0 * largest_m;
}

/// True while some point of the pair holds an intact bond (the narrow phase then keeps points
/// that opened slightly: contact/narrow_phase.cpp).
inline bool has_intact_bond(const PairContact& pair) {
    for (std::uint32_t k = 0; k < pair.count; ++k)
        if (pair.points[k].bond == BondState::intact) return true;
    return false;
}

/// update_pair_geometry's usual step, inline for the narrow phase (a call per pair showed in
/// profiles): when this step's manifold has last step's corners in the same order, updates the
/// pair as update_pair_geometry does (every point keeps its own history, none opens) and returns
/// true; otherwise changes nothing and returns false.
inline bool update_same_points(PairContact& pair, const ContactManifold& manifold) {
    if (manifold.count != pair.count) return false;
    for (std::uint32_t i = 0; i < manifold.count; ++i)
        if (manifold.points[i].feature != pair.points[i].feature) return false;
    // The shear history is a spring stretch: if the contact softened, its force follows.
    const double rescale = manifold.count > 0 && manifold.stiffness_scale != pair.stiffness_scale && pair.stiffness_scale > 0.0
                               ? manifold.stiffness_scale / pair.stiffness_scale
                               : 1.0;
    for (std::uint32_t i = 0; i < manifold.count; ++i) {
        pair.points[i].point_m = manifold.points[i].point_m;
        pair.points[i].overlap_m = manifold.points[i].overlap_m;
        if (rescale != 1.0) pair.points[i].shear_spring_n *= rescale;
    }
    pair.stiffness_scale = manifold.count > 0 ? manifold.stiffness_scale : 1.0;
    pair.normal = manifold.normal;
    pair.reference = manifold.count > 0 ? manifold.reference : no_reference;
    return true;
}

/// Updates a pair with this step's geometry: matched points keep their shear history. A point
/// matches last step's point with the same feature id, or else an unmatched old point closer
/// than match_distance_m (see the .cpp for why). Returns the old points that opened.
OpenedPoints update_pair_geometry(PairContact& pair, const ContactManifold& manifold, double match_distance_m);

}  // namespace blockdem
