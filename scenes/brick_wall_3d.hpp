#pragma once
// A 3-D brick wall on a shaken base (issue 15's benchmark scene): boxes in running bond, in
// wythes side by side, on a driven slab. Shared by the benchmark and the thread-count test.
#include "world/world_3d.hpp"

namespace blockdem::scenes {

struct BrickWall3dDef {
    int courses = 10;
    int bricks_per_course = 50;            ///< in each wythe
    int wythes = 2;
    Vec3 brick_m{0.4, 0.2, 0.2};           ///< [m] length (along x), thickness (y), height
    double density_kg_m3 = 2000.0;         ///< [kg/m^3]
    ContactParameters contact{.kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.6, .h_n = 0.3, .h_s = 0.3};
    ComponentMotion shaking = SineMotion{1.0, 0.5, 0.0, 0.0, 0.0};  ///< along x
    /// [s] Measured: the settling wall's ledger closes to 3e-4 at 2.5e-5 s and 1.4e-4 at 1.25e-5 s,
    /// but the shear dashpots of points with little effective mass go unstable at 5e-5 s (1.8e-2,
    /// growing); dynamics/critical_time_step_3d.hpp bounds it at 1.32e-5 s (settled, 288 boxes).
    double dt_s = 2e-5;
};

/// One brick of the wall: its course, wythe and place in the course, and its centre [m] with the
/// wall's lowest face at z = 0, its first brick's end at x = 0 and its first wythe's face at y = 0.
struct BrickPlacement3d {
    int course = 0;
    int wythe = 0;
    int index = 0;
    Vec3 centre_m;
};

/// The bricks in running bond (odd courses shifted by half a brick and one brick shorter, so that
/// none overhangs the one below), course by course: shared by the scene and the scenario's
/// brick_wall assembly (io/scenario_3d.cpp, which refuses bricks_per_course = 1 with more than
/// one course: its odd courses would be empty).
std::vector<BrickPlacement3d> running_bond_3d(int courses, int bricks_per_course, int wythes, Vec3 brick_m);

/// The wall, every brick placed touching its neighbours; body 0 is the driven slab.
World3d brick_wall_3d(const BrickWall3dDef& def);

}  // namespace blockdem::scenes
