// The deterministic sum of world/parallel.hpp: right at every size (including the sizes between
// one chunk and the parallel threshold) and equal bit for bit at 1 and 2 threads.
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

}  // namespace
}  // namespace blockdem
