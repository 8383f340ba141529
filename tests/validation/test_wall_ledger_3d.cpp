// The 3-D energy ledger on a shaken brick wall (issue 15, docs/3d.md "The ledger on a shaken
// wall"). Before the stiffness shares, the S3D wall's balance error was 0.10 (200 bricks) and 0.45
// (1000), and it did not fall with dt: on flush faces of equal width, the clipped overlap polygon
// gained and lost corners as an incident edge ran along a reference side plane, each corner a
// point with a full kn, so kn d^2 / 2 appeared and vanished at once. Each point now carries its
// corner's share of kn and ks (geometry/corner_share_3d.hpp), continuous in the polygon's shape.
// This test asserts the closed ledger and splits what is left by cause, from the points of the
// step before and after (contact/contact_table_3d.hpp: a point is its key):
//   (a) points born with a finite overlap: their normal spring energy w kn d^2 / 2 appears at once;
//   (b) points gone with a finite overlap: their w kn d^2 / 2 (as it was the step before) vanishes;
//   (c) points gone with a loaded shear spring (a key change restarts it): its |s|^2 / (2 w ks);
//   (e) kept points whose share w changed while loaded: the force w kn d does no work for dw, so
//       the stored energy changes by kn d^2 dw / 2 (and ks u^2 dw / 2) unbooked;
//   (d) the rest: the scheme's own error, the dashpots' and the table's booking, and the part of a
//       relabelled point's depth change that (a) and (b) count as a jump.
// A contact that opens or closes smoothly makes (a) and (b) of order kn (v dt)^2: all but nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "scenes/s3d_wall_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

struct LedgerBreakdown {
    double born_normal_j = 0.0;          ///< [J] (a), summed over the run
    double gone_normal_j = 0.0;          ///< [J] (b)
    double gone_shear_j = 0.0;           ///< [J] (c)
    double count_changed_normal_j = 0.0; ///< [J] (a) - (b) over the pair-steps whose point count changed
    double share_change_j = 0.0;         ///< [J] kept points' share changes, net
    double share_change_abs_j = 0.0;     ///< [J] the same, in absolute value
    double residual_j = 0.0;             ///< [J] the ledger's residual gained over the shaking
    double scale_j = 0.0;                ///< [J] the ledger's largest term over the run
    double balance_error = 0.0;          ///< the ledger's residual over its scale, at the end
    long pair_steps = 0;                 ///< touching pairs summed over the steps
    long count_changes = 0;              ///< pair-steps whose point count changed
    long born_points = 0;
    long gone_points = 0;
    /// What the jumps put into the residual: created minus destroyed [J].
    double jumps_j() const { return born_normal_j - gone_normal_j - gone_shear_j; }
    /// (d): the residual the jumps leave [J].
    double rest_j() const { return residual_j - jumps_j(); }
};

double normal_energy_j(const ContactParameters& p, const ContactPoint3d& c) {
    return 0.5 * c.stiffness_share * p.kn_N_m * c.overlap_m * c.overlap_m;
}

double shear_energy_j(const ContactParameters& p, const ContactPoint3d& c) {
    const double ks = c.stiffness_share * p.ks_N_m;
    return ks > 0.0 ? 0.5 * dot(c.shear.spring_n, c.shear.spring_n) / ks : 0.0;
}

// The stored energy a kept point's share change w0 -> w1 makes at fixed displacements: the normal
// spring's kn d^2 dw / 2 with d^2 the step's mean, the shear spring's ks u^2 dw / 2 with u its
// displacement before the change.
double share_change_j(const ContactParameters& p, const ContactPoint3d& before, const ContactPoint3d& after) {
    const double dw = after.stiffness_share - before.stiffness_share;
    const double mean_d2 = 0.5 * (before.overlap_m * before.overlap_m + after.overlap_m * after.overlap_m);
    return 0.5 * p.kn_N_m * dw * mean_d2 + (before.stiffness_share > 0.0 ? dw / before.stiffness_share : 0.0) * shear_energy_j(p, before);
}

using PointIt = std::vector<ContactPoint3d>::const_iterator;

// The end of the run of points of the pair that starts at first (the table is sorted by key, and
// a key starts with the pair).
PointIt pair_end(PointIt first, PointIt end) {
    return std::find_if(first, end, [&](const ContactPoint3d& c) {
        return c.key.body_a != first->key.body_a || c.key.body_b != first->key.body_b;
    });
}

// One pair's jumps between last step's points [b0, b1) and this step's [a0, a1), both sorted by key.
void tally_pair(const ContactParameters& p, PointIt b0, PointIt b1, PointIt a0, PointIt a1, LedgerBreakdown& tally) {
    double net_normal_j = 0.0;
    const bool count_changed = (b1 - b0) != (a1 - a0);
    while (b0 != b1 || a0 != a1) {
        if (a0 == a1 || (b0 != b1 && b0->key < a0->key)) {
            net_normal_j -= normal_energy_j(p, *b0);
            tally.gone_normal_j += normal_energy_j(p, *b0);
            tally.gone_shear_j += shear_energy_j(p, *b0);
            ++tally.gone_points;
            ++b0;
        } else if (b0 == b1 || a0->key < b0->key) {
            net_normal_j += normal_energy_j(p, *a0);
            tally.born_normal_j += normal_energy_j(p, *a0);
            ++tally.born_points;
            ++a0;
        } else {
            const double e = share_change_j(p, *b0, *a0);
            tally.share_change_j += e;
            tally.share_change_abs_j += std::abs(e);
            ++b0;
            ++a0;
        }
    }
    if (count_changed) {
        tally.count_changed_normal_j += net_normal_j;
        ++tally.count_changes;
    }
}

