#pragma once
// Independent reference for rocking: Housner's (1963) equation of motion of a rigid
// rectangular block (half width b, half height h, R = sqrt(b^2 + h^2), alpha = atan(b/h)) on a
// rigid base with horizontal acceleration a_g(t), rocking without sliding or bouncing:
//   theta'' = -p^2 [ s sin(alpha - s theta) - (a_g/g) cos(alpha - s theta) ],  s = sign(theta),
//   p^2 = 3 g / (4 R)   (I_corner = 4/3 m R^2; m g R / I_corner for another body, below),
// with theta counter-clockwise positive (theta > 0: pivot on the left corner, leaning to -x).
// At each impact (theta crosses 0) the angular velocity is multiplied by r; Housner's value
// from conservation of angular momentum about the new corner is r = 1 - 1.5 sin^2 alpha, or
// 1 - (m R^2 / I_corner)(1 - cos 2 alpha) for a body whose moment about its corner is not the
// rectangle's (a column drum: tests/validation/test_cylinder_3d.cpp).
// Rocking starts from rest when |a_g| > g tan(alpha). Integrated with classical RK4.
#include <vector>

#include "motion/table_motion.hpp"

namespace blockdem {

struct HousnerBlock {
    double half_width_m = 0.2;   ///< [m] b
    double half_height_m = 0.8;  ///< [m] h
    double gravity_m_s2 = 9.81;  ///< [m/s^2]
    double restitution = -1.0;   ///< [-] r; negative: Housner's 1 - 1.5 sin^2 alpha
    /// [-] I_corner / (m R^2) of a body that is not a uniform rectangle; 0: the rectangle's 4/3.
    double corner_inertia_ratio = 0.0;

    double alpha_rad() const;
    double p_rad_s() const;
    double housner_restitution() const;
};

struct RockingPoint {
    double time_s = 0.0;
    double theta_rad = 0.0;
    double omega_rad_s = 0.0;
};

struct RockingResult {
    std::vector<RockingPoint> history;
    std::vector<double> impact_times_s;  ///< [s]
    bool overturned = false;             ///< |theta| reached pi/2
    double peak_abs_theta_rad = 0.0;
};

/// Rocking response from theta0, omega0 under the base motion (RestMotion for free rocking).
RockingResult housner_rocking(const HousnerBlock& block, const ComponentMotion& base, double theta0_rad,
                              double omega0_rad_s, double end_s, double dt_s);

}  // namespace blockdem
