// The 3-D step on the peers' scene S3D (scenes/s3d_wall_3d.hpp: two-wythe running-bond wall of
// 0.2 x 0.1 x 0.1 m bricks on a base shaken out of plane, dt = 1e-4 s, 100 settling steps), so
// that our box-steps/s sit beside shared/peers/three_d/results.md. Arguments: bricks, threads.
// Counters: box-steps/s by the wall clock, box-steps per CPU second of the process (per core,
// what a loaded machine still measures), contact points and bytes per box. Never asserted on time.
#include <benchmark/benchmark.h>

#include <ctime>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "scenes/s3d_wall_3d.hpp"
#include "world/step_3d.hpp"

namespace {

using namespace blockdem;

double process_cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double wall_s() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_BrickWall3d(benchmark::State& state) {
#ifdef _OPENMP
    omp_set_num_threads(static_cast<int>(state.range(1)));
#endif
    scenes::S3dWallDef def;
    def.bricks = static_cast<int>(state.range(0));
    World3d w = scenes::settled_s3d_wall_3d(def);
    const double cpu_start_s = process_cpu_s();
    for (auto _ : state) step_3d(w);
    const double cpu_s = process_cpu_s() - cpu_start_s;
    const double n = static_cast<double>(w.bodies.size() - 1);
    const double box_steps = static_cast<double>(state.iterations()) * n;
    using benchmark::Counter;
    state.counters["box-steps/s"] = Counter(box_steps, Counter::kIsRate);
    state.counters["box-steps/cpu-s"] = box_steps / cpu_s;
    state.counters["points/box"] = static_cast<double>(w.contacts.size()) / n;
    state.counters["bytes/box"] = static_cast<double>(memory_bytes(w)) / n;
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
}
// A fixed number of steps for each size, so that one thread and two time the same steps: a step
// costs more as the shaking goes on (more points, more skin rebuilds; about 10 % from the first 100
// steps to the next 100 at 1e4), and a run of a set minimum time took twice the steps on two threads,
// the later ones, its ratio over one thread some 5 % low.
BENCHMARK(BM_BrickWall3d)->Args({1000, 1})->Args({1000, 2})->Iterations(1000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BrickWall3d)->Args({10000, 1})->Args({10000, 2})->Iterations(100)->Unit(benchmark::kMillisecond)->UseRealTime();
// 1e5 bricks: a few steps only (the settling alone is 1e7 box-steps).
BENCHMARK(BM_BrickWall3d)->Args({100000, 1})->Args({100000, 2})->Iterations(5)->Unit(benchmark::kMillisecond)->UseRealTime();

// What the machine gives two cores on this work, with nothing shared: two copies of the wall, each
// stepped by its own thread (its step's regions on one thread), the same steps as BM_BrickWall3d.
// Its box-steps/s over BM_BrickWall3d's one thread is the most two threads of one wall could reach
// here (a virtual machine's two vCPUs slow each other: shared cache, memory, the host's other guests),
// so the two threads' figure read against it is the step's own parallel loss. Counted when both
// copies are done: a copy that finishes first leaves the other the machine, which a per-copy sum
// would count as speed. Arguments: bricks, steps. At 1e4 only: two copies of a 1e5 wall hold 1.2 GB
// and contend for memory as one wall on two threads does not (they ran below it here), so they
// bound nothing there.
void BM_BrickWall3dCopies(benchmark::State& state) {
#ifdef _OPENMP
    omp_set_num_threads(1);
#endif
    scenes::S3dWallDef def;
    def.bricks = static_cast<int>(state.range(0));
    const auto steps = state.range(1);
    World3d first = scenes::settled_s3d_wall_3d(def);
    World3d second = first;
    // One step each before the clock: a copied world's scratch (vectors copied to their size, not
    // their capacity) grows again in its first step, which the original has done.
    step_3d(first);
    step_3d(second);
    const auto step_copy = [steps](World3d* w) {
#ifdef _OPENMP
        omp_set_num_threads(1);  // this thread's own setting: its step's regions run on it alone
#endif
        for (std::int64_t i = 0; i < steps; ++i) step_3d(*w);
    };
    for (auto _ : state) {
        std::thread a(step_copy, &first), b(step_copy, &second);
        a.join();
        b.join();
    }
    const double n = static_cast<double>(first.bodies.size() - 1);
    using benchmark::Counter;
    state.counters["box-steps/s"] = Counter(2.0 * static_cast<double>(state.iterations() * steps) * n, Counter::kIsRate);
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
}
// One thread and two on one wall, in alternating blocks of 10 steps (ABBA: 1, 2, 2, 1, ...): the
// host's speed here drifts by a third within seconds, so two separate runs' ratio (BM_BrickWall3d
// at 1 and at 2) is as much the host's as the step's; blocks of about 0.1 s each cancel that drift.
// Both thread counts give the same bits, so the wall moves on as one run would. Arguments: bricks,
// blocks (of each thread count). Counters: each thread count's box-steps/s and their ratio.
void BM_BrickWall3dAlternating(benchmark::State& state) {
    scenes::S3dWallDef def;
    def.bricks = static_cast<int>(state.range(0));
    const auto blocks = state.range(1);
    constexpr int steps_per_block = 10;
    World3d w = scenes::settled_s3d_wall_3d(def);
    double seconds[2] = {0.0, 0.0};
    for (auto _ : state) {
        for (std::int64_t b = 0; b < 2 * blocks; ++b) {
            const int two = static_cast<int>((b ^ (b >> 1)) & 1);  // 0, 1, 1, 0, 0, 1, 1, 0, ...
#ifdef _OPENMP
            omp_set_num_threads(two + 1);
#endif
            const double start_s = wall_s();
            for (int i = 0; i < steps_per_block; ++i) step_3d(w);
            seconds[two] += wall_s() - start_s;
        }
    }
    const double box_steps = static_cast<double>(state.iterations() * blocks * steps_per_block) *
                             static_cast<double>(w.bodies.size() - 1);
    state.counters["1t box-steps/s"] = box_steps / seconds[0];
    state.counters["2t box-steps/s"] = box_steps / seconds[1];
    state.counters["2t/1t"] = seconds[0] / seconds[1];
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
}
BENCHMARK(BM_BrickWall3dAlternating)->Args({10000, 20})->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BrickWall3dAlternating)->Args({100000, 2})->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK(BM_BrickWall3dCopies)->Args({10000, 100})->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
