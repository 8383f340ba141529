#include "dynamics/rigid_body_3d.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "world/world.hpp"  // ModelError

namespace blockdem {

RigidBody3d make_rigid_body_3d(const std::string& name, const std::vector<Vec3>& vertices_m, double density_kg_m3) {
    if (!(density_kg_m3 > 0.0))
        throw ModelError(fmt::format("body '{}': density must be positive, got {:g} kg/m^3", name, density_kg_m3));
    Polyhedron hull;
    try {
        hull = convex_polyhedron(vertices_m);
    } catch (const std::invalid_argument& e) {
        throw ModelError(fmt::format("body '{}': {}", name, e.what()));
    }
    const PolyhedronProperties props = polyhedron_properties(hull);
    const PrincipalAxes axes = principal_axes(props.inertia_m5);
    RigidBody3d b;
    b.name = name;
    b.mass_kg = density_kg_m3 * props.volume_m3;
    b.principal_moments_kg_m2 = density_kg_m3 * axes.moments;
    b.inverse_moments_1_kg_m2 = {1.0 / b.principal_moments_kg_m2.x, 1.0 / b.principal_moments_kg_m2.y,
                                 1.0 / b.principal_moments_kg_m2.z};
    b.position_m = props.centroid_m;
    b.orientation = axes.orientation;
    b.shape = hull;
    for (Vec3& v : b.shape.vertices_m) v = rotate_inverse(axes.orientation, v - props.centroid_m);
    for (Vec3& n : b.shape.face_normals) n = rotate_inverse(axes.orientation, n);
    return b;
}

Vec3 angular_momentum_of(const RigidBody3d& b, Vec3 angular_velocity_world_rad_s) {
    const Vec3 body = rotate_inverse(b.orientation, angular_velocity_world_rad_s);
    return rotate(b.orientation, hadamard(b.principal_moments_kg_m2, body));
}

void set_initial_velocity(RigidBody3d& b, Vec3 velocity_m_s, Vec3 angular_velocity_world_rad_s) {
    b.velocity_m_s = velocity_m_s;
    b.velocity_at_t_m_s = velocity_m_s;
    b.angular_momentum_kg_m2_s = angular_momentum_of(b, angular_velocity_world_rad_s);
    b.angular_velocity_at_t_rad_s = angular_velocity_world_rad_s;
    b.angular_velocity_body_rad_s = rotate_inverse(b.orientation, angular_velocity_world_rad_s);
}

double kinetic_energy(const RigidBody3d& b) {
    const Vec3 w = rotate_inverse(b.orientation, b.angular_velocity_at_t_rad_s);
    return 0.5 * b.mass_kg * dot(b.velocity_at_t_m_s, b.velocity_at_t_m_s) +
           0.5 * dot(w, hadamard(b.principal_moments_kg_m2, w));
}

}  // namespace blockdem
