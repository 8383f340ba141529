// The grid broad phase finds exactly the overlapping pairs that an all-pairs loop finds.
#include <gtest/gtest.h>

#include <random>

#include "broad_phase/grid_broad_phase.hpp"

namespace blockdem {
namespace {

TEST(GridBroadPhase, MatchesAllPairsOnRandomBoxes) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(0.0, 10.0), size(0.05, 0.4);
    std::vector<Aabb> boxes;
    std::vector<std::uint8_t> is_static;
    for (int i = 0; i < 600; ++i) {
        const Vec2 lo{pos(rng), pos(rng)};
        boxes.push_back({lo, lo + Vec2{size(rng), size(rng)}});
        is_static.push_back(i % 17 == 0 ? 1 : 0);
    }
    boxes.push_back({{-1.0, -1.0}, {11.0, 0.2}});  // a large ground slab
    is_static.push_back(1);
    boxes.push_back({{-1.0, 9.8}, {11.0, 11.0}});  // a large moving lid
    is_static.push_back(0);
    std::vector<BodyPair> expected;
    for (std::uint32_t a = 0; a < boxes.size(); ++a)
        for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
            if (!(is_static[a] && is_static[b]) && overlaps(boxes[a], boxes[b])) expected.emplace_back(a, b);
    GridBroadPhase grid;
    std::vector<BodyPair> found;
    grid.find_pairs(boxes, is_static, found);
    EXPECT_EQ(found, expected);
    EXPECT_GT(found.size(), 100u);
}

}  // namespace
}  // namespace blockdem
