// Sub-contacts through a crack (contact/sub_contacts.hpp): the face keeps its ends while an
// interior point is within the gap, and a broken interior point placed again is broken still.
#include <gtest/gtest.h>

#include "contact/sub_contacts.hpp"

namespace blockdem {
namespace {

// A face 0.3 m long whose second end opened: overlaps o0 at x = 0 and o1 at x = 0.3 m.
ContactManifold face(double o0, double o1) {
    ContactManifold m;
    m.normal = {0.0, 1.0};
    m.count = 2;
    m.points[0] = {{0.0, 0.0}, o0, 1u};
    m.points[1] = {{0.3, 0.0}, o1, 2u};
    m.stiffness_scale = 0.5;
    return m;
}

TEST(SubContacts, FaceKeepsBothEndsWhileAnInteriorPointIsWithinTheGap) {
    // n = 4: interior points at 1/3 and 2/3. The first at 1e-4 - (1/3) 4e-4 < 0 but within a
    // 1e-4 gap: the face stays, its opened end included.
    ContactManifold kept = face(1e-4, -3e-4);
    keep_face_or_trim(kept, 1e-4, 4);
    EXPECT_EQ(kept.count, 2u);
    EXPECT_EQ(kept.points[1].overlap_m, -3e-4);
    EXPECT_EQ(kept.stiffness_scale, 0.5);
    // No gap (nothing bonded): the interior point at 1/3 is open, so the face is trimmed to
    // the end that touches, as collide_polygons with no gap would find it.
    ContactManifold trimmed = face(1e-4, -3e-4);
    keep_face_or_trim(trimmed, 0.0, 4);
    ASSERT_EQ(trimmed.count, 1u);
    EXPECT_EQ(trimmed.points[0].feature, 1u);
    EXPECT_EQ(trimmed.stiffness_scale, 1.0);
    // Both ends beyond the gap: nothing.
    ContactManifold apart = face(-2e-4, -3e-4);
    apart.reference = make_feature(1, 0);
    keep_face_or_trim(apart, 1e-4, 8);
    EXPECT_EQ(apart.count, 0u);
    // ... with the values of a manifold of no points (ContactManifold{}), set field by field.
    const ContactManifold none{};
    EXPECT_EQ(apart.normal.x, none.normal.x);
    EXPECT_EQ(apart.normal.y, none.normal.y);
    EXPECT_EQ(apart.reference, none.reference);
    EXPECT_EQ(apart.stiffness_scale, none.stiffness_scale);
}

// A pair with two ends 0.3 m apart along x, at height y.
PairContact pair_at(double y, bool swapped) {
    PairContact pair;
    pair.count = 2;
    pair.normal = {0.0, 1.0};
    pair.points[swapped ? 1 : 0].point_m = {0.0, y};
    pair.points[swapped ? 0 : 1].point_m = {0.3, y};
    return pair;
}

TEST(SubContacts, BrokenInteriorPointsStayBrokenWhenPlacedAgain) {
    SubContacts sub;
    place_sub_points(sub, pair_at(0.0, false), 5, 0.01, BondState::intact);  // interior at x = 0.075, 0.15, 0.225
    ASSERT_EQ(sub.count, 3u);
    sub.points[0].bond = BondState::broken_tension;
    sub.points[1].bond = BondState::broken_shear;
    const DroppedSubPoints dropped = drop_sub_points(sub);
    EXPECT_EQ(dropped.count, 3u);
    EXPECT_EQ(sub.count, 0u);
    // Placed again with the ends listed the other way round: counted from the end where the
    // first broken point was, whatever the order.
    place_sub_points(sub, pair_at(1e-6, true), 5, 0.01, BondState::intact);
    ASSERT_EQ(sub.count, 3u);
    EXPECT_EQ(sub.points[2].bond, BondState::broken_tension);
    EXPECT_NEAR(sub.points[2].point_m.x, 0.075, 1e-12);
    EXPECT_EQ(sub.points[1].bond, BondState::broken_shear);
    EXPECT_EQ(sub.points[0].bond, BondState::intact) << "never broken: as a fresh point of the joint";
    // A fresh joint of dry points keeps the memory too: the broken points are not made dry ones.
    drop_sub_points(sub);
    place_sub_points(sub, pair_at(0.0, false), 5, 0.01);
    EXPECT_EQ(sub.points[0].bond, BondState::broken_tension);
    EXPECT_EQ(sub.points[2].bond, BondState::none);
}

}  // namespace
}  // namespace blockdem
