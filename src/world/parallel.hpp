#pragma once
// How the step uses threads (OpenMP), and the rule that keeps the results bit-identical
// whatever the number of threads (docs/performance.md, "Determinism"):
//   1. a parallel loop writes only to its own item's slots (a body's state, a pair's points,
//      a pair's force slot); it never adds into a shared total;
//   2. a body's force is the sum of its pairs' slots, visited in contact-table order, so each
//      body's sum has the same terms in the same order as the serial loop had;
//   3. a total over items (an energy) is summed in fixed chunks whose partial sums are then
//      added in chunk order: the chunking depends on the item count only (at least
//      min_sum_chunk items, at most max_sum_chunks chunks), never on the thread count.
// Loops shorter than parallel_threshold run serially: starting threads costs microseconds,
// more than a small scene's whole step.
#include <algorithm>
#include <cstddef>

namespace blockdem {

inline constexpr std::ptrdiff_t parallel_threshold = 2048;
inline constexpr std::ptrdiff_t min_sum_chunk = 1024;
inline constexpr std::ptrdiff_t max_sum_chunks = 1024;

/// Calls body(i) for i < n, on all threads when n is large (body must follow rule 1). Small
/// loops never enter OpenMP: even a parallel region that runs on one thread costs about a
/// microsecond, which is most of a step for a scene of a few blocks.
template <class Body>
void parallel_for(std::ptrdiff_t n, Body body) {
    if (n < parallel_threshold) {
        for (std::ptrdiff_t i = 0; i < n; ++i) body(i);
        return;
    }
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) body(i);
}

/// sum_{i < n} term(i), in the chunked order of rule 3 (parallel over chunks when n is large).
template <class Term>
double deterministic_sum(std::ptrdiff_t n, Term term) {
    const std::ptrdiff_t chunk = std::max(min_sum_chunk, (n + max_sum_chunks - 1) / max_sum_chunks);
    const std::ptrdiff_t chunks = (n + chunk - 1) / chunk;
    if (chunks <= 1) {
        double s = 0.0;
        for (std::ptrdiff_t i = 0; i < n; ++i) s += term(i);
        return s;
    }
    double partial[max_sum_chunks];  // on the stack: the step allocates nothing
    parallel_for(n >= parallel_threshold ? chunks : 0, [&](std::ptrdiff_t c) {
        double s = 0.0;
        const std::ptrdiff_t end = std::min(n, (c + 1) * chunk);
        for (std::ptrdiff_t i = c * chunk; i < end; ++i) s += term(i);
        partial[c] = s;
    });
    double total = 0.0;
    for (std::ptrdiff_t c = 0; c < chunks; ++c) total += partial[c];
    return total;
}

}  // namespace blockdem
