// The 3-D step's gather of the pairs' sums onto the bodies (world/step_3d.cpp): each body walks
// its candidate pairs, indexed by body only when the candidates change, and takes those in contact
// this step. Checked against the plain sum, one pass over the table in its order adding each pair
// onto its two bodies, on a loose scene: turned boxes whose bounding boxes overlap where the boxes
// do not (more candidates than pairs in contact), falling onto a slab, some past its edge and out
// of the model mid-run (the candidates change as the skin list is rebuilt and as bodies are taken
// out). The same terms in the same order: the same bits, so the comparison is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "dynamics/rigid_body_3d.hpp"
#include "geometry/polyhedron.hpp"
#include "geometry/quaternion.hpp"
#include "world/model_domain_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

constexpr double g_m_s2 = 9.81;

// nx x ny x nz boxes of 0.2 x 0.15 x 0.1 m, each turned about its own axis, centres 0.24 m apart
// (their bounding boxes overlap their neighbours', the boxes mostly not), above a fixed 1 m slab
// under the first half of the grid in x; the boxes past the slab's edge are thrown down at
// throw_m_s, so that they leave the model's extent (0.3 m below the slab's top) while the others
// land.
World3d loose_boxes(int nx, int ny, int nz, double throw_m_s) {
    World3d w;
    w.contact = ContactParameters{.kn_N_m = 1e7, .ks_N_m = 1e7, .mu = 0.5, .h_n = 0.2, .h_s = 0.2};
    w.dt_s = 2e-4;
    w.duration_s = 1.0;
    const double spacing_m = 0.24;
    const double slab_m = 0.5 * nx * spacing_m;
    add_body(w, make_rigid_body_3d("slab", box_vertices({slab_m, ny * spacing_m, 0.2}, {0.5 * slab_m, 0.5 * ny * spacing_m, -0.1}), 2500.0),
             BodyKind3d::fixed);
    int k = 0;
    for (int iz = 0; iz < nz; ++iz) {
        for (int iy = 0; iy < ny; ++iy) {
            for (int ix = 0; ix < nx; ++ix, ++k) {
                const Vec3 centre_m{(ix + 0.5) * spacing_m, (iy + 0.5) * spacing_m, 0.1 + iz * spacing_m};
                const Vec3 axis{std::sin(1.3 * k), std::cos(0.7 * k), 0.5};
                const Quaternion turn = from_rotation_vector((0.6 / std::sqrt(dot(axis, axis))) * axis);
                RigidBody3d b = make_rigid_body_3d("box", box_vertices({0.2, 0.15, 0.1}, centre_m, turn), 2500.0);
                if (centre_m.x > slab_m) b.velocity_m_s = {0.0, 0.0, -throw_m_s};
                add_body(w, std::move(b), BodyKind3d::dynamic);
            }
        }
    }
    init_model_domain_3d(w, Aabb3d{{-0.5, -0.5, -0.3}, {nx * spacing_m + 0.5, ny * spacing_m + 0.5, 10.0}});
    return w;
}

// The plain sum after step_begin: gravity, then every pair in the table's order onto its two
// bodies (the force on b, minus it on a; the moment about b's centroid is the one about a's plus
// (x_a - x_b) x F), compared with what the step left in each body, to the bit.
void expect_the_plain_sums(const World3d& w, int step) {
    const WorldScratch3d& s = w.scratch;
    std::vector<Vec3> force_n(w.bodies.size());
    std::vector<Vec3> torque_n_m(w.bodies.size());
    for (std::size_t i = 0; i < w.bodies.size(); ++i) force_n[i] = {0.0, 0.0, -w.gravity_m_s2 * w.bodies[i].mass_kg};
    for (const ContactPairSums3d& pair : s.contact_pairs) {
        const auto [a, b] = s.pairs[pair.candidate];
        force_n[b] += pair.force_n;
        torque_n_m[b] += pair.torque_about_a_n_m + cross(w.bodies[a].position_m - w.bodies[b].position_m, pair.force_n);
        force_n[a] -= pair.force_n;
        torque_n_m[a] -= pair.torque_about_a_n_m;
    }
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const RigidBody3d& body = w.bodies[i];
        ASSERT_TRUE(body.force_n.x == force_n[i].x && body.force_n.y == force_n[i].y && body.force_n.z == force_n[i].z &&
                    body.torque_n_m.x == torque_n_m[i].x && body.torque_n_m.y == torque_n_m[i].y &&
                    body.torque_n_m.z == torque_n_m[i].z)
            << "body " << i << " at step " << step;
    }
}

struct GatherRun {
    std::size_t most_candidates_apart = 0;  ///< the most candidates not in contact at one step
    std::size_t most_candidates = 0;        ///< the most candidates at one step
    std::size_t left = 0;                   ///< bodies taken out
    std::int64_t rebuilds = 0;              ///< skin list rebuilds
    std::size_t pairs_in_contact = 0;       ///< at the last step
};

GatherRun run_and_compare(World3d& w, int steps) {
    GatherRun r;
    for (int step = 0; step < steps; ++step) {
        step_begin(w);
        expect_the_plain_sums(w, step);
        if (::testing::Test::HasFatalFailure()) return r;
        const std::size_t apart = w.scratch.pairs.size() - w.scratch.contact_pairs.size();
        r.most_candidates_apart = std::max(r.most_candidates_apart, apart);
        r.most_candidates = std::max(r.most_candidates, w.scratch.pairs.size());
        step_end(w);
    }
    r.left = w.domain.left.size();
    r.rebuilds = w.scratch.broad_phase.rebuilds();
    r.pairs_in_contact = w.scratch.contact_pairs.size();
    return r;
}

TEST(PairSumsGather3d, GivesThePlainSumOnALooseSceneWithBodiesTakenOut) {
    World3d w = loose_boxes(8, 3, 2, 5.0);  // 48 boxes: candidates below parallel_threshold, one chunk
    const GatherRun r = run_and_compare(w, 1500);
    // Measured: 22 to 58 candidates a step, 0 to 10 of them in contact, 24 boxes out from step
    // 450 on, 112 rebuilds.
    EXPECT_GT(r.most_candidates_apart, 20u);
    EXPECT_GT(r.left, 10u);
    EXPECT_GT(r.rebuilds, 50);
    EXPECT_GT(r.pairs_in_contact, 5u);
}

TEST(PairSumsGather3d, GivesThePlainSumWithTheCandidatesInChunks) {
    // 2304 boxes: candidates above parallel_threshold (64 chunks) over the first steps, the
    // skin list rebuilt every step (the thrown boxes move 16 mm a step, the skin is 1 cm), the
    // lowest thrown ones out from about step 33. Measured: up to 2391 candidates, 2308 of them
    // apart, 145 boxes out, 45 rebuilds.
    World3d w = loose_boxes(24, 12, 8, 80.0);
    const GatherRun r = run_and_compare(w, 45);
    EXPECT_GT(r.most_candidates, 2048u);
    EXPECT_GT(r.most_candidates_apart, 1000u);
    EXPECT_GT(r.left, 50u);
    EXPECT_GT(r.rebuilds, 30);
}

}  // namespace
}  // namespace blockdem
