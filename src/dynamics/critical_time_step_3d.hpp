#pragma once
// The stable time step of the 3-D scheme over the live contact table: the 2-D bound
// (dynamics/critical_time_step.hpp, where the derivation is) with every body's six rows (x, y, z
// and the three rotations). A contact point adds k g g^T for its normal (kn, cn) and for two
// tangents (ks, cs), with g = M^-1/2 (-d, -(r_a x d) on a; d, r_b x d on b), M^-1/2 of a rotation
// being R diag(I^-1/2) R^T in the world frame; Gershgorin's row sums bound the largest eigenvalues
// of M^-1/2 K M^-1/2 and M^-1/2 C M^-1/2 (Lambda_K, Lambda_C), and the scheme is stable for
//     (dt^2 / 4) Lambda_K + (dt / 2) Lambda_C < 1.
// Why it is needed: the brick wall of scenes/brick_wall_3d.hpp with kn = ks = 1e8 N/m goes
// unstable at dt = 5e-5 s through its shear dashpots (docs/3d.md), which one body's vertical
// frequency sqrt(4 kn / m) does not show.
#include <cstdint>
#include <vector>

#include "world/world_3d.hpp"

namespace blockdem {

struct CriticalTimeStep3d {
    double dt_s = 0.0;         ///< [s] the bound (infinity: no dynamic body carries a point)
    std::uint32_t body = 0;    ///< the body whose row sets Lambda_K
    double omega_rad_s = 0.0;  ///< [rad/s] sqrt(Lambda_K)
    double h = 0.0;            ///< [-] Lambda_C / (2 omega)
};

/// The bound over the given points (of w's bodies, at w's poses), with each point's springs and
/// dashpots as the law applies them (kn and ks times the point's stiffness share, which reaches 2
/// at a sharp corner; the pair's reduced mass shared by the shares). Every dt below it is stable.
CriticalTimeStep3d stable_time_step_3d(const World3d& w, const std::vector<ContactPoint3d>& points);

/// The bound over w.contacts.
CriticalTimeStep3d live_time_step_3d(const World3d& w);

/// The limit of the points' highest mode (dynamics/highest_mode.hpp): the dt at which
/// M - (dt/2) C - (dt^2/4) K stops being positive definite along it, estimated by power iteration;
/// never below bound (the points' stable_time_step_3d), which it refines. The Gershgorin row sums
/// are 1.7 to 2.1 times below it for a block on its base, 3.7 to 4 times for a brick in a wall
/// (docs/3d.md). body: the body that moves most in the mode.
CriticalTimeStep3d highest_mode_time_step_3d(const World3d& w, const std::vector<ContactPoint3d>& points,
                                             const CriticalTimeStep3d& bound);

/// Each dynamic body's own 6 x 6 blocks of K~ and C~ (w.contacts, its partners held still) tested
/// at dt_s: a principal block's top eigenvalue is never above the whole matrix's (Cauchy's
/// interlacing), so a body whose block is unstable at dt_s makes dt_s unstable for certain,
/// whatever the layout around it; the single-ratio live watch can miss such a body
/// (world/run_checks_3d.hpp). Returns the limit of the most unstable body's block (below dt_s),
/// or infinity when every block is stable at dt_s. About 100 operations a body past the blocks.
CriticalTimeStep3d body_block_limit_3d(const World3d& w, double dt_s);

/// The limits at the start (world/world_3d_start.hpp: the contacts at the start and the landings
/// of the bodies that touch nothing).
struct StartTimeStep3d {
    CriticalTimeStep3d proven;        ///< every dt below it is stable
    CriticalTimeStep3d highest_mode;  ///< the estimated limit (>= proven)
    std::uint32_t landing_bodies = 0; ///< bodies touching nothing, taken as landing flat
};

}  // namespace blockdem