// Adds the jumps between last step's points and this step's (both sorted by key), pair by pair.
void tally_jumps(const ContactParameters& p, const std::vector<ContactPoint3d>& before,
                 const std::vector<ContactPoint3d>& after, LedgerBreakdown& tally) {
    PointIt b = before.begin();
    PointIt a = after.begin();
    const auto pair_of = [](const ContactPoint3d& c) { return std::pair{c.key.body_a, c.key.body_b}; };
    while (b != before.end() || a != after.end()) {
        const bool take_b = b != before.end() && (a == after.end() || pair_of(*b) <= pair_of(*a));
        const bool take_a = a != after.end() && (b == before.end() || pair_of(*a) <= pair_of(*b));
        const PointIt b_end = take_b ? pair_end(b, before.end()) : b;
        const PointIt a_end = take_a ? pair_end(a, after.end()) : a;
        tally_pair(p, b, b_end, a, a_end, tally);
        if (take_a) ++tally.pair_steps;
        b = b_end;
        a = a_end;
    }
}

// The S3D wall (scenes/s3d_wall_3d.hpp) of the given number of bricks: settled for 0.01 s, then
// shaken for shaking_s; the jumps and the ledger's residual are taken over the shaking only.
LedgerBreakdown shaken_wall(int bricks, double dt_s, double shaking_s) {
    scenes::S3dWallDef def;
    def.bricks = bricks;
    def.dt_s = dt_s;
    def.settling_steps = static_cast<int>(std::lround(0.01 / dt_s));
    World3d w = scenes::settled_s3d_wall_3d(def);
    LedgerBreakdown tally;
    const double residual_at_start_j = w.ledger.residual_j();
    std::vector<ContactPoint3d> before = w.contacts;
    const auto steps = std::lround(shaking_s / dt_s);
    for (long k = 0; k < steps; ++k) {
        step_3d(w);
        tally_jumps(w.contact, before, w.contacts, tally);
        before = w.contacts;
    }
    tally.residual_j = w.ledger.residual_j() - residual_at_start_j;
    tally.scale_j = w.ledger.scale_j();
    tally.balance_error = w.ledger.balance_error();
    return tally;
}

void print(double dt_s, const LedgerBreakdown& t) {
    std::printf("dt %.1e s: residual %.4e J of scale %.4e J (balance error %.3e); (a) born %.4e J (%ld points), "
                "(b) gone %.4e J, (c) shear gone %.4e J (%ld points); (a)-(b)-(c) %.4e J; (d) rest %.4e J; "
                "(a)-(b) where the count changed %.4e J (%ld of %ld pair-steps); share changes %.4e J (|.| %.4e J)\n",
                dt_s, t.residual_j, t.scale_j, t.balance_error, t.born_normal_j, t.born_points, t.gone_normal_j,
                t.gone_shear_j, t.gone_points, t.jumps_j(), t.rest_j(), t.count_changed_normal_j, t.count_changes,
                t.pair_steps, t.share_change_j, t.share_change_abs_j);
}

// A 200-brick wall (7 courses), 0.1 s of shaking at two steps. Measured (docs/3d.md), the courses
// placed at their static compression (scenes/s3d_wall_3d.cpp): balance error 2.4e-3 at 1e-4 s and
// 1.5e-3 at 5e-5 s; the share changes -0.0098 and -0.0121 J (0.15 % and 0.18 % of the ledger's
// scale); the born and gone points' net 0.010 and 0.012 J of 1.45 and 1.33 J born (nearly all
// relabelled points at the same place). Placed touching (before), the courses fell onto each
// other in the settling and rang: 4.2e-3 and 3.2e-3, share changes 0.65 % and 0.68 %.
TEST(WallLedger3d, ShakenWallLedgerCloses) {
    constexpr int bricks = 200;
    constexpr double shaking_s = 0.1;
    const LedgerBreakdown coarse = shaken_wall(bricks, 1e-4, shaking_s);
    const LedgerBreakdown fine = shaken_wall(bricks, 5e-5, shaking_s);
    print(1e-4, coarse);
    print(5e-5, fine);
    for (const LedgerBreakdown* t : {&coarse, &fine}) {
        // Closed to the run's own warning ratio (io/run_checks.hpp, energy_warning_ratio = 0.01):
        // a run below it is not flagged. It is not the scheme's 1e-4..1e-3 of one body, because
        // (e) is a property of the model, not of dt: it is asserted on its own below.
        EXPECT_LT(t->balance_error, 0.01);
        // (e), unbooked: a share changes while loaded only where the polygon's shape changes at a
        // loaded corner (two corners at one place splitting their turn anew, a cut moving); it
        // goes both ways and nets below 1 % of the scale (measured 0.15 % and 0.18 %).
        EXPECT_LT(std::abs(t->share_change_j), 0.01 * t->scale_j);
        // The points born and gone no longer carry energy in or out: their net is below 1 % of the
        // scale (measured 0.16 % and 0.18 %; it was 9.4 % and 10 % with a full kn a point), while
        // each of (a) and (b) is about 60 % of it (keys change, the springs at the same place).
        EXPECT_LT(std::abs(t->born_normal_j - t->gone_normal_j), 0.01 * t->scale_j);
        // The shear springs restarted by key changes: below 0.5 % of the scale (measured 0.04 %).
        EXPECT_LT(t->gone_shear_j, 0.005 * t->scale_j);
    }
    // Halving dt does not make it worse (measured 0.0147 and 0.0088 J): what is left is the
    // model's share changes and relabelling, not an error that grows as the step falls.
    EXPECT_LT(std::abs(fine.residual_j), 1.25 * std::abs(coarse.residual_j));
}

}  // namespace
}  // namespace blockdem
