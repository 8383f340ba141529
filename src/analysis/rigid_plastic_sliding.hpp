#pragma once
// Independent reference for sliding: Newmark's rigid-plastic block on a moving base (Newmark
// 1965), two-sided, on a level base or on an incline. The block moves with the table while
// friction can hold it; beyond that it slides with the friction force mu N against its relative
// velocity until that velocity returns to zero, where it sticks again if friction allows. No
// springs, no dashpots: this is what a DEM block approaches as its contacts become stiff.
//
// On an incline, in the surface's own frame (s along the surface, n its outward normal), with
// gravity's components g_s along it and g_n into it and the table accelerating by a(t) along the
// surface (a shaking table tilted with the incline), the block's acceleration relative to the
// table is g_s - a(t) - mu g_n sign(v) while it slides: friction can hold it while
// |g_s - a(t)| <= mu g_n. The two yield accelerations differ: down the slope the table need only
// reach g (mu cos th - sin th) against it, up the slope g (mu cos th + sin th).
#include <vector>

#include "motion/table_motion.hpp"

namespace blockdem {

struct SlidingPoint {
    double time_s = 0.0;                ///< [s]
    double relative_displacement_m = 0.0;///< [m] block minus table, along the surface
    double relative_velocity_m_s = 0.0; ///< [m/s]
    double block_acceleration_m_s2 = 0.0;///< [m/s^2] the block's absolute acceleration along the surface
};

/// The surface the block slides on, in its own frame.
struct SlidingSurface {
    double mu = 0.0;                    ///< [-] Coulomb friction coefficient
    double gravity_along_m_s2 = 0.0;    ///< [m/s^2] gravity's component along the surface's +s direction
    double gravity_into_m_s2 = 9.81;    ///< [m/s^2] gravity's component into the surface (> 0)
};

/// An incline at slope_rad whose +s direction points up the slope: g_s = -g sin th, g_n = g cos th.
SlidingSurface incline_surface(double mu, double slope_rad, double gravity_m_s2);

/// Integrates to end_s with step dt_s (trapezoidal with exact table velocity, and the stick
/// instant located within the step) for a table accelerating by `table` along the surface's +s.
/// Returns one point per step.
std::vector<SlidingPoint> rigid_plastic_sliding(const ComponentMotion& table, const SlidingSurface& surface, double end_s,
                                                double dt_s);

/// On a level table (g_s = 0, g_n = gravity_m_s2).
std::vector<SlidingPoint> rigid_plastic_sliding(const ComponentMotion& table, double mu, double gravity_m_s2,
                                                double end_s, double dt_s);

}  // namespace blockdem
