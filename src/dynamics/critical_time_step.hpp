#pragma once
// The stable time step of the explicit central-difference scheme, for bodies that carry several
// contact points at once, with rotation and dashpots.
//
// One damped mode of stiffness k, damping c and mass m, integrated by central differences with
// the dashpot fed the velocity of the last half step, is stable for
//     (k/m) dt^2 + 2 (c/m) dt < 4,   i.e.   dt < (2 / w) (sqrt(1 + h^2) - h).
// For many bodies the same scheme is stable while M - (dt/2) C - (dt^2/4) K stays positive
// definite (K, C the contacts' stiffness and damping matrices over every body's x, y and
// rotation; M the masses and inertias). By Weyl's inequality that holds when
//     (dt^2/4) lambda_max(M^-1/2 K M^-1/2) + (dt/2) lambda_max(M^-1/2 C M^-1/2) < 1,
// and Gershgorin's theorem bounds each lambda_max by the largest absolute row sum. A contact
// point between bodies a and b with direction d (its normal or its tangent) adds k g g^T, where
// g = M^-1/2 (-d, -(r_a x d) on a; d, r_b x d on b) and r is the lever from each centroid: so
// row p gains k |g_p| |g|_1. Summing over rows of one body gives that body's bound, with every
// contact it carries, its lever arms and its partners' compliance included. It is a bound, so a
// dt below it is stable; it is within about 1.3 of the exact limit for a block on two corners.
//
// Which contacts: at t = 0, every pair that touches (or overlaps) at the start; a dynamic body
// that touches nothing is taken as landing flat on two corners of a fixed body. During the run
// (world/step.cpp) the same bound is evaluated on the live contact table, so a configuration
// stiffer than the start (a falling block landing on a corner of another, a wall loading up)
// is noticed and reported.
#include <string>
#include <vector>

#include "world/world.hpp"

namespace blockdem {

struct CriticalTimeStep {
    double dt_s = 0.0;       ///< [s] the limit (infinity: no dynamic body carries a contact)
    std::string body;        ///< the body that sets it
    double omega_rad_s = 0.0;///< [rad/s] sqrt of its stiffness row bound: its highest contact frequency
    double h = 0.0;          ///< [-] its damping row bound over 2 omega: the damping ratio used
};

/// One contact point as the stable step sees it.
struct StiffnessPoint {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    Vec2 point_m;             ///< [m]
    Vec2 normal;              ///< unit, from a to b
    double kn_N_m = 0.0;      ///< [N/m]
    double ks_N_m = 0.0;      ///< [N/m]
    double cn_N_s_m = 0.0;    ///< [N s/m]
    double cs_N_s_m = 0.0;    ///< [N s/m]
};

/// The Gershgorin bound over the given points (the bodies' positions are those of the points).
CriticalTimeStep stable_time_step(const Bodies& bodies, const std::vector<StiffnessPoint>& points);

/// The bound over the live contact table, with every point's stiffness and damping as the law
/// applies them; rows is scratch (no allocation once sized).
CriticalTimeStep live_time_step(const World& w, StabilityRows& rows);

/// Each dynamic body's own 3 x 3 blocks of K~ and C~ (the live contact table, its partners held
/// still) tested at dt_s (dynamics/highest_mode.hpp, BodyBlocks: a body whose blocks are unstable
/// at dt_s makes it unstable for certain): the limit of the most unstable body's blocks (below
/// dt_s), or infinity when every body's are stable at dt_s.
CriticalTimeStep body_block_limit(const World& w, double dt_s);

/// The contact points at the start: every pair of the (built) candidate list that touches, and
/// a flat landing on a fixed body for a dynamic body that touches nothing.
std::vector<StiffnessPoint> start_stiffness_points(const World& w);

/// The limit of the points' highest mode, estimated by power iteration on
/// (dt^2/4) K~ + (dt/2) C~ and its Rayleigh quotients: the dt at which M - (dt/2) C - (dt^2/4) K
/// stops being positive definite along that mode. Never below bound (the Gershgorin bound of
/// the same points), which it refines: Gershgorin's row sums add every coupling with the same
/// sign, so for a brick in a wall with six neighbours the bound is 2 to 3 times below the dt at
/// which the scheme really goes unstable.
CriticalTimeStep highest_mode_time_step(const Bodies& bodies, const std::vector<StiffnessPoint>& points,
                                        const CriticalTimeStep& bound);

/// highest_mode_time_step over the live contact table's points, as the law applies them.
CriticalTimeStep live_highest_mode_time_step(const World& w, const CriticalTimeStep& bound);

/// The limits of the start configuration.
struct StartTimeStep {
    CriticalTimeStep proven;        ///< Gershgorin bound: every dt below it is stable
    CriticalTimeStep highest_mode;  ///< the estimated limit of the highest mode (>= proven)
};

/// The limits at the start (build_world and `check`); the world's geometry and candidate pairs
/// must be up to date.
StartTimeStep critical_time_step(const World& w);

}  // namespace blockdem
