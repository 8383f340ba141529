// The deterministic sum of world/parallel.hpp: right at every size (including the sizes between
// one chunk and the parallel threshold) and equal bit for bit at 1 and 2 threads; its form by
// chunks and parallel_for's by runs (the 3-D step's body loops).
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "world/parallel.hpp"

namespace blockdem {
namespace {

struct Totals {
    double first = 0.0;
    double second = 0.0;
    Totals& operator+=(const Totals& o) {
        first += o.first;
        second += o.second;
        return *this;
    }
};

// Terms of very different sizes, so that a different summation order changes the last bits.
double term_value(std::ptrdiff_t i) { return std::ldexp(1.0 + 0.37 * static_cast<double>(i % 11), static_cast<int>(i % 40) - 20); }

void set_threads(int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
}

TEST(DeterministicSum, CountsEveryItemAtEverySize) {
    for (std::ptrdiff_t n : {0, 1, 1023, 1024, 1025, 1500, 2047, 2048, 2049, 5000, 1048576, 3000001}) {
        EXPECT_EQ(deterministic_sum(n, [](std::ptrdiff_t) { return 1.0; }), static_cast<double>(n)) << "n = " << n;
        const Totals t = deterministic_sum(n, [](std::ptrdiff_t i) { return Totals{1.0, static_cast<double>(i)}; });
        EXPECT_EQ(t.first, static_cast<double>(n)) << "n = " << n;
        EXPECT_EQ(t.second, 0.5 * static_cast<double>(n) * static_cast<double>(n - 1)) << "n = " << n;
    }
}

TEST(DeterministicSum, SameBitsAtOneAndTwoThreads) {
    for (std::ptrdiff_t n : {1500, 4096, 100000, 2000003}) {
        set_threads(1);
        const double one = deterministic_sum(n, term_value);
        set_threads(2);
        const double two = deterministic_sum(n, term_value);
        EXPECT_EQ(one, two) << "n = " << n;
        EXPECT_NEAR(one, [&] {
            long double exact = 0.0L;
            for (std::ptrdiff_t i = 0; i < n; ++i) exact += term_value(i);
            return static_cast<double>(exact);
        }(), 1e-12 * std::abs(one));
    }
}

TEST(DeterministicSum, TermsMayWriteTheirOwnSlots) {
    const std::ptrdiff_t n = 50000;
    std::vector<double> slots(static_cast<std::size_t>(n), 0.0);
    set_threads(2);
    const double total = deterministic_sum(n, [&](std::ptrdiff_t i) {
        slots[static_cast<std::size_t>(i)] = 2.0 * static_cast<double>(i);
        return 1.0;
    });
    EXPECT_EQ(total, static_cast<double>(n));
    for (std::ptrdiff_t i = 0; i < n; ++i) ASSERT_EQ(slots[static_cast<std::size_t>(i)], 2.0 * static_cast<double>(i));
}

// deterministic_sum_of_chunks with each chunk summed in order from Value{}: deterministic_sum's
// bits at every size, at 1 and 2 threads (terms of different sizes, so another order or another
// chunking would change the last bits).
TEST(DeterministicSumOfChunks, SameBitsAsDeterministicSum) {
    const auto chunk_sum = [](std::ptrdiff_t begin, std::ptrdiff_t end) {
        double s{};
        for (std::ptrdiff_t i = begin; i < end; ++i) s += term_value(i);
        return s;
    };
    for (int threads : {1, 2}) {
        set_threads(threads);
        for (std::ptrdiff_t n : {0, 1, 1023, 1025, 2047, 2048, 2049, 10001, 100000, 2000003}) {
            const double by_terms = deterministic_sum(n, term_value);
            const double by_chunks = deterministic_sum_of_chunks(n, chunk_sum);
            EXPECT_EQ(std::bit_cast<std::uint64_t>(by_terms), std::bit_cast<std::uint64_t>(by_chunks))
                << "n = " << n << ", threads " << threads;
        }
    }
}

// parallel_for_runs hands out every item once, in runs of consecutive items no longer than
// run_length(n) (one run below the parallel threshold).
TEST(ParallelForRuns, EveryItemOnceInRunsOfRunLength) {
    set_threads(2);
    for (std::ptrdiff_t n : {0, 1, 2047, 2048, 10001, 300001}) {
        std::vector<int> seen(static_cast<std::size_t>(n), 0);
        std::vector<std::ptrdiff_t> longest(static_cast<std::size_t>(n), 0);
        parallel_for_runs(n, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
            for (std::ptrdiff_t i = begin; i < end; ++i) {
                ++seen[static_cast<std::size_t>(i)];
                longest[static_cast<std::size_t>(i)] = end - begin;
            }
        });
        const std::ptrdiff_t most = n < parallel_threshold ? n : run_length(n);
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            ASSERT_EQ(seen[static_cast<std::size_t>(i)], 1) << "n = " << n << ", item " << i;
            ASSERT_LE(longest[static_cast<std::size_t>(i)], most) << "n = " << n;
        }
    }
}

}  // namespace
}  // namespace blockdem
