// The rule block_deformability (laws/material_stiffness.hpp): each block's half height in series,
// per unit area, times the face one contact point carries.
#include <gtest/gtest.h>

#include <vector>

#include "geometry/polygon.hpp"
#include "laws/material_stiffness.hpp"

namespace blockdem {
namespace {

const ElasticMaterial stone{30e9, 0.2};
const BlockDimensions drum_block{0.9, 0.6, 1.0};  // 0.9 m high, 0.6 m wide, 1 m thick

// Two equal drums: kn'' = E / h, each point carries half the 0.6 m face: kn = E t w / (2 h).
TEST(MaterialStiffness, EqualBlocks) {
    const JointStiffness s = block_joint_stiffness({stone, drum_block}, {stone, drum_block});
    EXPECT_NEAR(s.kn_per_area_pa_m, 30e9 / 0.9, 1e-6 * 30e9 / 0.9);
    EXPECT_DOUBLE_EQ(s.tributary_length_m, 0.3);
    EXPECT_DOUBLE_EQ(s.thickness_m, 1.0);
    EXPECT_NEAR(s.kn_N_m, 1e10, 1.0);
    // ks / kn = G / E = 1 / (2 (1 + nu)).
    EXPECT_NEAR(s.ks_N_m / s.kn_N_m, 1.0 / 2.4, 1e-12);
    EXPECT_NEAR(shear_modulus_pa(stone), 12.5e9, 1.0);
}

// What the rule is for: a stack of equal blocks on two points per joint is as stiff axially as
// the continuum column. Each joint (two points in parallel) has the stiffness of one block,
// E A / h, so n joints in series give E A / (n h): the column of n blocks.
TEST(MaterialStiffness, TwoPointsPerJointGiveTheBlockAxialStiffness) {
    const JointStiffness s = block_joint_stiffness({stone, drum_block}, {stone, drum_block});
    const double block_axial_N_m = stone.young_modulus_pa * drum_block.width_m * drum_block.thickness_m / drum_block.height_m;
    EXPECT_NEAR(2.0 * s.kn_N_m, block_axial_N_m, 1e-9 * block_axial_N_m);
}

// Series: against a far stiffer base the joint gets only the drum's half height, twice as stiff.
// Against a softer material the softer side governs.
TEST(MaterialStiffness, SeriesCombination) {
    const ElasticMaterial steel{1e15, 0.3};
    const JointStiffness rigid_base = block_joint_stiffness({stone, drum_block}, {steel, {0.2, 4.0, 1.0}});
    EXPECT_NEAR(rigid_base.kn_per_area_pa_m, 2.0 * 30e9 / 0.9, 1e-4 * 2.0 * 30e9 / 0.9);
    const ElasticMaterial soft{3e9, 0.2};
    const JointStiffness mixed = block_joint_stiffness({stone, drum_block}, {soft, drum_block});
    EXPECT_NEAR(mixed.kn_per_area_pa_m, 1.0 / (0.45 / 30e9 + 0.45 / 3e9), 1.0);
    // The result does not depend on which side is a.
    EXPECT_DOUBLE_EQ(mixed.kn_N_m, block_joint_stiffness({soft, drum_block}, {stone, drum_block}).kn_N_m);
    EXPECT_DOUBLE_EQ(mixed.ks_N_m, block_joint_stiffness({soft, drum_block}, {stone, drum_block}).ks_N_m);
}

// The shared face is the narrower block's, and the thinner block's.
TEST(MaterialStiffness, SharedFace) {
    const JointStiffness s = block_joint_stiffness({stone, {0.9, 0.6, 0.5}}, {stone, {0.2, 4.0, 1.0}});
    EXPECT_DOUBLE_EQ(s.tributary_length_m, 0.3);
    EXPECT_DOUBLE_EQ(s.thickness_m, 0.5);
    EXPECT_NEAR(s.kn_N_m, s.kn_per_area_pa_m * 0.3 * 0.5, 1e-6);
}

// The stiffness scales with E and with the block's aspect ratio, not its size.
TEST(MaterialStiffness, ScalesWithModulusNotSize) {
    const double kn = block_joint_stiffness({stone, drum_block}, {stone, drum_block}).kn_N_m;
    const ElasticMaterial twice{60e9, 0.2};
    EXPECT_NEAR(block_joint_stiffness({twice, drum_block}, {twice, drum_block}).kn_N_m, 2.0 * kn, 1e-6 * kn);
    const BlockDimensions half{0.45, 0.3, 1.0};
    EXPECT_NEAR(block_joint_stiffness({stone, half}, {stone, half}).kn_N_m, kn, 1e-6 * kn);
}

TEST(MaterialStiffness, BlockDimensionsFromCorners) {
    const std::vector<Vec2> corners = rectangle_vertices(0.6, 0.9, {1.0, 2.0}, 0.0);
    const BlockDimensions d = block_dimensions(corners, 0.7);
    EXPECT_NEAR(d.height_m, 0.9, 1e-12);
    EXPECT_NEAR(d.width_m, 0.6, 1e-12);
    EXPECT_DOUBLE_EQ(d.thickness_m, 0.7);
}

// A wall of bricks and a few half bricks and one lintel: the typical block is the brick.
TEST(MaterialStiffness, TypicalBlockIsTheMedian) {
    std::vector<BlockDimensions> blocks(7, {0.1, 0.2, 1.0});
    blocks.push_back({0.1, 0.1, 1.0});
    blocks.push_back({0.1, 0.1, 1.0});
    blocks.push_back({0.15, 1.2, 1.0});
    const BlockDimensions t = typical_block(blocks);
    EXPECT_DOUBLE_EQ(t.height_m, 0.1);
    EXPECT_DOUBLE_EQ(t.width_m, 0.2);
    EXPECT_DOUBLE_EQ(t.thickness_m, 1.0);
}

}  // namespace
}  // namespace blockdem
