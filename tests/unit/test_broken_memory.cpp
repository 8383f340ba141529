// A broken joint point that opens and closes again stays broken (contact/contact_table.cpp): the
// pair remembers the corner of a broken point that left, so the point that closes there starts
// broken (residual friction, no cohesion or tension) rather than as a dry point with the peak
// friction; a corner that was never broken closes as a dry point.
#include <gtest/gtest.h>

#include "contact/contact_table.hpp"

namespace blockdem {
namespace {

ContactManifold two_corners() {
    ContactManifold m;
    m.normal = {0.0, 1.0};
    m.count = 2;
    m.points[0] = {{0.0, 0.0}, 1e-6, make_feature(1, 0)};
    m.points[1] = {{1.0, 0.0}, 1e-6, make_feature(1, 1)};
    m.reference = make_feature(0, 2);
    return m;
}

ContactManifold first_corner_only() {
    ContactManifold m = two_corners();
    m.count = 1;
    return m;
}

TEST(BrokenMemory, ABrokenPointThatClosesAgainIsBrokenStill) {
    PairContact pair;
    update_pair_geometry(pair, two_corners(), 0.05);
    pair.points[0].bond = BondState::intact;
    pair.points[1].bond = BondState::broken_shear;
    update_pair_geometry(pair, first_corner_only(), 0.05);  // the broken corner opens
    ASSERT_EQ(pair.count, 1u);
    update_pair_geometry(pair, two_corners(), 0.05);  // and closes again
    ASSERT_EQ(pair.count, 2u);
    EXPECT_EQ(pair.points[0].bond, BondState::intact);
    EXPECT_EQ(pair.points[1].bond, BondState::broken_shear);
}

TEST(BrokenMemory, BothCornersOpeningAndTheTensionStateAreKept) {
    PairContact pair;
    update_pair_geometry(pair, two_corners(), 0.05);
    pair.points[0].bond = BondState::broken_tension;
    pair.points[1].bond = BondState::broken_shear;
    update_pair_geometry(pair, ContactManifold{}, 0.05);  // the pair opens
    ASSERT_EQ(pair.count, 0u);
    update_pair_geometry(pair, two_corners(), 0.05);
    EXPECT_EQ(pair.points[0].bond, BondState::broken_tension);
    EXPECT_EQ(pair.points[1].bond, BondState::broken_shear);
}

TEST(BrokenMemory, ACornerNeverBrokenClosesDry) {
    PairContact pair;
    update_pair_geometry(pair, first_corner_only(), 0.05);
    pair.points[0].bond = BondState::broken_tension;
    update_pair_geometry(pair, ContactManifold{}, 0.05);
    update_pair_geometry(pair, two_corners(), 0.05);
    EXPECT_EQ(pair.points[0].bond, BondState::broken_tension);
    EXPECT_EQ(pair.points[1].bond, BondState::none);
}

}  // namespace
}  // namespace blockdem
