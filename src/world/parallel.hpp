#pragma once
// How the step uses threads (OpenMP), and the rule that keeps the results bit-identical
// whatever the number of threads (docs/performance.md, "Determinism"):
//   1. a parallel loop writes only to its own item's slots (a body's state, a pair's points,
//      a pair's force slot); it never adds into a shared total;
//   2. a body's force is the sum of its pairs' slots, visited in contact-table order, so each
//      body's sum has the same terms in the same order as the serial loop had;
//   3. a total over items (an energy) is summed in fixed chunks whose partial sums are then
//      added in chunk order: the chunking depends on the item count only (chunks of
//      run_length(n) items), never on the thread count.
// Loops shorter than parallel_threshold run serially: starting threads costs microseconds,
// more than a small scene's whole step.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <type_traits>

namespace blockdem {

inline constexpr std::ptrdiff_t parallel_threshold = 2048;
inline constexpr std::ptrdiff_t max_sum_chunks = 1024;

/// How many consecutive items a thread takes at a time, and the chunk of a sum (rule 3): a
/// function of the item count only. At least 16 runs to share out (a few runs of unequal cost
/// would leave a thread idle), but runs of 1024 items once there are enough: shorter runs cost
/// more at their edges (shared cache lines, broken prefetch streams) in a table larger than the
/// caches; and at most max_sum_chunks chunks.
constexpr std::ptrdiff_t run_length(std::ptrdiff_t n) {
    return std::max(std::clamp<std::ptrdiff_t>(n / 16, 256, 1024), (n + max_sum_chunks - 1) / max_sum_chunks);
}

/// Calls body(i) for i < n, on all threads when n is large (body must follow rule 1). Small
/// loops never enter OpenMP: even a parallel region that runs on one thread costs about a
/// microsecond, which is most of a step for a scene of a few blocks.
template <class Body>
void parallel_for(std::ptrdiff_t n, Body body) {
    if (n < parallel_threshold) {
        for (std::ptrdiff_t i = 0; i < n; ++i) body(i);
        return;
    }
    // Handed out in runs as threads free up: items differ in cost (a pair in contact costs
    // several times one that is apart, and those cluster: the lower rows of a wall), so equal
    // static halves would leave one thread waiting. Which thread runs an item never changes
    // what it computes (rule 1).
    [[maybe_unused]] const std::ptrdiff_t run = run_length(n);  // (unread in a build without OpenMP)
#pragma omp parallel for schedule(dynamic, run)
    for (std::ptrdiff_t i = 0; i < n; ++i) body(i);
}

/// parallel_for's schedule with the items given a run at a time: run(begin, end) for each run of
/// run_length(n) consecutive items (all n at once below parallel_threshold). For a loop whose
/// items are worked by a function compiled apart (world/vex_clones.hpp): one call a run, not an
/// item. Which thread takes a run never changes what it computes (rule 1).
template <class Run>
void parallel_for_runs(std::ptrdiff_t n, Run run) {
    if (n < parallel_threshold) {
        if (n > 0) run(std::ptrdiff_t{0}, n);
        return;
    }
    const std::ptrdiff_t length = run_length(n);
    const std::ptrdiff_t runs = (n + length - 1) / length;
#pragma omp parallel for schedule(dynamic)
    for (std::ptrdiff_t r = 0; r < runs; ++r) run(r * length, std::min(n, (r + 1) * length));
}

/// The chunked sum of rule 3, each chunk's sum made by chunk_sum(begin, end): deterministic_sum
/// below when it adds Value{} and the terms of begin .. end - 1 in order. Called directly for terms
/// worked by a function compiled apart (world/vex_clones.hpp): one call a chunk, not a term.
template <class ChunkSum>
auto deterministic_sum_of_chunks(std::ptrdiff_t n, ChunkSum chunk_sum) {
    using Value = std::decay_t<decltype(chunk_sum(std::ptrdiff_t{0}, std::ptrdiff_t{0}))>;
    const std::ptrdiff_t chunk = run_length(n);
    const std::ptrdiff_t chunks = (n + chunk - 1) / chunk;
    if (chunks <= 1) return n > 0 ? chunk_sum(std::ptrdiff_t{0}, n) : Value{};
    // On the stack: the step allocates nothing. Left uninitialised, each used slot constructed
    // by its chunk: a Value with default members, zeroed for all max_sum_chunks slots at every
    // call, was a 57 kB memset twice a step (1 % of a wall's step, docs/performance.md).
    union Slot {
        Slot() {}
        Value value;
    };
    Slot partial[max_sum_chunks];
    // The chunks, not the items, are shared out: their number is below parallel_threshold, so
    // this loop cannot go through parallel_for.
    if (n >= parallel_threshold) {
#pragma omp parallel for schedule(dynamic)
        for (std::ptrdiff_t c = 0; c < chunks; ++c)
            std::construct_at(&partial[c].value, chunk_sum(c * chunk, std::min(n, (c + 1) * chunk)));
    } else {
        for (std::ptrdiff_t c = 0; c < chunks; ++c)
            std::construct_at(&partial[c].value, chunk_sum(c * chunk, std::min(n, (c + 1) * chunk)));
    }
    Value total{};
    for (std::ptrdiff_t c = 0; c < chunks; ++c) total += partial[c].value;
    return total;
}

/// sum_{i < n} term(i), in the chunked order of rule 3 (parallel over chunks when n is large):
/// each chunk's terms added in order from Value{}. The value may be a double or a small struct
/// of totals with +=, summed member by member; a term may also write its own item's slots (rule
/// 1), so one pass can both update and total.
template <class Term>
auto deterministic_sum(std::ptrdiff_t n, Term term) {
    using Value = std::decay_t<decltype(term(std::ptrdiff_t{0}))>;
    return deterministic_sum_of_chunks(n, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
        Value s{};
        for (std::ptrdiff_t i = begin; i < end; ++i) s += term(i);
        return s;
    });
}

}  // namespace blockdem
