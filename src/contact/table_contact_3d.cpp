#include "contact/table_contact_3d.hpp"

#include "laws/linear_spring_dashpot.hpp"

namespace blockdem {

TableContactResult3d table_contact_3d(const RigidBody3d& b, const TablePlane3d& table, const ContactParameters& p,
                                      double dt_s, std::vector<VertexContact3d>& vertices) {
    const Vec3 normal{0.0, 0.0, 1.0};  // from the table (a) to the body (b)
    const double surface_z_m = table.surface_z_m + table.displacement_m.z;
    TableContactResult3d r;
    // First the count, for the dashpots' share of the body's mass.
    for (std::size_t i = 0; i < vertices.size(); ++i)
        if (world_vertex(b, i).z < surface_z_m) ++r.points;
    if (r.points == 0) {
        for (VertexContact3d& v : vertices) v = {};
        return r;
    }
    const DashpotCoefficients c = dashpot_coefficients(p, b.mass_kg / r.points);
    // The body's angular velocity over the last step: the drift turned it about this axis, so
    // its world direction is the same at the step's two ends.
    const Vec3 omega_world = rotate(b.orientation, b.angular_velocity_body_rad_s);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        VertexContact3d& v = vertices[i];
        const Vec3 arm = rotate(b.orientation, b.shape.vertices_m[i]);
        const double overlap_m = surface_z_m - (b.position_m.z + arm.z);
        if (overlap_m <= 0.0) {
            v = {};
            continue;
        }
        if (!v.active) {  // a new point: no history
            v = {};
            v.active = true;
        }
        const Vec3 relative = b.velocity_m_s + cross(omega_world, arm) - table.velocity_m_s;
        const double normal_speed = dot(relative, normal);
        const Vec3 tangential = relative - normal_speed * normal;
        // The normal half of the 2-D law, as it is (no tangential speed: the shear is done below).
        const ContactForce f =
            linear_spring_dashpot(p, c, {overlap_m, normal_speed, 0.0}, {0.0, v.normal_dashpot_n, 0.0}, dt_s);
        const ShearForce3d s = coulomb_slider_3d(p.ks_N_m, c.cs_N_s_m, p.mu * std::max(0.0, f.normal_n), tangential,
                                                 carry_to_normal(v.shear, normal), dt_s);
        v.normal_dashpot_n = f.normal_dashpot_n;
        v.shear = {s.spring_n, s.dashpot_n};
        v.sliding = s.sliding;
        const Vec3 force = f.normal_n * normal + s.total_n;
        r.force_n += force;
        r.torque_n_m += cross(arm, force);
        r.sliding_points += s.sliding ? 1 : 0;
        r.elastic_j += p.ks_N_m > 0.0
                           ? 0.5 * p.kn_N_m * overlap_m * overlap_m + 0.5 * dot(s.spring_n, s.spring_n) / p.ks_N_m
                           : 0.5 * p.kn_N_m * overlap_m * overlap_m;
        r.normal_dashpot_work_j += f.normal_dashpot_work_j;
        r.shear_dashpot_work_j += s.shear_dashpot_work_j;
        r.friction_work_j += s.friction_work_j;
    }
    return r;
}

}  // namespace blockdem
