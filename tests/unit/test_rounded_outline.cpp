// The parts of a concave body with rounded corners (geometry/rounded_outline.hpp): the convex
// cores of the outline moved inward by r, each moved back out by r, with their seam corners.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geometry/rounded_outline.hpp"

namespace blockdem {
namespace {

struct Box {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
};

Box box_of(const std::vector<Vec2>& p) {
    Box b;
    for (Vec2 v : p) {
        b.x0 = std::min(b.x0, v.x);
        b.y0 = std::min(b.y0, v.y);
        b.x1 = std::max(b.x1, v.x);
        b.y1 = std::max(b.y1, v.y);
    }
    return b;
}

// The L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), r = 0.1: its moved-in outline is the L
// [r, 2-r] x [r, 1-r] plus [r, 1-r] x [1-r, 2-r], cut along y = 1 - r; moved back out, the
// parts are [0, 2] x [0, 1] and [0, 1] x [1 - 2r, 2] (reaching r below the cut, where the
// first part is). Of their 8 corners 5 are the arcs of the L's 5 convex corners; the cut's two
// ends and the reflex corner are seams.
TEST(RoundedOutline, LIsTwoPartsMeetingAtTheMovedInCutWithFiveArcs) {
    const double r = 0.1;
    const RoundedOutlineParts p =
        rounded_outline_parts({{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}, {1.0, 2.0}, {0.0, 2.0}}, r);
    ASSERT_EQ(p.parts.size(), 2u);
    int arcs = 0, seams = 0;
    bool foot = false, stem = false;
    for (std::size_t k = 0; k < p.parts.size(); ++k) {
        ASSERT_EQ(p.parts[k].size(), p.seam[k].size());
        for (std::uint8_t s : p.seam[k]) (s ? seams : arcs) += 1;
        const Box b = box_of(p.parts[k]);
        const double tol = 1e-12;
        if (std::abs(b.x1 - 2.0) < tol) {
            foot = std::abs(b.x0) < tol && std::abs(b.y0) < tol && std::abs(b.y1 - 1.0) < tol;
        } else {
            stem = std::abs(b.x0) < tol && std::abs(b.x1 - 1.0) < tol && std::abs(b.y0 - (1.0 - 2.0 * r)) < tol &&
                   std::abs(b.y1 - 2.0) < tol;
        }
    }
    EXPECT_TRUE(foot);
    EXPECT_TRUE(stem);
    EXPECT_EQ(arcs, 5);
    EXPECT_EQ(seams, 3);
}

TEST(RoundedOutline, RadiusThatRemovesAnEdgeIsRefusedNamingIt) {
    // A tab 0.1 m wide on the top face: r = 0.2 moves its two sides past each other, so its top
    // edge (edge 4, corner 4 to 5) turns round.
    const std::vector<Vec2> tabbed{{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.1, 1.0}, {1.1, 1.1}, {1.0, 1.1}, {1.0, 1.0}, {0.0, 1.0}};
    EXPECT_NO_THROW(rounded_outline_parts(tabbed, 0.02));
    try {
        rounded_outline_parts(tabbed, 0.2);
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("[contact] rounding = 0.2 m removes edge 4"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace blockdem
