#include "contact/contact_table.hpp"

namespace blockdem {

void merge_candidate_pairs(std::vector<PairContact>& table, const std::vector<BodyPair>& pairs,
                           const std::vector<std::uint32_t>& part_body, std::vector<PairContact>& scratch) {
    scratch.clear();
    scratch.reserve(pairs.size());
    std::size_t old = 0;
    for (const auto& [a, b] : pairs) {
        while (old < table.size() && (table[old].part_a < a || (table[old].part_a == a && table[old].part_b < b))) ++old;
        if (old < table.size() && table[old].part_a == a && table[old].part_b == b) {
            scratch.push_back(table[old]);
        } else {
            PairContact fresh;
            fresh.a = part_body[a];
            fresh.b = part_body[b];
            fresh.part_a = a;
            fresh.part_b = b;
            scratch.push_back(fresh);
        }
    }
    table.swap(scratch);
}

namespace {

// A broken bond stays broken where it was (issue 13: a cracked joint that closes again keeps
// only its residual friction): the corner of a broken point that opens is remembered by its
// pair, and a point that closes at that corner again starts broken.
void remember_broken(PairContact& pair, const ContactPoint& old) {
    if (!is_broken(old.bond)) return;
    const std::uint32_t entry = old.feature | (old.bond == BondState::broken_shear ? broken_in_shear : 0u);
    for (std::uint32_t& slot : pair.broken_features)
        if (slot == no_feature || (slot & ~broken_in_shear) == old.feature) {
            slot = entry;
            return;
        }
    pair.broken_features[1] = entry;  // (more than two: the latest is kept)
}

BondState remembered_bond(const PairContact& pair, std::uint32_t feature) {
    for (const std::uint32_t slot : pair.broken_features)
        if (slot != no_feature && (slot & ~broken_in_shear) == feature)
            return (slot & broken_in_shear) != 0 ? BondState::broken_shear : BondState::broken_tension;
    return BondState::none;
}

}  // namespace

OpenedPoints update_pair_geometry(PairContact& pair, const ContactManifold& manifold, double match_distance_m) {
    // The same corners as last step, in the same order (the usual step of a lasting contact):
    // every point keeps its own history (what the general matching below gives here).
    if (update_same_points(pair, manifold)) {
        OpenedPoints none;  // (count 0, nothing else written: contact_table.hpp)
        return none;
    }
    ContactPoint updated[2];
    bool taken[2] = {false, false};
    for (std::uint32_t i = 0; i < manifold.count; ++i) {
        ContactPoint& p = updated[i];
        p.feature = manifold.points[i].feature;
        p.point_m = manifold.points[i].point_m;
        p.overlap_m = manifold.points[i].overlap_m;
        if (pair.broken_features[0] != no_feature) [[unlikely]]
            p.bond = remembered_bond(pair, p.feature);
        for (std::uint32_t j = 0; j < pair.count; ++j)
            if (!taken[j] && pair.points[j].feature == p.feature) {
                p.keep_history_of(pair.points[j]);
                taken[j] = true;
            }
    }
    // Two equal, aligned faces (stacked blocks of one width) give the same corner either owner's
    // id depending on which face is the reference; a point that lost its id but sits where an
    // unmatched old point was is the same contact and keeps its history.
    for (std::uint32_t i = 0; i < manifold.count; ++i) {
        bool matched = false;
        for (std::uint32_t j = 0; j < pair.count; ++j) matched = matched || pair.points[j].feature == updated[i].feature;
        if (matched) continue;
        for (std::uint32_t j = 0; j < pair.count; ++j)
            if (!taken[j] && length(pair.points[j].point_m - updated[i].point_m) < match_distance_m) {
                updated[i].keep_history_of(pair.points[j]);
                taken[j] = true;
                break;
            }
    }
    // The shear history is a spring stretch: if the contact softened, its force follows.
    if (manifold.stiffness_scale != pair.stiffness_scale && pair.stiffness_scale > 0.0)
        for (std::uint32_t i = 0; i < manifold.count; ++i)
            updated[i].shear_spring_n *= manifold.stiffness_scale / pair.stiffness_scale;
    OpenedPoints opened;
    opened.normal_x = pair.normal.x;
    opened.normal_y = pair.normal.y;
    for (std::uint32_t j = 0; j < pair.count; ++j) {
        if (taken[j]) continue;
        const ContactPoint& old = pair.points[j];
        remember_broken(pair, old);
        opened.points[opened.count++] = {old.point_m.x, old.point_m.y, old.normal_dashpot_n, old.shear_dashpot_n};
    }
    pair.stiffness_scale = manifold.count > 0 ? manifold.stiffness_scale : 1.0;
    pair.count = manifold.count;
    pair.normal = manifold.normal;
    pair.reference = manifold.count > 0 ? manifold.reference : no_reference;
    for (std::uint32_t i = 0; i < manifold.count; ++i) pair.points[i] = updated[i];
    return opened;
}

}  // namespace blockdem
