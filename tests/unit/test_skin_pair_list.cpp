// The Verlet skin over the grid (broad_phase/skin_pair_list.hpp) gives, at every step, exactly the
// pairs the grid gives on the same boxes, in the same order, while searching the grid only when
// a body has left its enlarged box.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "broad_phase/grid_broad_phase_3d.hpp"
#include "broad_phase/skin_pair_list.hpp"

namespace blockdem {
namespace {

// n boxes 0.2 x 0.1 x 0.1 m stacked as a block: 0.5 mm apart along x, touching along y and
// overlapping by 0.2 mm along z (so that pairs open and close as they drift), and one large
// static slab under them.
void lattice(std::size_t n, std::vector<Aabb3d>& boxes, std::vector<std::uint8_t>& is_static) {
    const auto side = static_cast<std::size_t>(std::cbrt(static_cast<double>(n))) + 1;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 lo{0.2005 * static_cast<double>(i % side), 0.1 * static_cast<double>((i / side) % side),
                      0.0998 * static_cast<double>(i / (side * side))};
        boxes.push_back({lo, lo + Vec3{0.2, 0.1, 0.1}});
        is_static.push_back(0);
    }
    boxes.push_back({{-1.0, -1.0, -0.5}, {1.0 + 0.2005 * static_cast<double>(side), 1.0 + 0.1 * static_cast<double>(side), 0.0}});
    is_static.push_back(1);
}

// Moves each body by up to step_m along each axis and lets its box breathe by up to step_m (a
// turn changes a box's size as well as its place).
void jiggle(std::vector<Aabb3d>& boxes, std::mt19937& rng, double step_m) {
    std::uniform_real_distribution<double> d(-step_m, step_m);
    for (std::size_t i = 0; i + 1 < boxes.size(); ++i) {
        const Vec3 move{d(rng), d(rng), d(rng)};
        const double grow = d(rng);
        boxes[i].lo = boxes[i].lo + move - Vec3{grow, grow, grow};
        boxes[i].hi = boxes[i].hi + move + Vec3{grow, grow, grow};
    }
}

TEST(SkinPairList, GivesTheGridsPairsEveryStepAndSearchesRarely) {
    // 1200 boxes: more than parallel_threshold listed pairs, so the filter runs in its 64 chunks.
    std::vector<Aabb3d> boxes;
    std::vector<std::uint8_t> is_static;
    lattice(1200, boxes, is_static);
    std::mt19937 rng(11);
    SkinPairList3d skin;
    GridBroadPhase3d grid;
    std::vector<BodyPair> from_skin, from_grid;
    std::size_t most_pairs = 0;
    const int steps = 120;
    for (int step = 0; step < steps; ++step) {
        jiggle(boxes, rng, 2e-4);
        if (step == 60) boxes[17].lo.z += 0.5, boxes[17].hi.z += 0.5;  // one body jumps: a rebuild
        if (step == 90) is_static[42] = 1;                              // one body stops: a rebuild
        skin.find_pairs(boxes, is_static, from_skin);
        grid.find_pairs(boxes, is_static, from_grid);
        ASSERT_EQ(from_skin, from_grid) << "step " << step;
        most_pairs = std::max(most_pairs, from_grid.size());
    }
    EXPECT_GT(most_pairs, 2048u);
    EXPECT_GT(skin.listed_pairs(), 2048u);
    // A 1 cm margin against a drift of at most 0.4 mm a step (move and growth): the first search,
    // the two forced ones, and a few for the random walk; never every step.
    EXPECT_GE(skin.rebuilds(), 3);
    EXPECT_LT(skin.rebuilds(), steps / 10);
}

TEST(SkinPairList, FollowsBodiesAddedRemovedAndNotANumber) {
    std::vector<Aabb3d> boxes;
    std::vector<std::uint8_t> is_static;
    lattice(200, boxes, is_static);
    SkinPairList3d skin;
    GridBroadPhase3d grid;
    std::vector<BodyPair> from_skin, from_grid;
    auto same = [&] {
        skin.find_pairs(boxes, is_static, from_skin);
        grid.find_pairs(boxes, is_static, from_grid);
        return from_skin == from_grid;
    };
    EXPECT_TRUE(same());
    boxes.push_back(boxes[5]);  // a body added on top of another
    is_static.push_back(0);
    EXPECT_TRUE(same());
    boxes.pop_back();
    is_static.pop_back();
    EXPECT_TRUE(same());
    const std::int64_t before = skin.rebuilds();
    boxes[3].hi.x = NAN;  // a body that blew up: no pair, and the list searched again
    EXPECT_TRUE(same());
    EXPECT_EQ(skin.rebuilds(), before + 1);
    boxes[3].hi.x = boxes[3].lo.x + 0.2;
    EXPECT_TRUE(same());
    EXPECT_GT(from_grid.size(), 200u);
}

TEST(SkinPairList, GivesTheGridsPairsInTwoDimensions) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(0.0, 6.0), size(0.05, 0.4), d(-1e-3, 1e-3);
    std::vector<Aabb> boxes;
    std::vector<std::uint8_t> is_static;
    for (int i = 0; i < 500; ++i) {
        const Vec2 lo{pos(rng), pos(rng)};
        boxes.push_back({lo, lo + Vec2{size(rng), size(rng)}});
        is_static.push_back(i % 13 == 0 ? 1 : 0);
    }
    SkinPairList skin;
    GridBroadPhase grid;
    std::vector<BodyPair> from_skin, from_grid;
    for (int step = 0; step < 100; ++step) {
        for (Aabb& b : boxes) {
            const Vec2 move{d(rng), d(rng)};
            b.lo = b.lo + move;
            b.hi = b.hi + move;
        }
        skin.find_pairs(boxes, is_static, from_skin);
        grid.find_pairs(boxes, is_static, from_grid);
        ASSERT_EQ(from_skin, from_grid) << "step " << step;
    }
    EXPECT_GT(from_grid.size(), 50u);
    EXPECT_LT(skin.rebuilds(), 100);
}

}  // namespace
}  // namespace blockdem
