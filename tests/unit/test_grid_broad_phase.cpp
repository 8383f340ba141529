// The grid broad phase finds exactly the overlapping pairs that an all-pairs loop finds, in 2-D
// and in 3-D (one implementation for both: GridBroadPhaseOf<Box>).
#include <gtest/gtest.h>

#include <random>

#include "broad_phase/grid_broad_phase.hpp"
#include "broad_phase/grid_broad_phase_3d.hpp"

namespace blockdem {
namespace {

template <class Box>
std::vector<BodyPair> all_pairs(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& is_static) {
    std::vector<BodyPair> pairs;
    for (std::uint32_t a = 0; a < boxes.size(); ++a)
        for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
            if (!(is_static[a] && is_static[b]) && overlaps(boxes[a], boxes[b])) pairs.emplace_back(a, b);
    return pairs;
}

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
    const std::vector<BodyPair> expected = all_pairs(boxes, is_static);
    GridBroadPhase grid;
    std::vector<BodyPair> found;
    grid.find_pairs(boxes, is_static, found);
    EXPECT_EQ(found, expected);
    EXPECT_GT(found.size(), 100u);
}

// Clusters a million metres apart force the cell-count cap to coarsen the grid; pairs at
// +-1e308 m make the extent overflow to infinity, hence one cell. Both dimensions must still find exactly
// the overlapping pairs.
TEST(GridBroadPhase, SpreadOutBodiesMatchAllPairsInBothDimensions) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> pos(0.0, 2.0), size(0.1, 0.5);
    std::vector<Aabb> boxes;
    std::vector<Aabb3d> boxes_3d;
    std::vector<std::uint8_t> is_static;
    auto add = [&](Vec2 lo, Vec2 side) {
        boxes.push_back({lo, lo + side});
        boxes_3d.push_back({{lo.x, lo.y, lo.x}, {lo.x + side.x, lo.y + side.y, lo.x + side.x}});
        is_static.push_back(0);
    };
    for (double cluster_m : {0.0, 1e6, 3e6})
        for (int i = 0; i < 40; ++i) add({cluster_m + pos(rng), pos(rng)}, {size(rng), size(rng)});
    for (double far_m : {-1e308, 1e308}) {
        add({far_m, far_m}, {0.3, 0.3});
        add({far_m, far_m}, {0.3, 0.3});  // at 1e308, 0.3 m is below the spacing of doubles: points that touch
    }
    const std::vector<BodyPair> expected = all_pairs(boxes, is_static);
    const std::vector<BodyPair> expected_3d = all_pairs(boxes_3d, is_static);
    EXPECT_GT(expected.size(), 30u);
    EXPECT_GT(expected_3d.size(), 10u);
    GridBroadPhase grid;
    GridBroadPhase3d grid_3d;
    std::vector<BodyPair> found, found_3d;
    grid.find_pairs(boxes, is_static, found);
    grid_3d.find_pairs(boxes_3d, is_static, found_3d);
    EXPECT_EQ(found, expected);
    EXPECT_EQ(found_3d, expected_3d);
}

// A 3-D set that is a 2-D set extruded by the same depth has the 2-D set's pairs.
TEST(GridBroadPhase, ExtrudedBoxesHaveThePlanePairs) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> pos(0.0, 4.0), size(0.05, 0.5);
    std::vector<Aabb> boxes;
    std::vector<Aabb3d> boxes_3d;
    std::vector<std::uint8_t> is_static;
    for (int i = 0; i < 300; ++i) {
        const Vec2 lo{pos(rng), pos(rng)};
        const Vec2 hi = lo + Vec2{size(rng), size(rng)};
        boxes.push_back({lo, hi});
        boxes_3d.push_back({{lo.x, lo.y, -0.1}, {hi.x, hi.y, 0.1}});
        is_static.push_back(i % 11 == 0 ? 1 : 0);
    }
    GridBroadPhase grid;
    GridBroadPhase3d grid_3d;
    std::vector<BodyPair> found, found_3d;
    grid.find_pairs(boxes, is_static, found);
    grid_3d.find_pairs(boxes_3d, is_static, found_3d);
    EXPECT_GT(found.size(), 100u);
    EXPECT_EQ(found_3d, found);
}

}  // namespace
}  // namespace blockdem
