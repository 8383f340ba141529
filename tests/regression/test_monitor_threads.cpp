// The response monitor's body loop runs on threads (world/parallel.hpp): what it keeps for every
// body must be bit-identical at 1 and 2 threads. The wall is the determinism test's (2100
// bricks, more than parallel_threshold, so the loop really is shared out), shaken past sliding
// so that contact points slide and bricks turn on their supports, during and after the support
// window (100 steps).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "scenes/assemblies.hpp"
#include "world/parallel.hpp"
#include "world/response_monitor.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// FNV-1a over the bytes of each value.
struct ResponseHash {
    std::uint64_t h = 1469598103934665603ull;
    template <class T>
    void add(const T& value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    }
};

struct Observed {
    std::uint64_t hash = 0;
    int sliding = 0;  ///< bodies with a contact point sliding on their supporters at some step
    int turned = 0;   ///< bodies turned on their support body
};

Observed observe_wall(int threads, int steps) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    Model m = scenes::s3_wall_scene(2100, 1.0, 1e-4);
    m.table_motion.horizontal = SineMotion{0.8 * 9.81, 0.5, 0.0, 0.0, 0.0};  // past sliding
    World w = build_world(m);
    ResponseMonitor monitor(w);
    for (int i = 0; i < steps; ++i) {
        step_begin(w);
        monitor.observe(w);
        step_end(w);
    }
    EXPECT_GT(w.bodies.size(), static_cast<std::size_t>(parallel_threshold));
    Observed out;
    ResponseHash hash;
    for (const BodyResponse& r : monitor.responses()) {
        for (double v : {r.peak_abs_rotation_rad, r.time_of_peak_rotation_s, r.last_crossing_s,
                         r.peak_abs_relative_displacement_m, r.relative_displacement_m.x, r.relative_displacement_m.y,
                         r.base_slip_m, r.peak_abs_base_slip_m, r.sliding_time_s, r.peak_abs_rotation_on_support_rad,
                         r.peak_elastic_shear_m, r.rocking_onset_s, r.slip_onset_s, r.support_lost_time_s, r.drop_time_s})
            hash.add(v);
        hash.add(r.support_body);
        hash.add(r.beyond_alpha);
        hash.add(r.touches_a_supporter);
        hash.add(r.at_rest);
        for (std::uint32_t s : r.supporters) hash.add(s);
        out.sliding += r.sliding_time_s > 0.0 ? 1 : 0;
        out.turned += r.peak_abs_rotation_on_support_rad > 0.0 ? 1 : 0;
    }
    out.hash = hash.h;
    return out;
}

TEST(ResponseMonitorThreads, SameResponsesAtOneAndTwoThreads) {
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#endif
    const Observed one = observe_wall(1, 150);
    const Observed two = observe_wall(2, 150);
    // The responses are not trivially equal: contact points slide, bricks turn on their supports.
    EXPECT_GT(one.sliding, 100) << one.sliding;
    EXPECT_GT(one.turned, 1000) << one.turned;
    EXPECT_EQ(one.hash, two.hash);
    EXPECT_EQ(one.sliding, two.sliding);
    EXPECT_EQ(one.turned, two.turned);
}

}  // namespace
}  // namespace blockdem
