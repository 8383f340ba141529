#pragma once
// Contact points grouped for a per-body pass: runs (consecutive points of the same two bodies)
// and each moving body's runs, in run order. The stability estimates (the proven bound, each
// body's own blocks, the pencil of dynamics/block_pencil.hpp) sum over a body's points; walked
// this way, each body's sums are made by one thread in one order, so their bits do not depend
// on the thread count (world/parallel.hpp, rule 2), and the bodies can be shared out.
//
// A Source gives the points, in any order:
//   std::size_t points() const;
//   PointEnds ends(std::size_t i) const;
//   template <class F> void directions(std::size_t i, F&& f) const;
//     calls f(const double* g_a, const double* g_b, double k, double c) for each direction of
//     point i: g's N entries on a and on b (mass-normalised, zeros on an end that does not move)
//     and the spring k and dashpot c along it;
//   template <class F> void end_directions(std::size_t i, bool b_end, F&& f) const;
//     the same, f(const double* g, double k, double c), with g's entries on one end only (on b
//     where b_end), for a pass that needs no more (half the work in 3-D); only for_each_direction
//     asks for it.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace blockdem {

struct PointEnds {
    std::uint32_t a = 0, b = 0;  ///< bodies (an end that does not move may be any index)
    bool a_moves = false, b_moves = false;
};

class PointRuns {
public:
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

    struct Run {
        PointEnds ends;
        std::uint32_t first = 0, end = 0;  ///< its points first .. end - 1
        std::uint32_t coupling = none;     ///< its index among the runs whose two bodies move
    };

    /// One body's place in a run: the run, its index, and whether the body is its b.
    struct Entry {
        const Run& run;
        std::uint32_t index;
        bool is_b;
    };

    /// The source's runs, for bodies < body_count; points whose two ends do not move are in none.
    template <class Source>
    PointRuns(const Source& source, std::size_t body_count) : bodies_(body_count) {
        for (std::size_t i = 0; i < source.points(); ++i) {
            const PointEnds e = source.ends(i);
            if (!e.a_moves && !e.b_moves) continue;
            const auto at = static_cast<std::uint32_t>(i);
            if (!runs_.empty() && runs_.back().end == at && runs_.back().ends.a == e.a && runs_.back().ends.b == e.b) {
                ++runs_.back().end;
                continue;
            }
            runs_.push_back({e, at, at + 1, e.a_moves && e.b_moves ? couplings_++ : none});
        }
        index_by_body();
    }

    std::size_t bodies() const { return bodies_; }
    std::size_t size() const { return runs_.size(); }
    const Run& run(std::size_t r) const { return runs_[r]; }
    std::uint32_t couplings() const { return couplings_; }

    /// Calls f(Entry) for each of body's runs, in run order (none for a body that does not move).
    template <class F>
    void for_each_run(std::size_t body, F&& f) const {
        for (std::uint32_t e = start_[body]; e < start_[body + 1]; ++e) {
            const std::uint32_t r = entries_[e] >> 1;
            f(Entry{runs_[r], r, (entries_[e] & 1u) != 0});
        }
    }

    /// Calls f(g, k, c) for each direction of each of body's points, in run order, g its own N
    /// entries.
    template <class Source, class F>
    void for_each_direction(const Source& source, std::size_t body, F&& f) const {
        for_each_run(body, [&](const Entry& e) {
            for (std::uint32_t p = e.run.first; p < e.run.end; ++p) source.end_directions(p, e.is_b, f);
        });
    }

private:
    // Each moving body's runs in run order, as entries 2 run + (1 where it is the run's b).
    void index_by_body() {
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

    std::size_t bodies_ = 0;
    std::uint32_t couplings_ = 0;
    std::vector<Run> runs_;
    std::vector<std::uint32_t> start_;    // body i's entries: entries_[start_[i] .. start_[i + 1])
    std::vector<std::uint32_t> entries_;  // 2 run + (1 where the body is the run's b)
};

}  // namespace blockdem
