#pragma once
// A convex polyhedron against the table: the half-space below a horizontal plane that moves with
// the table (docs/3d.md). Each vertex below the plane is a contact point, as a corner on an edge
// is in 2-D: a face lying on the table carries its corners, an edge its two ends. The law is the
// 2-D one (laws/linear_spring_dashpot.hpp) for the normal force, with the shear spring a vector
// in the table's plane (laws/coulomb_slider_3d.hpp); the dashpots use the body's mass shared
// among its points in contact (docs/physics.md, "Which mass the damping uses").
#include <vector>

#include "dynamics/rigid_body_3d.hpp"
#include "laws/coulomb_slider_3d.hpp"
#include "laws/contact_parameters.hpp"

namespace blockdem {

/// The table at t: its surface at rest, and its motion.
struct TablePlane3d {
    double surface_z_m = 0.0;  ///< [m] height of the surface when the table is at rest
    Vec3 displacement_m;       ///< [m] the table's displacement at t
    Vec3 velocity_m_s;         ///< [m/s] its velocity over the interval that ends at t (t - dt/2)
};

/// One vertex's history against the table (one per body vertex).
struct VertexContact3d {
    bool active = false;
    double normal_dashpot_n = 0.0;  ///< [N] last step's normal dashpot force on the body
    ShearHistory3d shear;
    bool sliding = false;           ///< this step's state, for output
};

/// What the table does to the body this step.
struct TableContactResult3d {
    Vec3 force_n;                       ///< [N] on the body, world frame
    Vec3 torque_n_m;                    ///< [N m] on the body about its centroid
    int points = 0;                     ///< vertices in contact
    int sliding_points = 0;             ///< of which sliding
    double elastic_j = 0.0;             ///< [J] stored in the points' springs now
    double normal_dashpot_work_j = 0.0; ///< [J] dissipated over the interval that ends now
    double shear_dashpot_work_j = 0.0;  ///< [J]
    double friction_work_j = 0.0;       ///< [J]
};

/// The table's contact forces on body b at t (positions at t, velocities of the interval that
/// ends at t), updating each vertex's history in `vertices` (sized to the body's vertices).
TableContactResult3d table_contact_3d(const RigidBody3d& b, const TablePlane3d& table, const ContactParameters& p,
                                      double dt_s, std::vector<VertexContact3d>& vertices);

}  // namespace blockdem
