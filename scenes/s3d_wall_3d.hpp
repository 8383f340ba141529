#pragma once
// The peers' scene S3D (shared/peers/three_d/README.md), so that our figures sit beside Bullet's,
// ODE's and YADE's on the same wall: N bricks 0.2 x 0.1 x 0.1 m of 2000 kg/m^3 in two wythes,
// each in running bond, 1 mm head and collar gaps, bed joints closed by the springs' static
// compression (S3D places them touching; see s3d_wall_3d.cpp, course_sinking_m, for why), on a
// driven base box shaken out of plane (along y) by a = 0.3 g sin(4 pi t) from rest once the wall
// has settled.
// The benchmark (benchmarks/bench_world_3d.cpp) and the thread-count test use it.
#include <vector>

#include "world/world_3d.hpp"

namespace blockdem::scenes {

struct S3dWallDef {
    int bricks = 1000;                      ///< N, filled course by course, wythe 0 then wythe 1
    Vec3 brick_m{0.2, 0.1, 0.1};            ///< [m] length (x), thickness (y), height (z)
    double gap_m = 0.001;                   ///< [m] head and collar joints
    double density_kg_m3 = 2000.0;          ///< [kg/m^3]
    /// S3D asks for about 1e8 N/m a contact (4 x 2.5e7 N/m a point) at dt = 1e-4 s; for a 4 kg
    /// brick that is beyond this explicit scheme's stable step (dynamics/critical_time_step_3d.hpp
    /// bounds it at 2e-5 s on the settled wall), so the stiffness is lowered, not the step:
    /// 1e6 N/m a point (bound 2.1e-4 s measured). The cost of a step does not depend on kn beyond
    /// the number of points, which is the same (4 a bed patch).
    ContactParameters contact{.kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.6, .h_n = 0.05, .h_s = 0.05};
    double amplitude_m_s2 = 0.3 * 9.81;     ///< [m/s^2] along y
    double period_s = 0.5;                  ///< [s] 2 Hz
    double dt_s = 1e-4;                     ///< [s]
    int settling_steps = 100;               ///< steps with the base still before the shaking starts
};

/// The bricks' centres [m] (S3D's layout: C = round(sqrt(N)) bricks a wythe in even courses, C - 1
/// shifted by half a pitch in odd ones, wythe centres at y = -/+ (t + gap) / 2, base top at z = 0,
/// each course lowered by its bed joints' static compression);
/// returns them and sets per_course to C.
std::vector<Vec3> s3d_brick_centres(const S3dWallDef& def, int& per_course);

/// The wall and its base (body 0, driven), the shaking starting after settling_steps steps.
World3d s3d_wall_3d(const S3dWallDef& def);

/// The wall after its settling steps: time is then the shaking's start.
World3d settled_s3d_wall_3d(const S3dWallDef& def);

}  // namespace blockdem::scenes
