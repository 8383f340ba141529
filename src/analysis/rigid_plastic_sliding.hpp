#pragma once
// Independent reference for sliding: Newmark's rigid-plastic block on a moving base (Newmark
// 1965), two-sided. The block moves with the table while |a_table| <= mu g; beyond that it
// slides with acceleration +-mu g (friction drags it after the table) until the relative
// velocity returns to zero, where it sticks again if the table's acceleration allows. No
// springs, no dashpots: this is what a DEM block approaches as its contacts become stiff.
#include <vector>

#include "motion/table_motion.hpp"

namespace blockdem {

struct SlidingPoint {
    double time_s = 0.0;                ///< [s]
    double relative_displacement_m = 0.0;///< [m] block minus table
    double relative_velocity_m_s = 0.0; ///< [m/s]
    double block_acceleration_m_s2 = 0.0;///< [m/s^2]
};

/// Integrates to end_s with step dt_s (trapezoidal with exact table velocity, and the stick
/// instant located within the step). Returns one point per step.
std::vector<SlidingPoint> rigid_plastic_sliding(const ComponentMotion& table, double mu, double gravity_m_s2,
                                                double end_s, double dt_s);

}  // namespace blockdem
