// Thread determinism (world/parallel.hpp): the state after N steps is bit-identical at 1 and 2
// threads. The wall is large enough (2100 bricks, about 5000 pairs) that every parallel loop
// really runs on threads, is shaken so that contacts slide and open, and has its broad-phase
// margin cut to 10 um so that the candidate pairs are rebuilt many times on the way.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "scenes/assemblies.hpp"
#include "world/parallel.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// FNV-1a over the bytes of the state: positions, rotations, velocities, contact history.
struct StateHash {
    std::uint64_t h = 1469598103934665603ull;
    template <class T>
    void add(const T& value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    }
};

std::uint64_t hash_after(int threads, int steps, std::int64_t& rebuilds) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    Model m = scenes::s3_wall_scene(2100, 1.0, 1e-4);
    m.table_motion.horizontal = SineMotion{0.8 * 9.81, 0.5, 0.0, 0.0, 0.0};  // past sliding: contacts slip
    World w = build_world(m);
    w.broad_phase_margin_m = 1e-5;
    for (int i = 0; i < steps; ++i) step(w);
    StateHash hash;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        hash.add(w.bodies.position_m[i]);
        hash.add(w.bodies.rotation_rad[i]);
        hash.add(w.bodies.velocity_m_s[i]);
        hash.add(w.bodies.angular_velocity_rad_s[i]);
    }
    for (const PairContact& pair : w.contacts)
        for (std::uint32_t k = 0; k < pair.count; ++k) hash.add(pair.points[k].shear_spring_n);
    hash.add(w.energy.kinetic_j);
    hash.add(w.energy.friction_j);
    rebuilds = w.broad_phase_rebuilds;
    EXPECT_GT(w.contacts.size(), static_cast<std::size_t>(parallel_threshold));
    EXPECT_GT(w.bodies.size(), static_cast<std::size_t>(parallel_threshold));
    return hash.h;
}

TEST(Determinism, SameStateAtOneAndTwoThreads) {
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#endif
    std::int64_t rebuilds_1 = 0;
    std::int64_t rebuilds_2 = 0;
    const std::uint64_t one = hash_after(1, 150, rebuilds_1);
    const std::uint64_t two = hash_after(2, 150, rebuilds_2);
    EXPECT_GE(rebuilds_1, 5);  // the build's, and several during the run
    EXPECT_EQ(rebuilds_1, rebuilds_2);
    EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace blockdem
