#pragma once
// The 3-D contact table: this step's contact points, sorted by key, each with the history it
// carries to the next step. A point's key is (body a, body b, feature of a, feature of b)
// (geometry/polyhedron_contact_3d.hpp), so a point that the narrow phase finds again from the
// same pair of features keeps its shear spring; one found for the first time starts at zero, and
// one not found again is dropped (the 2-D table's rule, contact/contact_table.hpp).
#include <compare>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"
#include "laws/contact_parameters.hpp"
#include "laws/coulomb_slider_3d.hpp"

namespace blockdem {

struct ContactKey3d {
    std::uint32_t body_a = 0;
    std::uint32_t body_b = 0;     ///< body_a < body_b
    std::uint32_t feature_a = 0;  ///< feature_3d of a
    std::uint32_t feature_b = 0;  ///< feature_3d of b
    friend constexpr auto operator<=>(const ContactKey3d&, const ContactKey3d&) = default;
};

struct ContactPoint3d {
    ContactKey3d key;
    Vec3 point_m;                   ///< [m]
    Vec3 normal;                    ///< unit, from a to b
    double overlap_m = 0.0;         ///< [m] > 0
    double stiffness_share = 1.0;   ///< [-] its share w of kn and ks (geometry/corner_share_3d.hpp)
    // History carried to the next step.
    double normal_dashpot_n = 0.0;  ///< [N] last step's normal dashpot force on b
    ShearHistory3d shear;           ///< [N] shear spring and dashpot force on b, in the tangent plane
    bool sliding = false;           ///< this step's state, for output
    Vec3 force_n;                   ///< [N] this step's force on b (minus it on a), world frame
};

/// The law's parameters at a point: kn and ks times its stiffness share (the dashpots follow
/// through dashpot_coefficients, C = 2 h sqrt(M w k)).
inline ContactParameters point_parameters(const ContactParameters& p, double stiffness_share) {
    ContactParameters q = p;
    q.kn_N_m *= stiffness_share;
    q.ks_N_m *= stiffness_share;
    return q;
}

/// Gives each point of current (sorted by key, fresh from the narrow phase) the history of the
/// point of previous (sorted by key) with the same key, by one merge pass, and a point with no
/// such key a zero history (whatever it held: the step's table fill leaves it unwritten). The
/// shear spring is the point's tangential displacement times its stiffness w ks: when w changes
/// it is scaled by w_now / w_before, so that the displacement is what is carried.
void carry_history(const std::vector<ContactPoint3d>& previous, std::vector<ContactPoint3d>& current);

/// The same for a run of count points of current (sorted by key), all of one pair of bodies: last
/// step's run of that pair is found in previous at hint (where the run is expected in previous:
/// where last step's pair of the same rank began, or the run's index in current), or by galloping
/// from it, and then merged: runs of one table can be carried in parallel, with the whole
/// table's result, whatever the hints. hint_starts_a_run: the caller knows that hint is where a
/// run of last step's table began (where last step's pair of the same rank began), so where the
/// point there is of run's pair, it is that pair's first and the point before it is not read.
void carry_history(const std::vector<ContactPoint3d>& previous, ContactPoint3d* run, std::size_t count,
                   std::size_t hint, bool hint_starts_a_run = false);

/// p takes the history of last step's point before, of its key: the shear spring is the point's
/// tangential displacement times its stiffness w ks, so a changed w scales it by w_now / w_before.
[[gnu::always_inline]] inline void take_history(const ContactPoint3d& before, ContactPoint3d& p) {
    p.normal_dashpot_n = before.normal_dashpot_n;
    p.shear = before.shear;
    const double share_before = before.stiffness_share;
    if (p.stiffness_share != share_before)
        p.shear.spring_n = share_before > 0.0 ? (p.stiffness_share / share_before) * p.shear.spring_n : Vec3{};
}

/// A point found for the first time starts with no history.
[[gnu::always_inline]] inline void start_history(ContactPoint3d& p) {
    p.normal_dashpot_n = 0.0;
    p.shear = {};
}

namespace contact_key_words {
// A key's bodies, and its features, each as one 64-bit word: equal where both fields are.
inline std::uint64_t bodies(const ContactKey3d& k) {
    static_assert(offsetof(ContactKey3d, body_b) == offsetof(ContactKey3d, body_a) + 4);
    std::uint64_t w;
    std::memcpy(&w, &k.body_a, sizeof w);
    return w;
}
inline std::uint64_t features(const ContactKey3d& k) {
    static_assert(offsetof(ContactKey3d, feature_b) == offsetof(ContactKey3d, feature_a) + 4);
    std::uint64_t w;
    std::memcpy(&w, &k.feature_a, sizeof w);
    return w;
}
// The features as one word ordered as the key orders them.
inline std::uint64_t features_order(const ContactKey3d& k) {
    return (std::uint64_t{k.feature_a} << 32) | k.feature_b;
}
}  // namespace contact_key_words

/// Whether previous[start, end) is the run of key's pair of bodies in previous (sorted by key),
/// given that start and end are where runs of previous begin (or its end): the step carries last
/// step's run starts, as carry_history's hint_starts_a_run trusts them (a state file read into
/// the world clears them: replace_contacts). Inline, as RunHistoryWalk: called once a pair, a
/// call cost as much as the work.
inline bool is_run_of(const std::vector<ContactPoint3d>& previous, std::size_t start, std::size_t end,
                      const ContactKey3d& key) {
    return start < end && end <= previous.size() &&
           contact_key_words::bodies(previous[start].key) == contact_key_words::bodies(key);
}

/// carry_history for a run of this step's points (sorted by key), point by point, whose pair of
/// bodies had the run [q, end) last step (is_run_of): a straight merge of the two runs, comparing
/// features only, with no search and no test of the table's end. Point by point, so that the
/// step's fill takes the history as it writes a point (one pass over the run, not two).
struct RunHistoryWalk {
    const ContactPoint3d* q;    ///< last step's next point not yet passed
    const ContactPoint3d* end;  ///< the end of last step's run of the pair

    /// p (this step's, after the points already walked) takes its history.
    [[gnu::always_inline]] void carry(ContactPoint3d& p) {
        using contact_key_words::features;
        using contact_key_words::features_order;
        // The usual point kept its key, and last step's point at q is its own: one comparison of
        // the features says so (the bodies are the run's). Otherwise the walk passes last step's
        // smaller features (points gone).
        const std::uint64_t f = features(p.key);
        bool found = q != end && features(q->key) == f;
        if (!found) {
            const std::uint64_t order = features_order(p.key);
            while (q != end && features_order(q->key) < order) ++q;
            found = q != end && features(q->key) == f;
        }
        if (found) {
            take_history(*q, p);
            ++q;
        } else {
            start_history(p);
        }
    }
};

/// The same as carry_history for a run of count points of current (sorted by key) whose pair of
/// bodies had last_run[0, last_count) last step (that pair's whole run, is_run_of).
inline void carry_history_from_run(const ContactPoint3d* last_run, std::size_t last_count, ContactPoint3d* run,
                                   std::size_t count) {
    RunHistoryWalk walk{last_run, last_run + last_count};
    for (ContactPoint3d* p = run; p != run + count; ++p) walk.carry(*p);
}

}  // namespace blockdem
