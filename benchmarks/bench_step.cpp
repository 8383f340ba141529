// Steps per second of the whole time step (make bench). Never asserted in tests.
#include <benchmark/benchmark.h>

#include "laws/restitution.hpp"
#include "scenes/basic_scenes.hpp"
#include "world/step.hpp"

namespace {

using namespace blockdem;

void BM_SingleBlockSliding(benchmark::State& state) {
    World w = build_world(scenes::paper_sliding(1.0, 1e9));
    for (auto _ : state) step(w);
    state.counters["steps/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SingleBlockSliding);

void BM_BlockStack(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const ContactParameters c{.kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.6, .h_n = damping_ratio_paper(0.4), .h_s = 1.0};
    World w = build_world(scenes::block_stack(n, 0.4, 0.2, 2400.0, c, 1e9));
    for (auto _ : state) step(w);
    state.counters["steps/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["block-steps/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * n, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BlockStack)->Arg(10)->Arg(100);

}  // namespace
