#pragma once
// Gershgorin's row sums of the mass-normalised stiffness and damping matrices, the proven bound's
// rows (dynamics/critical_time_step.hpp derives it), N rows a body: a point's direction adds
// k |g_q| |g|_1 to row q of each of its bodies (and c |g_q| |g|_1 to the damping's), g over both
// ends, signs aside. Each run of points sums its two ends' rows in parallel over the runs, then
// each body its runs' sums in run order (dynamics/point_runs.hpp): the same bits at any thread
// count, and no pass over the points on one thread (the 1e4-brick wall's live bound in 3-D: 18.5
// ms every 32 steps on two threads, 6.3 ms so). 2-D keeps its one streaming pass over the table
// (dynamics/stability_rows.hpp): its g has 3 entries, and gathering the points, their runs and
// the runs' sums cost more than they spared (the 1e4-block wall's bound: 2.2 ms against 1.55 on
// one thread, 1.65 against 1.6 on two; docs/performance.md).
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "dynamics/point_runs.hpp"
#include "world/parallel.hpp"

namespace blockdem {

template <int N>
struct GershgorinRows {
    std::vector<std::array<double, N>> stiffness_1_s2;  ///< [1/s^2] a body's N rows of K~
    std::vector<std::array<double, N>> damping_1_s;     ///< [1/s] of C~
};

template <int N, class Source>
GershgorinRows<N> gershgorin_rows(const Source& source, const PointRuns& runs) {
    using Rows = std::array<double, N>;
    const auto l1 = [](const double* g) {
        double sum = 0.0;
        for (int j = 0; j < N; ++j) sum += std::abs(g[j]);
        return sum;
    };
    struct RunRows {
        Rows k[2]{}, c[2]{};  // a's, b's
    };
    std::vector<RunRows> run_rows(runs.size());
    parallel_for(static_cast<std::ptrdiff_t>(runs.size()), [&](std::ptrdiff_t r) {
        RunRows sums;
        const PointRuns::Run& run = runs.run(static_cast<std::size_t>(r));
        for (std::uint32_t p = run.first; p < run.end; ++p)
            source.directions(p, [&](const double* ga, const double* gb, double k, double c) {
                const double norm1 = l1(ga) + l1(gb);
                for (int q = 0; q < N; ++q) {
                    sums.k[0][q] += k * std::abs(ga[q]) * norm1;
                    sums.c[0][q] += c * std::abs(ga[q]) * norm1;
                    sums.k[1][q] += k * std::abs(gb[q]) * norm1;
                    sums.c[1][q] += c * std::abs(gb[q]) * norm1;
                }
            });
        run_rows[r] = sums;
    });
    GershgorinRows<N> rows{std::vector<Rows>(runs.bodies(), Rows{}), std::vector<Rows>(runs.bodies(), Rows{})};
    parallel_for(static_cast<std::ptrdiff_t>(runs.bodies()), [&](std::ptrdiff_t i) {
        Rows k{}, c{};
        runs.for_each_run(static_cast<std::size_t>(i), [&](const PointRuns::Entry& e) {
            const RunRows& sums = run_rows[e.index];
            for (int q = 0; q < N; ++q) {
                k[q] += sums.k[e.is_b][q];
                c[q] += sums.c[e.is_b][q];
            }
        });
        rows.stiffness_1_s2[i] = k;
        rows.damping_1_s[i] = c;
    });
    return rows;
}

}  // namespace blockdem
