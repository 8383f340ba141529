// Why the 3-D energy ledger does not close on a shaken brick wall (issue 15, docs/3d.md "The
// ledger on a shaken wall"). On one body the ledger closes to the scheme's error; on the S3D wall
// it did not, and the error hardly fell with dt. A step's stored energy jumps, unbooked, when the
// narrow phase's points change: the residual's increment over a step is split here by cause,
// from the points of the step before and after (contact/contact_table_3d.hpp: a point is its key):
//   (a) points born with a finite overlap: their normal spring energy kn d^2 / 2 appears at once;
//   (b) points gone with a finite overlap: their kn d^2 / 2 (as it was the step before) vanishes;
//   (c) points gone with a loaded shear spring (a key change restarts it): its |s|^2 / (2 ks) vanishes;
//   (d) the rest: the scheme's own error (second order in dt), the dashpots' and the table's booking.
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
    return 0.5 * p.kn_N_m * c.overlap_m * c.overlap_m;
}

double shear_energy_j(const ContactParameters& p, const ContactPoint3d& c) {
    return p.ks_N_m > 0.0 ? 0.5 * dot(c.shear.spring_n, c.shear.spring_n) / p.ks_N_m : 0.0;
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
                "(a)-(b) where the count changed %.4e J (%ld of %ld pair-steps)\n",
                dt_s, t.residual_j, t.scale_j, t.balance_error, t.born_normal_j, t.born_points, t.gone_normal_j,
                t.gone_shear_j, t.gone_points, t.jumps_j(), t.rest_j(), t.count_changed_normal_j, t.count_changes,
                t.pair_steps);
}

// A 200-brick wall (7 courses), 0.1 s of shaking at two steps. Measured (docs/3d.md): balance
// error 0.10 at both; the jumps 80 % and 93 % of the residual; of the normal jumps' net, 99 % in
// pair-steps whose point count changed; the shear restarts 11 % and 10 %; the rest 2.0 % and
// 0.7 % of the ledger's scale. This pins the breakdown (it is not a fix): when the narrow phase's
// point count no longer flickers, the balance error must fall and these bounds be revisited.
TEST(WallLedger3d, PointCountFlickerAccountsForTheResidual) {
    constexpr int bricks = 200;
    constexpr double shaking_s = 0.1;
    const LedgerBreakdown coarse = shaken_wall(bricks, 1e-4, shaking_s);
    const LedgerBreakdown fine = shaken_wall(bricks, 5e-5, shaking_s);
    print(1e-4, coarse);
    print(5e-5, fine);
    for (const LedgerBreakdown* t : {&coarse, &fine}) {
        // The ledger is far from closed (a single body's closes to 1e-4..1e-3).
        EXPECT_GT(t->balance_error, 0.03);
        // The jumps account for the residual: to 25 % (measured 20 % at 1e-4 s, 7 % at 5e-5 s; the
        // rest is the clipped points' law and the scheme, which fall with dt).
        EXPECT_LT(std::abs(t->rest_j()), 0.25 * std::abs(t->residual_j));
        // The normal jumps are nearly all where a pair's point count changed (measured 99 %):
        // relabelled points (a reference switch, a corner changing feature) carry almost nothing.
        EXPECT_GT(t->count_changed_normal_j, 0.8 * (t->born_normal_j - t->gone_normal_j));
        // The shear springs restarted are a minor part (measured 11 % and 10 %).
        EXPECT_LT(t->gone_shear_j, 0.2 * t->residual_j);
        // Without the jumps the ledger closes to a few percent of its largest term.
        EXPECT_LT(std::abs(t->rest_j()), 0.03 * t->scale_j);
    }
    // Not the scheme's error: halving dt leaves the residual (measured 0.627 and 0.609 J).
    EXPECT_GT(fine.residual_j, 0.5 * coarse.residual_j);
}

}  // namespace
}  // namespace blockdem
