#pragma once
// Parameters of the linear spring-dashpot-slider contact (Cundall 1971) for one pair of
// materials, after calibration: what the time step uses.

namespace blockdem {

struct ContactParameters {
    double kn_N_m = 0.0;  ///< [N/m] normal stiffness of one contact point
    double ks_N_m = 0.0;  ///< [N/m] shear stiffness of one contact point
    double mu = 0.0;      ///< [-] Coulomb friction coefficient
    double h_n = 0.0;     ///< [-] normal damping ratio
    double h_s = 0.0;     ///< [-] shear damping ratio
};

}  // namespace blockdem
