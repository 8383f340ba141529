#include "laws/linear_spring_dashpot.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {

DashpotCoefficients dashpot_coefficients(const ContactParameters& p, double mass_kg) {
    return {2.0 * p.h_n * std::sqrt(mass_kg * p.kn_N_m), 2.0 * p.h_s * std::sqrt(mass_kg * p.ks_N_m)};
}

ContactForce linear_spring_dashpot(const ContactParameters& p, const DashpotCoefficients& c,
                                   const ContactKinematics& k, double previous_shear_spring_n, double dt_s) {
    ContactForce f;
    const double spring_n = p.kn_N_m * k.overlap_m;
    // No tension: the dashpot may only reduce the compressive force to zero.
    f.normal_n = std::max(0.0, spring_n - c.cn_N_s_m * k.normal_speed_m_s);
    const double normal_dashpot_n = f.normal_n - spring_n;
    f.normal_dashpot_work_j = -normal_dashpot_n * k.normal_speed_m_s * dt_s;

    // The slider's dissipation has two parts: if the cap fell below last step's spring force
    // (the normal force dropped), the excess spring energy is released at once; then the slip
    // beyond the cap, (|trial| - limit) / ks, happens against the force mu F_n.
    const double limit_n = p.mu * f.normal_n;
    const double previous_n = std::clamp(previous_shear_spring_n, -limit_n, limit_n);
    const double released_j =
        0.5 * (previous_shear_spring_n * previous_shear_spring_n - previous_n * previous_n) / p.ks_N_m;
    const double trial_spring_n = previous_n - p.ks_N_m * k.tangential_speed_m_s * dt_s;
    if (std::abs(trial_spring_n) > limit_n || released_j > 0.0) {
        f.sliding = true;
        f.shear_spring_n = std::clamp(trial_spring_n, -limit_n, limit_n);
        f.shear_n = f.shear_spring_n;
        f.friction_work_j = released_j + limit_n * std::max(0.0, std::abs(trial_spring_n) - limit_n) / p.ks_N_m;
    } else {
        f.shear_spring_n = trial_spring_n;
        const double dashpot_n = -c.cs_N_s_m * k.tangential_speed_m_s;
        f.shear_n = std::clamp(trial_spring_n + dashpot_n, -limit_n, limit_n);
        f.shear_dashpot_work_j = -(f.shear_n - trial_spring_n) * k.tangential_speed_m_s * dt_s;
    }
    return f;
}

double contact_elastic_energy(const ContactParameters& p, double overlap_m, double shear_spring_n) {
    const double shear_energy = p.ks_N_m > 0.0 ? 0.5 * shear_spring_n * shear_spring_n / p.ks_N_m : 0.0;
    return 0.5 * p.kn_N_m * overlap_m * overlap_m + shear_energy;
}

}  // namespace blockdem
