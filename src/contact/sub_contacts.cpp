#include "contact/sub_contacts.hpp"

#include <algorithm>

#include "world/world.hpp"

namespace blockdem {

namespace {

// The broken states of the points, kept in broken_memory when they are dropped. (Rewritten
// whole: points placed again took their broken states from it, so they hold all it held.)
void remember_broken(SubContacts& sub) {
    if (sub.count == 0) return;
    std::uint32_t memory = 0;
    for (std::uint32_t k = 0; k < sub.count; ++k)
        if (is_broken(sub.points[k].bond)) memory |= (static_cast<std::uint32_t>(sub.points[k].bond) - 1u) << (2 * k);
    sub.broken_memory = memory;
    sub.memory_first_m = memory != 0 ? sub.points[0].point_m : Vec2{};
}

// The remembered bond of interior point k of interior points in all (none if it was not broken).
BondState remembered_bond(const SubContacts& sub, std::uint32_t k) {
    const std::uint32_t bits = (sub.broken_memory >> (2 * k)) & 3u;
    return bits == 0 ? BondState::none : static_cast<BondState>(bits + 1);
}

}  // namespace

double face_gap_m(const Bodies& b, const PairContact& pair) {
    return 0.25 * std::min(b.part_radius_m[pair.part_a], b.part_radius_m[pair.part_b]);
}

void keep_face_or_trim(ContactManifold& manifold, double gap_m, std::uint32_t n) {
    if (manifold.count == 2) {
        const double first_m = manifold.points[0].overlap_m;
        const double change_m = manifold.points[1].overlap_m - first_m;
        for (std::uint32_t k = 0; k + 2 < n; ++k)
            if (first_m + sub_point_fraction(k, n) * change_m > -gap_m) return;  // (as collide_polygons' test)
    }
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < manifold.count; ++i)
        if (manifold.points[i].overlap_m > -gap_m) manifold.points[kept++] = manifold.points[i];
    if (kept == manifold.count) return;
    manifold.count = kept;
    // (No points: the manifold's values as ContactManifold{} has them, set one by one, since the
    // unset point storage is not worth copying.)
    if (kept == 0) {
        manifold.normal = Vec2{};
        manifold.reference = 0;
    }
    manifold.stiffness_scale = 1.0;  // (a one-point contact is not softened: polygon_contact.cpp)
}

DroppedSubPoints drop_sub_points(SubContacts& sub) {
    DroppedSubPoints dropped;
    remember_broken(sub);
    for (std::uint32_t k = 0; k < sub.count; ++k) dropped.points[dropped.count++] = sub.points[k];
    sub.count = 0;
    return dropped;
}

DroppedSubPoints place_sub_points(SubContacts& sub, const PairContact& pair, std::uint32_t n, double match_distance_m,
                                  BondState new_bond) {
    const std::uint32_t interior = n - 2;
    const Vec2 first_m = pair.points[0].point_m;
    const Vec2 span_m = pair.points[1].point_m - first_m;
    const double first_overlap_m = pair.points[0].overlap_m;
    const double overlap_change_m = pair.points[1].overlap_m - first_overlap_m;
    // Which way last step's points run: from this step's first end, or from its second (the
    // manifold may list the ends in the other order). Judged on the point nearest an end.
    bool reversed = false;
    bool keep = sub.count == interior;
    if (keep) {
        const Vec2 next_to_first_m = first_m + sub_point_fraction(0, n) * span_m;
        const double same = length(sub.points[0].point_m - next_to_first_m);
        const double flipped = length(sub.points[interior - 1].point_m - next_to_first_m);
        reversed = flipped < same;
        keep = std::min(same, flipped) < match_distance_m;
    }
    DroppedSubPoints dropped;
    if (!keep) dropped = drop_sub_points(sub);
    SubContacts old = sub;
    // Fresh points where broken ones were dropped start broken (the header): counted from the
    // end nearer where point 0 was.
    bool memory_reversed = false;
    if (!keep && sub.broken_memory != 0) {
        const Vec2 last_m = first_m + sub_point_fraction(interior - 1, n) * span_m;
        const Vec2 next_to_first_m = first_m + sub_point_fraction(0, n) * span_m;
        memory_reversed = length(last_m - sub.memory_first_m) < length(next_to_first_m - sub.memory_first_m);
    }
    for (std::uint32_t k = 0; k < interior; ++k) {
        ContactPoint& p = sub.points[k];
        if (keep) {
            p = old.points[reversed ? interior - 1 - k : k];
        } else {
            p = ContactPoint{};
            p.bond = new_bond;
            if (old.broken_memory != 0) [[unlikely]] {
                const BondState remembered = remembered_bond(old, memory_reversed ? interior - 1 - k : k);
                if (remembered != BondState::none) p.bond = remembered;
            }
        }
        const double s = sub_point_fraction(k, n);
        p.feature = sub_point_feature(k);
        p.point_m = first_m + s * span_m;
        p.overlap_m = first_overlap_m + s * overlap_change_m;
    }
    sub.count = interior;
    sub.normal = pair.normal;
    return dropped;
}

void carry_sub_contacts(const std::vector<PairContact>& old_table, const std::vector<SubContacts>& old_sub,
                        const std::vector<PairContact>& table, std::vector<SubContacts>& sub) {
    sub.assign(table.size(), SubContacts{});
    // Both tables are sorted by (part_a, part_b): one linear merge.
    std::size_t old = 0;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const PairContact& pair = table[i];
        while (old < old_table.size() && (old_table[old].part_a < pair.part_a ||
                                          (old_table[old].part_a == pair.part_a && old_table[old].part_b < pair.part_b)))
            ++old;
        if (old < old_table.size() && old < old_sub.size() && old_table[old].part_a == pair.part_a &&
            old_table[old].part_b == pair.part_b)
            sub[i] = old_sub[old];
    }
}

}  // namespace blockdem
