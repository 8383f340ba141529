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
// A Source gives the points, in any order (a run is consecutive points of the same two bodies):
//   std::size_t points() const;
//   PencilEnds ends(std::size_t i) const;
//   template <class F> void directions(std::size_t i, F&& f) const;
//     calls f(const double* g_a, const double* g_b, double k, double c) for each direction of
//     point i: g's N entries on a and on b (zeros on an end that does not move) and the spring
//     k and dashpot c along it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "dynamics/highest_mode.hpp"
#include "world/parallel.hpp"

namespace blockdem {

struct PencilEnds {
    std::uint32_t a = 0, b = 0;  ///< bodies (an end that does not move may be any index)
    bool a_moves = false, b_moves = false;
};

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

    /// The runs and each moving body's list of them, for bodies < body_count.
    template <class Source>
    BlockPencil(const Source& source, std::size_t body_count) : bodies_(body_count) {
        for (std::size_t i = 0; i < source.points(); ++i) {
            const PencilEnds e = source.ends(i);
            if (!e.a_moves && !e.b_moves) continue;
            const auto at = static_cast<std::uint32_t>(i);
            if (!runs_.empty() && runs_.back().end == at && same_bodies(runs_.back().ends, e)) {
                ++runs_.back().end;
                continue;
            }
            const bool couples = e.a_moves && e.b_moves;
            runs_.push_back({e, at, at + 1, couples ? couplings_++ : none});
        }
        index_runs_by_body();
        diagonal_.resize(bodies_);
        coupling_.resize(couplings_);
    }

    /// The blocks of B at these weights (w_k [s^2], w_c [s]): each body's diagonal block, and the
    /// coupling of each run where the body is a, from the same directions; in parallel over
    /// bodies, each writing its own blocks (rule 1).
    template <class Source>
    void assemble(const Source& source, double weight_k, double weight_c) {
        parallel_for(static_cast<std::ptrdiff_t>(bodies_), [&](std::ptrdiff_t body) {
            Block& d = diagonal_[body];
            d.fill(0.0);
            for (std::uint32_t e = start_[body]; e < start_[body + 1]; ++e) {
                const Run& run = runs_[entries_[e] >> 1];
                const bool is_b = (entries_[e] & 1u) != 0;
                Block* couple = !is_b && run.coupling != none ? &coupling_[run.coupling] : nullptr;
                if (couple) couple->fill(0.0);
                for (std::uint32_t p = run.first; p < run.end; ++p)
                    source.directions(p, [&](const double* ga, const double* gb, double k, double c) {
                        const double w = weight_k * k + weight_c * c;
                        const double* g = is_b ? gb : ga;
                        add_outer(d, w, g, g);
                        if (couple) add_outer(*couple, w, ga, gb);
                    });
            }
        });
        weight_k_ = weight_k;
        weight_c_ = weight_c;
    }

    /// Whether the blocks hold B at these weights.
    bool holds(double weight_k, double weight_c) const { return weight_k == weight_k_ && weight_c == weight_c_; }

    /// y = B x, N entries a body (a body that does not move gets zeros).
    void apply(const std::vector<double>& x, std::vector<double>& y) const {
        parallel_for_runs(static_cast<std::ptrdiff_t>(bodies_), [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
            for (std::ptrdiff_t body = begin; body < end; ++body) gather(body, x, &y[N * body]);
        });
    }

    /// x^T K~ x and x^T C~ x, over the points in fixed chunks (rule 3).
    template <class Source>
    PencilQuotients quotients(const Source& source, const std::vector<double>& x) const {
        return deterministic_sum(static_cast<std::ptrdiff_t>(source.points()), [&](std::ptrdiff_t i) {
            const PencilEnds e = source.ends(static_cast<std::size_t>(i));
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
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    struct Run {
        PencilEnds ends;
        std::uint32_t first = 0, end = 0;  ///< its points first .. end - 1
        std::uint32_t coupling = none;     ///< its block, where both bodies move
    };

    static bool same_bodies(const PencilEnds& x, const PencilEnds& y) { return x.a == y.a && x.b == y.b; }

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

    // Each moving body's runs in run order, as entries 2 run + (1 where it is the run's b).
    void index_runs_by_body() {
        start_.assign(bodies_ + 1, 0);
        const auto each_moving_end = [&](auto&& f) {
            for (std::uint32_t r = 0; r < runs_.size(); ++r) {
                if (runs_[r].ends.a_moves) f(runs_[r].ends.a, 2 * r);
                if (runs_[r].ends.b_moves) f(runs_[r].ends.b, 2 * r + 1);
            }
        };
        each_moving_end([&](std::uint32_t body, std::uint32_t) { ++start_[body + 1]; });
        for (std::size_t i = 0; i < bodies_; ++i) start_[i + 1] += start_[i];
        entries_.resize(start_[bodies_]);
        std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
        each_moving_end([&](std::uint32_t body, std::uint32_t entry) { entries_[next[body]++] = entry; });
    }

    void gather(std::ptrdiff_t body, const std::vector<double>& x, double* y) const {
        const Block& d = diagonal_[body];
        const double* xi = &x[N * body];
        for (int r = 0; r < N; ++r) y[r] = dot(&d[N * r], xi);
        for (std::uint32_t e = start_[body]; e < start_[body + 1]; ++e) {
            const Run& run = runs_[entries_[e] >> 1];
            if (run.coupling == none) continue;
            const Block& c = coupling_[run.coupling];
            if ((entries_[e] & 1u) == 0) {
                const double* xb = &x[N * run.ends.b];
                for (int r = 0; r < N; ++r) y[r] += dot(&c[N * r], xb);
            } else {
                const double* xa = &x[N * run.ends.a];
                for (int col = 0; col < N; ++col) {
                    double s = 0.0;
                    for (int r = 0; r < N; ++r) s += c[N * r + col] * xa[r];
                    y[col] += s;
                }
            }
        }
    }

    std::size_t bodies_ = 0;
    std::uint32_t couplings_ = 0;
    std::vector<Run> runs_;
    std::vector<std::uint32_t> start_;    // body i's entries: entries_[start_[i] .. start_[i + 1])
    std::vector<std::uint32_t> entries_;  // 2 run + (1 where the body is the run's b)
    std::vector<Block> diagonal_;
    std::vector<Block> coupling_;         // rows: a's entries; columns: b's
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
