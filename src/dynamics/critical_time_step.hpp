#pragma once
// The stable time step of the explicit central-difference scheme.
//
// A damped oscillator of natural circular frequency w and damping ratio h integrated by central
// differences is stable for dt <= (2 / w) (sqrt(1 + h^2) - h). For a rigid block on a contact
// point of stiffness k at distance r from its centroid, the stiffest mode couples translation
// and rotation: w^2 = k (1/m + r^2/I) (the inverse of the effective mass at the corner). We
// take, for each dynamic body, the largest stiffness and damping ratio of any material pair it
// can meet and its bounding radius, add the compliance of the most compliant other dynamic body
// (its possible partner: w^2 = k (1/m_a + r_a^2/I_a + 1/m_b + r_b^2/I_b)), and return the least
// dt over all bodies. The damping ratio
// is that of the corner mode, which is higher than h because the dashpot is sized with the
// body's mass while the corner moves with its smaller effective mass.
//
// This is the limit for one contact point; a body pressed by several points at once has a
// higher frequency (about sqrt(number of points) higher), which is why the derived step uses a
// safety factor (dt_safety, default 0.2) and why the run watches its energy balance.
#include <string>

#include "world/world.hpp"

namespace blockdem {

struct CriticalTimeStep {
    double dt_s = 0.0;       ///< [s] the limit
    std::string body;        ///< the body that sets it
    double omega_rad_s = 0.0;///< [rad/s] its highest contact frequency
    double h = 0.0;          ///< [-] the damping ratio used
};

CriticalTimeStep critical_time_step(const Bodies& bodies, const MaterialPairs& contact);

}  // namespace blockdem
