#pragma once
// Contact stiffness from the material: the rule "block_deformability" (docs/physics.md,
// "Choosing the contact stiffness").
//
// The blocks are rigid, so all the deformability of the structure lives in its joints. The rule
// lumps each block's own elastic shortening into the joints that load it: a block of height h
// between two joints gives each of them half its height, a spring of h / (2 E) per unit area
// (normal) and h / (2 G) (shear). A joint between blocks a and b is the two halves in series:
//
//     kn'' = 1 / (h_a / (2 E_a) + h_b / (2 E_b))      [Pa/m], normal stiffness per unit area
//     ks'' = 1 / (h_a / (2 G_a) + h_b / (2 G_b))      [Pa/m], G = E / (2 (1 + nu))
//
// Cundall's corner-to-edge contact puts two points on a face; each carries half of the shared
// face, l = min(w_a, w_b) long and t = min(t_a, t_b) thick:
//
//     kn = kn'' (l / 2) t,   ks = ks'' (l / 2) t                [N/m] per contact point
//
// so that two equal blocks of height h stacked on two points have the axial stiffness
// E (w t) / h of one block, as a continuum column would. ks / kn = G / E = 1 / (2 (1 + nu)).
#include <span>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// An isotropic elastic material.
struct ElasticMaterial {
    double young_modulus_pa = 0.0;  ///< [Pa] E
    double poisson_ratio = 0.2;     ///< [-] nu, in (-1, 0.5)
};

/// A block's dimensions as the rule sees them.
struct BlockDimensions {
    double height_m = 0.0;     ///< [m] across the joint (vertical extent: bed joints carry the weight)
    double width_m = 0.0;      ///< [m] along the joint (horizontal extent)
    double thickness_m = 1.0;  ///< [m] out of plane
};

/// One side of a joint: the block and its material.
struct JointSide {
    ElasticMaterial material;
    BlockDimensions block;
};

/// What the rule gives for one joint, and the intermediate quantities (for `blockdem check`).
struct JointStiffness {
    double kn_per_area_pa_m = 0.0;   ///< [Pa/m] kn''
    double ks_per_area_pa_m = 0.0;   ///< [Pa/m] ks''
    double tributary_length_m = 0.0; ///< [m] l / 2: the face length one contact point carries
    double thickness_m = 0.0;        ///< [m] t: the face thickness
    double kn_N_m = 0.0;             ///< [N/m] per contact point
    double ks_N_m = 0.0;             ///< [N/m] per contact point
};

/// How one pair of materials got its kn and ks (printed by `blockdem check`).
struct StiffnessOrigin {
    bool derived = false;   ///< from the rule; false: given as kn and ks
    JointSide a, b;         ///< the typical blocks and the materials the rule used
    JointStiffness rule;    ///< what the rule gave
    bool kn_given = false;  ///< kn given for this pair in [[contact.pairs]] (overrides the rule)
    bool ks_given = false;  ///< ks likewise
};

/// G = E / (2 (1 + nu)) [Pa].
double shear_modulus_pa(const ElasticMaterial& m);

/// The rule for a joint between the blocks of a and b. Requires E > 0, nu in (-1, 0.5) and
/// positive dimensions (the scenario reader checks them).
JointStiffness block_joint_stiffness(const JointSide& a, const JointSide& b);

/// The bounding box of a block's corners (world coordinates at t = 0) and its thickness.
BlockDimensions block_dimensions(std::span<const Vec2> vertices_m, double thickness_m);

/// The typical block of a set: the median of each dimension separately (a wall of bricks and a
/// few half bricks gives the brick). The set must not be empty.
BlockDimensions typical_block(const std::vector<BlockDimensions>& blocks);

}  // namespace blockdem
