// The pencil held as blocks (dynamics/block_pencil.hpp) against the same matrices written out
// densely, sum over points and directions of k g g^T: its products and Rayleigh quotients, on
// points whose runs of one pair are split, whose ends include bodies that do not move and an
// index that is no body; the same bits at one and two threads; and the highest mode through it
// against the one found with the dense product.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "dynamics/block_pencil.hpp"
#include "dynamics/highest_mode.hpp"

namespace blockdem {
namespace {

constexpr int pencil_dofs = 3;
constexpr std::uint32_t no_body = 0xffffffffu;  // as the 2-D estimate's fixed ground

int pencil_threads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

void use_pencil_threads(int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
}

// A point with two directions, each with g's parts on its two ends and a spring and a dashpot.
struct SyntheticPoint {
    PointEnds ends;
    double g[2][2][pencil_dofs];  // [direction][end][entry]
    double k[2], c[2];
};

struct SyntheticSource {
    std::vector<SyntheticPoint> list;
    std::size_t points() const { return list.size(); }
    PointEnds ends(std::size_t i) const { return list[i].ends; }
    template <class F>
    void directions(std::size_t i, F&& f) const {
        const SyntheticPoint& p = list[i];
        for (int d = 0; d < 2; ++d) f(p.g[d][0], p.g[d][1], p.k[d], p.c[d]);
    }
};

struct Lcg {
    std::uint64_t state = 12345;
    double uniform() {  // in [0, 1)
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    }
    std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(uniform() * n); }
};

// Bodies of which every seventh does not move; pairs of neighbours in runs of 1 to 4 points, each
// pair met again later in a second run, and some points on the ground (no body).
SyntheticSource synthetic_points(std::uint32_t bodies, std::vector<bool>& moving) {
    Lcg r;
    moving.assign(bodies, true);
    for (std::uint32_t i = 0; i < bodies; i += 7) moving[i] = false;
    SyntheticSource s;
    const auto add_run = [&](std::uint32_t a, std::uint32_t b, bool b_is_ground) {
        const std::uint32_t count = 1 + r.below(4);
        for (std::uint32_t n = 0; n < count; ++n) {
            SyntheticPoint p{};
            p.ends = {a, b_is_ground ? no_body : b, moving[a], !b_is_ground && moving[b]};
            for (int d = 0; d < 2; ++d) {
                for (int e = 0; e < 2; ++e) {
                    const bool moves = e == 0 ? p.ends.a_moves : p.ends.b_moves;
                    for (int j = 0; j < pencil_dofs; ++j) p.g[d][e][j] = moves ? r.uniform() - 0.5 : 0.0;
                }
                p.k[d] = 0.5 + r.uniform();
                p.c[d] = 0.1 * r.uniform();
            }
            s.list.push_back(p);
        }
    };
    for (std::uint32_t i = 0; i + 1 < bodies; ++i) add_run(i, i + 1, false);
    for (std::uint32_t i = 0; i + 3 < bodies; i += 3) add_run(i, i + 3, false);
    for (std::uint32_t i = 0; i + 1 < bodies; i += 5) add_run(i, i + 1, false);  // a second run of a pair
    for (std::uint32_t i = 0; i < bodies; i += 4) add_run(i, 0, true);
    return s;
}

// sum_points sum_directions (weight_k k + weight_c c) g (g . x), written out.
std::vector<double> dense_product(const SyntheticSource& s, std::size_t bodies, double weight_k, double weight_c,
                                  const std::vector<double>& x) {
    std::vector<double> y(pencil_dofs * bodies, 0.0);
    for (const SyntheticPoint& p : s.list) {
        const std::uint32_t ends[2] = {p.ends.a, p.ends.b};
        const bool moves[2] = {p.ends.a_moves, p.ends.b_moves};
        for (int d = 0; d < 2; ++d) {
            double gx = 0.0;
            for (int e = 0; e < 2; ++e)
                for (int j = 0; moves[e] && j < pencil_dofs; ++j) gx += p.g[d][e][j] * x[pencil_dofs * ends[e] + j];
            const double w = weight_k * p.k[d] + weight_c * p.c[d];
            for (int e = 0; e < 2; ++e)
                for (int j = 0; moves[e] && j < pencil_dofs; ++j) y[pencil_dofs * ends[e] + j] += w * p.g[d][e][j] * gx;
        }
    }
    return y;
}

std::vector<double> test_vector(std::size_t n, const std::vector<bool>& moving) {
    Lcg r{999};
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = moving[i / pencil_dofs] ? r.uniform() - 0.5 : 0.0;
    return x;
}

TEST(BlockPencil, ProductsAndQuotientsAreThoseOfTheDenseMatrices) {
    const std::uint32_t bodies = 60;
    std::vector<bool> moving;
    const SyntheticSource s = synthetic_points(bodies, moving);
    const std::vector<double> x = test_vector(pencil_dofs * bodies, moving);
    BlockPencil<pencil_dofs> pencil(s, bodies);
    for (const auto [wk, wc] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}, std::pair{0.3, 0.7}}) {
        pencil.assemble(s, wk, wc);
        EXPECT_TRUE(pencil.holds(wk, wc));
        std::vector<double> y(x.size());
        pencil.apply(x, y);
        const std::vector<double> reference = dense_product(s, bodies, wk, wc, x);
        for (std::size_t i = 0; i < y.size(); ++i) {
            EXPECT_NEAR(y[i], reference[i], 1e-12) << "entry " << i << " at weights " << wk << ", " << wc;
            if (!moving[i / pencil_dofs]) EXPECT_EQ(y[i], 0.0) << "a body that does not move, entry " << i;
        }
    }
    const PencilQuotients q = pencil.quotients(s, x);
    const auto quotient = [&](double wk, double wc) {
        const std::vector<double> y = dense_product(s, bodies, wk, wc, x);
        double sum = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) sum += x[i] * y[i];
        return sum;
    };
    EXPECT_NEAR(q.k, quotient(1.0, 0.0), 1e-12 * std::abs(q.k));
    EXPECT_NEAR(q.c, quotient(0.0, 1.0), 1e-12 * std::abs(q.c));
}

