#pragma once
// The narrow phase of one pair (narrow_phase.hpp), inline: update_pair_contact and
// update_joint_pair_contact are made of it, and so is the step's contact pass
// (contact_forces.hpp, update_convex_contacts_and_forces), which runs it and the law in one body of
// code per pair: two calls per pair and one from the chunk sum, with the OpenedPoints and the
// ContactEnergy handed through memory, cost the rounded per-length wall 3.7 % of its step
// (docs/performance.md, "The narrow phase and the law in one pass"). Not for other callers:
// narrow_phase.hpp is the interface.
#include <algorithm>
#include <cmath>

#include "contact/bonded_pairs.hpp"
#include "contact/narrow_phase.hpp"
#include "contact/contact_table.hpp"
#include "contact/sub_contacts.hpp"
#include "geometry/polygon_contact.hpp"
#include "geometry/rounded_contact.hpp"
#include "geometry/rounded_face_contact.hpp"
#include "laws/mohr_coulomb_joint.hpp"
#include "world/world.hpp"

namespace blockdem::narrow_phase_detail {


inline PolygonView part_view(const Bodies& b, std::uint32_t part) {
    return {&b.world_vertices_m[b.part_vertex_begin[part]], &b.world_normals[b.part_vertex_begin[part]],
            b.part_vertex_count[part]};
}

// A part's polygon with its corners' core offsets for rounding r, when the body geometry made
// them for r (world/step.cpp); as it is otherwise (the narrow phase then makes them).
inline PolygonView with_corner_offsets(const Bodies& b, double rounding_m, PolygonView polygon, std::uint32_t part) {
    if (b.corner_offsets_rounding_m == rounding_m) polygon.corner_offsets_m = &b.world_corner_offsets_m[b.part_vertex_begin[part]];
    return polygon;
}

// How far the open end of a per-length joint's two-point (edge-to-edge) contact may be apart
// and the pair still keep it, as a point carrying nothing [m] (0 for its other pairs). Why:
// the per-length law gives each end of an edge contact half the face and a lone corner point 0.1
// of the least width (laws/mohr_coulomb_joint.hpp), so a face whose end flickers about zero
// overlap (bricks laid exactly touching: a head joint at rest) jumped its stiffness five-fold
// at every flicker; the energy each jump made or took never came to rest (a wall at rest on a
// level table crept and its ledger's error grew by 0.1 a second: tests/validation/
// test_jointed_wall_at_rest.cpp). Kept up to joint_face_keep_fraction of the thinner body's
// least width, and taken back as a face only when both ends touch again, the pair changes its
// point count on a real opening or closing, once, not at every step.
inline double joint_face_gap_m(const Bodies& b, const PairContact& pair) {
    if (pair.count != 2) return 0.0;
    return joint_face_keep_fraction * std::min(b.least_width_m[pair.a], b.least_width_m[pair.b]);
}

// How far pair p's points may be apart and still be kept [m], and whether its face is kept
// whole for its sub-contacts (both below). (The pair's parameters looked up once: bonded pairs
// asked for them twice a step.)
struct KeptGap {
    double gap_m = 0.0;
    bool face_kept = false;
};

template <bool joints_only>
inline KeptGap kept_gap_m(const World& w, const PairContact& pair, std::size_t p) {
    KeptGap kept;
    if (pair.count == 0) return kept;
    const Bodies& b = w.bodies;
    // (Bonds and dilation exist only on per-length joints: bonded_pairs.cpp, the scenario
    // reader; a per-point pair's points never hold either.)
    const ContactParameters* params = nullptr;
    if constexpr (!joints_only) {
        params = &w.contact.at(b.material[pair.a], b.material[pair.b]);
        if (params->stiffness != StiffnessBasis::per_length) return kept;
    }
    // A bonded joint holds its points while it opens by less than its gap (bonded_pairs.hpp),
    // or by the interior points of its sub-contacts (contact/sub_contacts.hpp). (In a world of
    // joints only, the parameters are needed only here.)
    if (has_intact_bond(pair) || (!w.sub_contacts.empty() && has_intact_bond(w.sub_contacts[p]))) {
        if (params == nullptr) params = &w.contact.at(b.material[pair.a], b.material[pair.b]);
        kept.gap_m = bonded_gap_m(b, pair, *params);
    }
    // A bonded joint discretised into sub-contacts stays one face while any of its points is in
    // contact or bonded: its ends are found up to face_gap_m apart, so that its interior points
    // keep their place, bond and history while a crack runs along it (sub_contacts.hpp).
    kept.face_kept = kept.gap_m > 0.0 && !w.sub_contacts.empty() && w.sub_contacts[p].count > 0;
    // A dilated joint point pushes while the faces are apart by less than its dilation.
    if (w.contact.any_dilation) [[unlikely]]
        kept.gap_m = std::max(kept.gap_m, dilated_gap_m(pair));
    kept.gap_m = std::max(kept.gap_m, joint_face_gap_m(b, pair));
    return kept;
}

// update_pair_contact, and with joints_only, update_joint_pair_contact (narrow_phase.hpp);
// inlined in each, and in the step's contact pass, so the per-point path has the code it had.
template <bool joints_only>
[[gnu::always_inline]] inline OpenedPoints pair_contact(World& w, std::size_t p) {
    const Bodies& b = w.bodies;
    PairContact& pair = w.contacts[p];
    // The pair's polygons are parts (a convex body's one part is the body itself); the motion
    // that moves them is their bodies'.
    const std::uint32_t part_a = pair.part_a;
    const std::uint32_t part_b = pair.part_b;
    // A pair that keeps points apart by a gap gets no early exit on the boxes.
    const KeptGap kept = kept_gap_m<joints_only>(w, pair, p);
    const double gap_m = kept.gap_m;
    const bool face_kept = kept.face_kept;
    const double collide_gap_m = face_kept ? std::max(gap_m, face_gap_m(b, pair)) : gap_m;
    // Early exit: boxes apart by a gap means some edge normal separates the polygons, so
    // collide_polygons would return no points; the pair is updated exactly as it would be.
    const Aabb& box_a = b.part_box_m[part_a];
    const Aabb& box_b = b.part_box_m[part_b];
    if (collide_gap_m == 0.0 &&
        (box_a.hi.x < box_b.lo.x || box_b.hi.x < box_a.lo.x || box_a.hi.y < box_b.lo.y || box_b.hi.y < box_a.lo.y)) {
        // (Reset only if set: a pair apart stays clean and its cache line is not written.)
        if (pair.axis_cache.separating != no_reference || pair.axis_cache.others_max_separation_m < INFINITY)
            pair.axis_cache = AxisCache{};
        if (pair.count > 0 || pair.reference != no_reference) return update_pair_geometry(pair, ContactManifold{}, 0.0);
        OpenedPoints none;  // (count 0, nothing else written: contact_table.hpp)
        return none;
    }
    const PolygonView a = part_view(b, part_a);
    const PolygonView c = part_view(b, part_b);
    // Still apart along the edge that separated the pair last step: the pair (no points, no
    // reference) is already what collide_polygons would make it. (Bricks laid side by side
    // stay exactly touching, separation 0, until the load reaches them.)
    if (pair.count == 0 && separated_by_cached_edge(a, c, pair.axis_cache)) {
        OpenedPoints none;
        return none;
    }
    // How far any edge's separation can have moved since the last step: both bodies'
    // translations plus their rotations times a lever covering every corner of either (the
    // bodies' radii cover their parts too) (x(t) - x(t - dt) = v(t - dt/2) dt exactly), with a
    // margin for round-off.
    // (Lengths are bounded by |x| + |y|: no square roots, and a bound is all this needs.)
    const double radii = b.bounding_radius_m[pair.a] + b.bounding_radius_m[pair.b];
    const double lever = norm_bound(b.position_m[pair.a] - b.position_m[pair.b]) + radii;
    const double turn_rad = w.dt_s * (std::abs(b.angular_velocity_rad_s[pair.a]) + std::abs(b.angular_velocity_rad_s[pair.b]));
    pair.axis_cache.drift_m += w.dt_s * (norm_bound(b.velocity_m_s[pair.a]) + norm_bound(b.velocity_m_s[pair.b])) +
                               turn_rad * lever + 1e-9 * radii;
    // (Plus the round-off of the angles' own updates, theta += dt omega, which a long run at a
    // steady spin accumulates with one sign: half an ulp of each angle per step, doubled.)
    pair.axis_cache.turn_rad +=
        turn_rad + 2.3e-16 * (1.0 + std::abs(b.rotation_rad[pair.a]) + std::abs(b.rotation_rad[pair.b]));
    ContactManifold manifold;
    if (w.contact.rounding_m > 0.0) [[unlikely]]  // (sharp corners keep their code layout)
        rounded_detail::collide_rounded_lasting(with_corner_offsets(b, w.contact.rounding_m, a, part_a),
                                                with_corner_offsets(b, w.contact.rounding_m, c, part_b),
                                                w.contact.rounding_m, pair.reference, manifold, pair.axis_cache, collide_gap_m,
                                                b.part_count[pair.a] > 1 ? &b.seam_corner[b.part_vertex_begin[part_a]] : nullptr,
                                                b.part_count[pair.b] > 1 ? &b.seam_corner[b.part_vertex_begin[part_b]] : nullptr);
    else
        collide_polygons(a, c, pair.reference, manifold, &pair.axis_cache, collide_gap_m);
    if (face_kept) [[unlikely]]
        keep_face_or_trim(manifold, gap_m, w.contact.sub_contacts);
    if (update_same_points(pair, manifold)) {
        OpenedPoints none;  // (count 0, nothing else written: contact_table.hpp)
        return none;
    }
    return update_pair_geometry(pair, manifold, part_match_distance_m(b, pair));
}

}  // namespace blockdem::narrow_phase_detail
