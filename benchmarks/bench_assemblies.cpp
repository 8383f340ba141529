// The step on the benchmark scenes of issue 5 (make bench): the S3 brick wall (and its keyed
// variant of concave bricks), a jointed rock slope and a Voronoi rockfill, with block-steps/s,
// contact-steps/s and the phase split as counters. `blockdem bench` (docs/performance.md) runs the same scenes with repeats, thread
// counts and a markdown table; this file keeps them in the Google Benchmark suite. Never
// asserted on time.
#include <benchmark/benchmark.h>

#include "scenes/assemblies.hpp"
#include "world/step.hpp"

namespace {

using namespace blockdem;

void run(benchmark::State& state, World w) {
    for (int i = 0; i < 5; ++i) step(w);  // warm-up: caches, first contacts
    w.timings = StepTimings{};
    w.timings.enabled = true;
    for (auto _ : state) step(w);
    std::size_t points = 0;
    for (const PairContact& pair : w.contacts) points += pair.count;
    const double blocks = static_cast<double>(w.bodies.size() - 1);
    const double steps = static_cast<double>(state.iterations());
    using benchmark::Counter;
    state.counters["block-steps/s"] = Counter(steps * blocks, Counter::kIsRate);
    state.counters["contact-steps/s"] = Counter(steps * static_cast<double>(points), Counter::kIsRate);
    const StepTimings& t = w.timings;
    const double total = t.geometry_s + t.broad_phase_s + t.contacts_s + t.bodies_s + t.positions_s;
    state.counters["contacts%"] = 100.0 * t.contacts_s / total;
    state.counters["bodies%"] = 100.0 * t.bodies_s / total;
    state.counters["bytes/block"] = static_cast<double>(memory_bytes(w)) / blocks;
}

void BM_S3Wall(benchmark::State& state) {
    run(state, build_world(scenes::s3_wall_scene(static_cast<int>(state.range(0)), 1e9)));
}
BENCHMARK(BM_S3Wall)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// S3 of concave keyed bricks (5 convex parts each; docs/performance.md, "Concave bodies").
void BM_KeyedWall(benchmark::State& state) {
    run(state, build_world(scenes::keyed_wall_scene(static_cast<int>(state.range(0)), 1e9)));
}
BENCHMARK(BM_KeyedWall)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

// S3 with every joint bonded (per-length stiffness, cohesion, tension; docs/performance.md, "Joints").
void BM_BondedWall(benchmark::State& state) {
    run(state, build_world(scenes::bonded_wall_scene(static_cast<int>(state.range(0)), 1e9)));
}
BENCHMARK(BM_BondedWall)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_RockSlope(benchmark::State& state) {
    run(state, build_world(scenes::rock_slope_scene(static_cast<int>(state.range(0)), 1e9)));
}
BENCHMARK(BM_RockSlope)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_VoronoiRockfill(benchmark::State& state) {
    run(state, build_world(scenes::rockfill_scene(static_cast<int>(state.range(0)), 1e9)));
}
BENCHMARK(BM_VoronoiRockfill)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
