#pragma once
// The pencil B = w_k K~ + w_c C~ of dynamics/highest_mode.hpp held as N x N blocks (N = 3 in 2-D,
// 6 in 3-D): one on each moving body's diagonal, one for each run of points between two moving
// bodies. Why: the power iteration applies B some 250 times at one pair of weights, and a point's
// g (its tangents, levers, M^-1/2 of the rotation) cost about 300 operations a point in 3-D each
// time it was made again; the blocks cost 2 N^2 a run and N^2 a body, and a pair of bricks touches
// at about 4 points. The 1e5-brick wall's start estimate took 11 s on one thread with g made at
// every product (docs/performance.md, "Twenty-first session").
//
// Every product is a gather: body i's entries are D_i x_i plus its runs' blocks (B x_b where it is
// a run's a, B^T x_a where it is b) in run order, so y has the same bits at any thread count
// (world/parallel.hpp, rule 2); the Rayleigh quotients are summed over points in fixed chunks
// (rule 3).
//
// The points come from a Source as dynamics/point_runs.hpp describes it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "dynamics/highest_mode.hpp"
#include "dynamics/point_runs.hpp"
#include "world/parallel.hpp"

namespace blockdem {

/// The two Rayleigh quotients x^T K~ x and x^T C~ x.
struct PencilQuotients {
    double k = 0.0;  ///< [1/s^2]
    double c = 0.0;  ///< [1/s]
    PencilQuotients& operator+=(const PencilQuotients& o) {
        k += o.k;
        c += o.c;
        return *this;
    }
};

template <int N>
class BlockPencil {
public:
    using Block = std::array<double, N * N>;  ///< row-major

    template <class Source>
    BlockPencil(const Source& source, std::size_t body_count)
        : runs_(source, body_count), diagonal_(body_count), coupling_(runs_.couplings()) {}

    /// The blocks of B at these weights (w_k [s^2], w_c [s]): each body's diagonal block, and the
    /// coupling of each run where the body is a, from the same directions; in parallel over
    /// bodies, each writing its own blocks (rule 1).
    template <class Source>
    void assemble(const Source& source, double weight_k, double weight_c) {
        parallel_for(static_cast<std::ptrdiff_t>(runs_.bodies()), [&](std::ptrdiff_t body) {
            Block& d = diagonal_[body];
            d.fill(0.0);
            runs_.for_each_run(body, [&](const PointRuns::Entry& e) {
                Block* couple = !e.is_b && e.run.coupling != PointRuns::none ? &coupling_[e.run.coupling] : nullptr;
                if (couple) couple->fill(0.0);
                for (std::uint32_t p = e.run.first; p < e.run.end; ++p)
                    source.directions(p, [&](const double* ga, const double* gb, double k, double c) {
                        const double w = weight_k * k + weight_c * c;
                        const double* g = e.is_b ? gb : ga;
                        add_outer(d, w, g, g);
                        if (couple) add_outer(*couple, w, ga, gb);
                    });
            });
        });
        weight_k_ = weight_k;
        weight_c_ = weight_c;
    }

    /// Whether the blocks hold B at these weights.
    bool holds(double weight_k, double weight_c) const { return weight_k == weight_k_ && weight_c == weight_c_; }

    /// y = B x, N entries a body (a body that does not move gets zeros).
    void apply(const std::vector<double>& x, std::vector<double>& y) const {
        parallel_for_runs(static_cast<std::ptrdiff_t>(runs_.bodies()), [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
            for (std::ptrdiff_t body = begin; body < end; ++body) gather(body, x, &y[N * body]);
        });
    }

    /// x^T K~ x and x^T C~ x, over the points in fixed chunks (rule 3).
    template <class Source>
    PencilQuotients quotients(const Source& source, const std::vector<double>& x) const {
        return deterministic_sum(static_cast<std::ptrdiff_t>(source.points()), [&](std::ptrdiff_t i) {
            const PointEnds e = source.ends(static_cast<std::size_t>(i));
            PencilQuotients q;
            source.directions(static_cast<std::size_t>(i), [&](const double* ga, const double* gb, double k, double c) {
                double s = 0.0;
                if (e.a_moves) s += dot(ga, &x[N * e.a]);
                if (e.b_moves) s += dot(gb, &x[N * e.b]);
                q.k += k * s * s;
                q.c += c * s * s;
            });
            return q;
        });
    }

private:
    static double dot(const double* g, const double* x) {
        double s = 0.0;
        for (int j = 0; j < N; ++j) s += g[j] * x[j];
        return s;
    }

    static void add_outer(Block& block, double w, const double* rows, const double* columns) {
        for (int r = 0; r < N; ++r) {
            const double wr = w * rows[r];
            for (int col = 0; col < N; ++col) block[N * r + col] += wr * columns[col];
        }
    }

    void gather(std::ptrdiff_t body, const std::vector<double>& x, double* y) const {
        const Block& d = diagonal_[body];
        const double* xi = &x[N * body];
        for (int r = 0; r < N; ++r) y[r] = dot(&d[N * r], xi);
        runs_.for_each_run(body, [&](const PointRuns::Entry& e) {
            if (e.run.coupling == PointRuns::none) return;
            const Block& c = coupling_[e.run.coupling];
            if (!e.is_b) {
                const double* xb = &x[N * e.run.ends.b];
                for (int r = 0; r < N; ++r) y[r] += dot(&c[N * r], xb);
            } else {
                const double* xa = &x[N * e.run.ends.a];
                for (int col = 0; col < N; ++col) {
                    double s = 0.0;
                    for (int r = 0; r < N; ++r) s += c[N * r + col] * xa[r];
                    y[col] += s;
                }
            }
        });
    }

    PointRuns runs_;
    std::vector<Block> diagonal_;
    std::vector<Block> coupling_;  // one a run whose two bodies move: rows a's entries, columns b's
    double weight_k_ = std::numeric_limits<double>::quiet_NaN();
    double weight_c_ = std::numeric_limits<double>::quiet_NaN();
};

/// highest_mode over the source's points with the pencil held as blocks, assembled at each trial
/// dt's weights.
template <int N, class Source>
HighestMode pencil_highest_mode(const Source& source, std::size_t body_count, double trial_dt_s) {
    BlockPencil<N> pencil(source, body_count);
    return highest_mode(
        N * body_count, trial_dt_s,
        [&](double wk, double wc, const std::vector<double>& x, std::vector<double>& y) {
            if (!pencil.holds(wk, wc)) pencil.assemble(source, wk, wc);
            pencil.apply(x, y);
        },
        [&](const std::vector<double>& x) {
            const PencilQuotients q = pencil.quotients(source, x);
            return std::pair<double, double>{q.k, q.c};
        });
}

}  // namespace blockdem