TEST(BlockPencil, SameBitsAtOneAndTwoThreads) {
    const std::uint32_t bodies = 20000;  // above the parallel threshold
    std::vector<bool> moving;
    const SyntheticSource s = synthetic_points(bodies, moving);
    const std::vector<double> x = test_vector(pencil_dofs * bodies, moving);
    const auto product = [&](int threads) {
        use_pencil_threads(threads);
        BlockPencil<pencil_dofs> pencil(s, bodies);
        pencil.assemble(s, 0.25, 0.5);
        std::vector<double> y(x.size());
        pencil.apply(x, y);
        const PencilQuotients q = pencil.quotients(s, x);
        y.push_back(q.k);
        y.push_back(q.c);
        return y;
    };
    const int threads_before = pencil_threads();
    const std::vector<double> one = product(1);
    const std::vector<double> two = product(2);
    use_pencil_threads(threads_before);
    ASSERT_EQ(one.size(), two.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < one.size(); ++i) differing += one[i] != two[i];
    EXPECT_EQ(differing, 0u);
}

TEST(BlockPencil, HighestModeIsTheDenseProductsOne) {
    const std::uint32_t bodies = 40;
    std::vector<bool> moving;
    const SyntheticSource s = synthetic_points(bodies, moving);
    const double trial_dt = 0.1;
    const HighestMode blocks = pencil_highest_mode<pencil_dofs>(s, bodies, trial_dt);
    const HighestMode dense = highest_mode(pencil_dofs * bodies, trial_dt,
                                           [&](double wk, double wc, const std::vector<double>& x, std::vector<double>& y) {
                                               y = dense_product(s, bodies, wk, wc, x);
                                           });
    ASSERT_TRUE(blocks.found);
    ASSERT_TRUE(dense.found);
    EXPECT_NEAR(blocks.dt_s, dense.dt_s, 1e-10 * dense.dt_s);
    EXPECT_NEAR(blocks.omega_rad_s, dense.omega_rad_s, 1e-10 * dense.omega_rad_s);
    EXPECT_NEAR(blocks.h, dense.h, 1e-9 * std::abs(dense.h));
}

}  // namespace
}  // namespace blockdem
