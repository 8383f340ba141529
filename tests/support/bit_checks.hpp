#pragma once
// Checks that two runs agree to the bit: numbers and vectors compared as bytes (so that -0 and 0,
// or two NaNs, are told apart as a restart must keep them), and the external loads of a world, in
// either dimension, array by array and body by body.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>

#include "geometry/vec2.hpp"
#include "geometry/vec3.hpp"

namespace blockdem::testing {

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool same_bits(Vec2 a, Vec2 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }
inline bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

/// Every array of the loads (ExternalLoads or ExternalLoads3d), every body, to the bit.
template <class Loads>
void expect_same_loads(const Loads& a, const Loads& b) {
    ASSERT_EQ(a.force_n.size(), b.force_n.size());
    ASSERT_EQ(a.held, b.held);
    for (std::size_t i = 0; i < a.force_n.size(); ++i) {
        EXPECT_TRUE(same_bits(a.force_n[i], b.force_n[i])) << "body " << i;
        EXPECT_TRUE(same_bits(a.torque_n_m[i], b.torque_n_m[i])) << "body " << i;
        EXPECT_TRUE(same_bits(a.held_velocity_m_s[i], b.held_velocity_m_s[i])) << "body " << i;
        EXPECT_TRUE(same_bits(a.held_angular_velocity_rad_s[i], b.held_angular_velocity_rad_s[i])) << "body " << i;
    }
}

}  // namespace blockdem::testing
