// The 3-D step's one pass over the candidates' chunks (world/step_3d.cpp, find_contacts): a chunk's
// runs of the contact table are filled and take the law as soon as its place is known, while the
// narrow phase of the chunks after it still runs. It must give the table, forces and ledger of
// the plain passes (every chunk's narrow phase, then the whole layout, then every fill and law:
// WorldScratch3d::fill_as_placed off), step by step, however the chunks' counts change: a wall
// shaken off its base, bodies taken out, a table replaced by a shorter one (the room made for the
// table is then too small and the chunks beyond it are filled after the layout), one chunk, 64, or
// more (a chunk for every WorldScratch3d::candidates_per_chunk candidates past 64 chunks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "scenes/brick_wall_3d.hpp"
#include "world/step_3d.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace blockdem {
namespace {

template <class T>
bool same_bytes(const T& x, const T& y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// The first difference between the two worlds' state after a step, or "" when there is none:
// the bodies' motion and forces, every point of the table with its history and force, every
// pair's sums, and the ledger, to the bit.
std::string first_difference(const World3d& a, const World3d& b) {
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        const RigidBody3d& p = a.bodies[i];
        const RigidBody3d& q = b.bodies[i];
        if (!same_bytes(p.position_m, q.position_m) || !same_bytes(p.orientation, q.orientation) ||
            !same_bytes(p.velocity_m_s, q.velocity_m_s) ||
            !same_bytes(p.angular_momentum_kg_m2_s, q.angular_momentum_kg_m2_s) ||
            !same_bytes(p.force_n, q.force_n) || !same_bytes(p.torque_n_m, q.torque_n_m))
            return "body " + std::to_string(i);
    }
    if (a.contacts.size() != b.contacts.size()) return "the number of points";
    for (std::size_t k = 0; k < a.contacts.size(); ++k) {
        const ContactPoint3d& p = a.contacts[k];
        const ContactPoint3d& q = b.contacts[k];
        if (!same_bytes(p.key, q.key) || !same_bytes(p.point_m, q.point_m) || !same_bytes(p.normal, q.normal) ||
            !same_bytes(p.overlap_m, q.overlap_m) || !same_bytes(p.stiffness_share, q.stiffness_share) ||
            !same_bytes(p.normal_dashpot_n, q.normal_dashpot_n) ||
            !same_bytes(p.shear, q.shear) || p.sliding != q.sliding || !same_bytes(p.force_n, q.force_n))
            return "point " + std::to_string(k);
    }
    const std::vector<ContactPairSums3d>& pa = a.scratch.contact_pairs;
    const std::vector<ContactPairSums3d>& pb = b.scratch.contact_pairs;
    if (pa.size() != pb.size()) return "the number of pairs";
    for (std::size_t k = 0; k < pa.size(); ++k)
        if (pa[k].candidate != pb[k].candidate || pa[k].first_point != pb[k].first_point ||
            pa[k].points != pb[k].points || !same_bytes(pa[k].dashpot_mass_per_share_kg, pb[k].dashpot_mass_per_share_kg) ||
            !same_bytes(pa[k].force_n, pb[k].force_n) || !same_bytes(pa[k].torque_about_a_n_m, pb[k].torque_about_a_n_m))
            return "pair " + std::to_string(k);
    if (!same_bytes(a.ledger, b.ledger)) return "the ledger";
    return "";
}

// What a run of the two worlds side by side saw.
struct TwinRun {
    int steps_compared = 0;
    int steps_differing = 0;
    int count_changes = 0;           ///< steps whose number of points differs from the step before
    int steps_on_one_chunk = 0;
    int steps_on_64_chunks = 0;
    int steps_on_more_chunks = 0;    ///< steps with more than 64 chunks
    int steps_miscounted = 0;        ///< steps on several chunks whose number is not max(64, candidates / per chunk)
    std::size_t chunk_steps = 0;     ///< chunks summed over the steps
    std::size_t one_pass_late = 0;   ///< chunks the one pass filled after the layout, all steps
    std::size_t plain_late = 0;      ///< likewise in the plain world
    std::size_t late_after_short_table = 0;  ///< the one pass's late chunks the step after the short table
    int steps_not_all_given_back = 0;  ///< steps after which a point buffer was still lent, or given back twice
    std::size_t most_buffers_held = 0; ///< the most point buffers holding memory after a one-pass step
};

// Whether every point buffer of the pool is free after a step, each once.
bool all_given_back(const WorldScratch3d& s) {
    std::vector<std::uint32_t> free = s.free_point_buffers;
    std::sort(free.begin(), free.end());
    if (free.size() != s.point_buffers.size()) return false;
    for (std::size_t i = 0; i < free.size(); ++i)
        if (free[i] != i) return false;
    return true;
}

std::size_t buffers_held(const WorldScratch3d& s) {
    std::size_t held = 0;
    for (const auto& b : s.point_buffers) held += b.capacity() > 0;
    return held;
}

// Steps a world with the one pass and its copy with the plain passes, alike, for steps steps:
// take_out_at takes a few of the top bodies out of both; shorten_at replaces both tables with
// their first half (a state file with fewer contacts), keep_at with a copy of themselves (the
// ranks' hints are dropped).
TwinRun run_twins(World3d one_pass, int steps, int take_out_at, int shorten_at, int keep_at) {
    World3d plain = one_pass;
    plain.scratch.fill_as_placed = false;
    TwinRun run;
    std::size_t points_before = 0;
    for (int i = 0; i < steps; ++i) {
        if (i == take_out_at) {
            for (World3d* w : {&one_pass, &plain}) {
                w->domain.taken_out.assign(w->bodies.size(), 0);
                for (std::uint32_t b = static_cast<std::uint32_t>(w->bodies.size()) - 5; b < w->bodies.size(); ++b)
                    take_out(*w, b);
            }
        }
        if (i == shorten_at || i == keep_at) {
            for (World3d* w : {&one_pass, &plain}) {
                std::vector<ContactPoint3d> table = w->contacts;
                if (i == shorten_at) table.resize(table.size() / 2);
                replace_contacts(*w, std::move(table));
            }
        }
        step_3d(one_pass);
        step_3d(plain);
        ++run.steps_compared;
        const std::string difference = first_difference(one_pass, plain);
        if (!difference.empty()) {
            if (run.steps_differing == 0) ADD_FAILURE() << "step " << i << ": " << difference << " differs";
            ++run.steps_differing;
        }
        if (i > 0 && one_pass.contacts.size() != points_before) ++run.count_changes;
        points_before = one_pass.contacts.size();
        const std::size_t chunks = one_pass.scratch.chunk_pairs.size() - 1;
        run.steps_on_one_chunk += chunks == 1;
        run.steps_on_64_chunks += chunks == 64;
        run.steps_on_more_chunks += chunks > 64;
        const std::size_t per_chunk = one_pass.scratch.candidates_per_chunk;
        const std::size_t candidates = one_pass.scratch.pairs.size();
        run.steps_miscounted += chunks > 1 && chunks != std::max<std::size_t>(64, (candidates + per_chunk - 1) / per_chunk);
        run.chunk_steps += chunks;
        run.one_pass_late += one_pass.scratch.chunks_filled_late;
        run.plain_late += plain.scratch.chunks_filled_late;
        if (i == shorten_at) run.late_after_short_table = one_pass.scratch.chunks_filled_late;
        run.steps_not_all_given_back += !all_given_back(one_pass.scratch) || !all_given_back(plain.scratch);
        run.most_buffers_held = std::max(run.most_buffers_held, buffers_held(one_pass.scratch));
    }
    return run;
}

// A wall on a base shaken at 1.5 g, well above mu g (0.6 g): it slides and rocks on its base and
// its joints open and close, so the chunks' counts change from step to step.
World3d shaken_wall(int courses, int bricks_per_course) {
    scenes::BrickWall3dDef def;
    def.courses = courses;
    def.bricks_per_course = bricks_per_course;
    def.shaking = SineMotion{15.0, 0.02, 0.0, 0.0, 0.0};
    return scenes::brick_wall_3d(def);
}

TEST(StepChunks3d, OnePassIsThePlainPassesStepByStepFromOneChunkTo64) {
    // 640 bricks: the candidates pass 2048 (one chunk to 64) at about step 155 as the wall settles
    // into its base and rocks; the bodies are taken out on one chunk, the short table read on 64.
#ifdef _OPENMP
    const int threads_before = omp_get_max_threads();
    omp_set_num_threads(2);  // chunks placed and filled by the thread that finds the chunk before them
#endif
    const TwinRun run = run_twins(shaken_wall(8, 40), 200, 60, 190, 120);
#ifdef _OPENMP
    omp_set_num_threads(threads_before);
#endif
    std::printf("640 bricks, 200 steps: %d on one chunk, %d on 64, %d changes of the points' number; chunks "
                "filled late: %zu of %zu (one pass), %zu (plain); %zu after the short table\n",
                run.steps_on_one_chunk, run.steps_on_64_chunks, run.count_changes, run.one_pass_late,
                run.chunk_steps, run.plain_late, run.late_after_short_table);
    EXPECT_EQ(run.steps_differing, 0);
    EXPECT_GT(run.steps_on_one_chunk, 0);
    EXPECT_GT(run.steps_on_64_chunks, 0);
    EXPECT_GT(run.count_changes, 20);
    // The plain world fills every chunk after the layout; the one pass only its first step's (no
    // table before it: no room), those past the room after the short table, and those of the few
    // steps that outgrow the room while the wall beds in (measured: 81 of 2027 chunks).
    EXPECT_EQ(run.plain_late, run.chunk_steps);
    EXPECT_GT(run.late_after_short_table, 0u);
    EXPECT_LT(run.late_after_short_table, 64u);
    EXPECT_GE(run.one_pass_late, 1u + run.late_after_short_table);
    EXPECT_LT(run.one_pass_late, run.chunk_steps / 20);
    // The chunks' points wait in a few buffers lent in turn (two a thread kept), all given back
    // by the step's end, also after the steps that lent every chunk its own.
    EXPECT_EQ(run.steps_not_all_given_back, 0);
    EXPECT_GE(run.most_buffers_held, 1u);
    EXPECT_LE(run.most_buffers_held, 4u);
}

TEST(StepChunks3d, OnePassIsThePlainPassesStepByStepOnMoreThan64Chunks) {
    // The same wall with a chunk for every 6 candidates: some 350 chunks once it passes 2048 (more
    // than a byte counts).
#ifdef _OPENMP
    const int threads_before = omp_get_max_threads();
    omp_set_num_threads(2);
#endif
    World3d wall = shaken_wall(8, 40);
    wall.scratch.candidates_per_chunk = 6;
    const TwinRun run = run_twins(wall, 200, 60, 190, 120);
#ifdef _OPENMP
    omp_set_num_threads(threads_before);
#endif
    std::printf("640 bricks, 6 candidates a chunk: %d steps on one chunk, %d on more than 64; chunks filled late: "
                "%zu of %zu (one pass); %zu after the short table\n",
                run.steps_on_one_chunk, run.steps_on_more_chunks, run.one_pass_late, run.chunk_steps,
                run.late_after_short_table);
    EXPECT_EQ(run.steps_differing, 0);
    EXPECT_GT(run.steps_on_one_chunk, 0);
    EXPECT_GT(run.steps_on_more_chunks, 20);
    EXPECT_EQ(run.steps_miscounted, 0);
    EXPECT_EQ(run.plain_late, run.chunk_steps);
    EXPECT_GT(run.late_after_short_table, 64u);
    EXPECT_LT(run.one_pass_late, run.chunk_steps / 20);
    EXPECT_EQ(run.steps_not_all_given_back, 0);
    EXPECT_LE(run.most_buffers_held, 4u);
}

TEST(StepChunks3d, ManyChunksGiveTheSameBitsOnOneThreadAndTwo) {
#ifdef _OPENMP
    World3d one = shaken_wall(8, 40);
    one.scratch.candidates_per_chunk = 6;
    World3d two = one;
    const int threads_before = omp_get_max_threads();
    omp_set_num_threads(1);
    for (int i = 0; i < 200; ++i) step_3d(one);
    omp_set_num_threads(2);
    for (int i = 0; i < 200; ++i) step_3d(two);
    omp_set_num_threads(threads_before);
    EXPECT_GT(one.scratch.chunk_pairs.size(), 65u);
    EXPECT_EQ(first_difference(one, two), "");
#endif
}

TEST(StepChunks3d, OnePassIsThePlainPassesStepByStepOnOneChunk) {
    const TwinRun run = run_twins(shaken_wall(3, 8), 200, 60, 120, 160);
    EXPECT_EQ(run.steps_differing, 0);
    EXPECT_EQ(run.steps_on_one_chunk, 200);
    EXPECT_GT(run.count_changes, 20);
    EXPECT_EQ(run.plain_late, 200u);
    EXPECT_EQ(run.late_after_short_table, 1u);
    // The first step, the short table, and the steps whose table grew: a table of a few hundred
    // points has no room beyond last step's (measured: 35 of 200).
    EXPECT_GE(run.one_pass_late, 2u);
    EXPECT_LT(run.one_pass_late, 60u);
    EXPECT_EQ(run.steps_not_all_given_back, 0);
    EXPECT_EQ(run.most_buffers_held, 1u);
}

TEST(StepChunks3d, AStepInsideACallersParallelRegionIsTheSerialStep) {
#ifdef _OPENMP
    // One small wall (one chunk: the step opens no region of its own) for each thread of a caller's
    // loop of 4, the step's own regions at 1 thread: its serial parts run under the caller's thread
    // number, up to 3, which its per-thread scratch must cover (it was sized by the 1 thread).
    const World3d start = shaken_wall(3, 8);
    World3d serial = start;
    for (int i = 0; i < 20; ++i) step_3d(serial);
    std::vector<World3d> worlds(4, start);
    const int threads_before = omp_get_max_threads();
#pragma omp parallel for num_threads(4) schedule(static, 1)
    for (int k = 0; k < 4; ++k) {
        omp_set_num_threads(1);
        for (int i = 0; i < 20; ++i) step_3d(worlds[k]);
    }
    omp_set_num_threads(threads_before);
    for (std::size_t k = 0; k < worlds.size(); ++k) {
        EXPECT_EQ(first_difference(worlds[k], serial), "") << "world " << k;
        EXPECT_GE(worlds[k].scratch.clipping.size(), k + 1) << "world " << k;
        EXPECT_GE(worlds[k].scratch.thread_free_point_buffers.size(), k + 1) << "world " << k;
    }
#endif
}

}  // namespace
}  // namespace blockdem
