// The 3-D step on issue 15's scene: a brick wall of boxes (running bond, two wythes) on a shaken
// base (scenes/brick_wall_3d.hpp), box-steps/s at the thread count given as the second argument,
// and bytes per box. Never asserted on time.
#include <benchmark/benchmark.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "scenes/brick_wall_3d.hpp"
#include "world/step_3d.hpp"

namespace {

using namespace blockdem;

void BM_BrickWall3d(benchmark::State& state) {
    const int boxes = static_cast<int>(state.range(0));
#ifdef _OPENMP
    omp_set_num_threads(static_cast<int>(state.range(1)));
#endif
    // 2 wythes of bricks_per_course, courses high: 1e3 boxes as 10 x 2 x 50, 1e4 as 25 x 2 x 200.
    scenes::BrickWall3dDef def;
    def.courses = boxes >= 10000 ? 25 : 10;
    def.bricks_per_course = boxes / (2 * def.courses);
    World3d w = scenes::brick_wall_3d(def);
    for (int i = 0; i < 200; ++i) step_3d(w);  // warm-up: the wall settles into its springs
    for (auto _ : state) step_3d(w);
    const double n = static_cast<double>(w.bodies.size() - 1);
    using benchmark::Counter;
    state.counters["box-steps/s"] = Counter(static_cast<double>(state.iterations()) * n, Counter::kIsRate);
    state.counters["points/box"] = static_cast<double>(w.contacts.size()) / n;
    state.counters["bytes/box"] = static_cast<double>(memory_bytes(w)) / n;
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
}
BENCHMARK(BM_BrickWall3d)
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->Args({10000, 1})
    ->Args({10000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
