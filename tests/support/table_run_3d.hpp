#pragma once
// Test support: one 3-D body on the table, stepped in the 2-D engine's order (contacts and
// forces at t, the kick, the ledger at t, the drift), until a World3d does it.
#include <algorithm>
#include <vector>

#include "contact/table_contact_3d.hpp"
#include "dynamics/rigid_rotation_3d.hpp"
#include "motion/table_motion.hpp"
#include "world/energy_ledger.hpp"

namespace blockdem::testing {

// A body on a table shaken along the horizontal unit vector `direction` by `horizontal` (and
// along y by `along_y`, along z by `vertical`); advanced by the step of the 2-D engine (world/step.cpp), written out,
// with the energy ledger filled as that step fills it.
struct TableRun3d {
    RigidBody3d body;
    std::vector<VertexContact3d> vertices;
    ContactParameters contact;
    ComponentMotion horizontal = RestMotion{};
    Vec3 direction{1.0, 0.0, 0.0};
    ComponentMotion along_y = RestMotion{};  ///< a second horizontal component, along y
    ComponentMotion vertical = RestMotion{};  ///< the vertical component, along z
    double gravity_m_s2 = 9.81;
    double dt_s = 1e-4;
    double time_s = 0.0;
    int steps = 0;
    EnergyLedger ledger;
    TableContactResult3d last;

    Vec3 table_displacement(double t_s) const {
        return sample(horizontal, t_s).displacement_m * direction +
               Vec3{0.0, sample(along_y, t_s).displacement_m, sample(vertical, t_s).displacement_m};
    }

    void step() {
        const double dt = dt_s;
        const TablePlane3d table{0.0, table_displacement(time_s),
                                 (1.0 / dt) * (table_displacement(time_s) - table_displacement(time_s - dt))};
        last = table_contact_3d(body, table, contact, dt, vertices);
        body.force_n = last.force_n + Vec3{0.0, 0.0, -gravity_m_s2 * body.mass_kg};
        body.torque_n_m = last.torque_n_m;
        update_velocity_3d(body, dt, steps == 0);
        // The ledger at t, as the 2-D step fills it.
        ledger.kinetic_j = kinetic_energy(body);
        ledger.gravitational_j = body.mass_kg * gravity_m_s2 * body.position_m.z;
        ledger.elastic_j = last.elastic_j;
        ledger.normal_dashpot_j += last.normal_dashpot_work_j;
        ledger.shear_dashpot_j += last.shear_dashpot_work_j;
        ledger.friction_j += last.friction_work_j;
        // The table's work pairs the contact force at t with the centred displacement, as the
        // scheme's energy identity does (dynamics/central_difference.cpp).
        ledger.table_work_j +=
            dot(last.force_n, 0.5 * (table_displacement(time_s + dt) - table_displacement(time_s - dt)));
        if (steps == 0) {
            ledger.initial_j = ledger.stored_j();
            ledger.initial_gravitational_j = ledger.gravitational_j;
        }
        ledger.peak_scale_j = std::max(ledger.peak_scale_j, ledger.current_scale_j());
        update_position_3d(body, dt);
        time_s += dt;
        ++steps;
    }
};

/// A run of body on a still table with the given contact; gravity on, dt 1e-4 s.
inline TableRun3d table_run(RigidBody3d body, const ContactParameters& contact) {
    TableRun3d run{.body = std::move(body), .vertices = {}, .contact = contact};
    run.vertices.resize(run.body.shape.vertices_m.size());
    return run;
}

}  // namespace blockdem::testing
