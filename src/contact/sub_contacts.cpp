#include "contact/sub_contacts.hpp"

#include <algorithm>

namespace blockdem {

DroppedSubPoints drop_sub_points(SubContacts& sub) {
    DroppedSubPoints dropped;
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
    for (std::uint32_t k = 0; k < interior; ++k) {
        ContactPoint& p = sub.points[k];
        if (keep) {
            p = old.points[reversed ? interior - 1 - k : k];
        } else {
            p = ContactPoint{};
            p.bond = new_bond;
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
