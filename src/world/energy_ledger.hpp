#pragma once
// The energy balance of a run. Stored energies are the current values; dissipated energies and
// the table's work are running sums. With E0 the initial stored energy,
//   kinetic + gravitational + elastic + dissipated + removed - table_work - tilt_work - external_work = E0
// (up to the scheme's error), where external_work is what a caller's loads and velocity changes did
// (world/external_loads.hpp; 0 in a run of the CLI), removed is the kinetic and gravitational energy that bodies
// leaving the model took with them (world/model_domain.hpp), gravitational is -m g . x, and
// tilt_work is the work a turning gravity (a tilting table, tilt_rate_deg_s) did on the bodies,
// -integral of dg/dt . sum(m x) dt (world/step.cpp),
// and balance_error() is the mismatch relative to the largest term.
#include <algorithm>
#include <cmath>

namespace blockdem {

struct EnergyLedger {
    double kinetic_j = 0.0;          ///< [J] now
    double gravitational_j = 0.0;    ///< [J] now, m g y summed over dynamic bodies
    double elastic_j = 0.0;          ///< [J] now, stored in contact springs
    double normal_dashpot_j = 0.0;   ///< [J] dissipated so far
    double shear_dashpot_j = 0.0;    ///< [J] dissipated so far
    double friction_j = 0.0;         ///< [J] dissipated so far
    double table_work_j = 0.0;       ///< [J] work done by driven bodies on the rest so far
    double initial_j = 0.0;          ///< [J] stored energy at t = 0
    double initial_gravitational_j = 0.0;  ///< [J] gravitational part of initial_j
    double peak_scale_j = 0.0;       ///< [J] the largest term seen so far in the run
    // (Last, so that code filling the ledger in order, e.g. the energy tests, is unchanged.)
    double removed_j = 0.0;          ///< [J] kinetic + gravitational energy of bodies taken out of the model, at removal
    double tilt_work_j = 0.0;        ///< [J] work done on the bodies by gravity turning (tilt_rate), so far
    double bond_breakage_j = 0.0;    ///< [J] released by bonds that broke, so far (laws/mohr_coulomb_joint.hpp)
    double external_work_j = 0.0;    ///< [J] done on the bodies by external loads and velocity changes, so far (world/external_loads.hpp)

    double stored_j() const { return kinetic_j + gravitational_j + elastic_j; }
    double dissipated_j() const { return normal_dashpot_j + shear_dashpot_j + friction_j + bond_breakage_j; }
    double residual_j() const {
        return stored_j() + dissipated_j() + removed_j - table_work_j - tilt_work_j - external_work_j - initial_j;
    }
    /// The largest term of the balance now [J]; gravitational energy counts by its change since t = 0
    /// (with what the bodies taken out carried away, so that a removal does not look like a change).
    double current_scale_j() const {
        return std::max({kinetic_j, std::abs(gravitational_j + removed_j - initial_gravitational_j), elastic_j, dissipated_j(),
                         std::abs(table_work_j), std::abs(tilt_work_j), std::abs(external_work_j), 1e-300});
    }
    /// The largest term over the run so far [J] (a term passing through zero does not inflate the error).
    double scale_j() const { return std::max(peak_scale_j, current_scale_j()); }
    double balance_error() const { return std::abs(residual_j()) / scale_j(); }
};

}  // namespace blockdem
