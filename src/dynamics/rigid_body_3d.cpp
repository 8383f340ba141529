#include "dynamics/rigid_body_3d.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "world/world.hpp"  // ModelError

namespace blockdem {

namespace {

// The hull from make_hull, its failure reported as the body's.
template <class MakeHull>
Polyhedron checked_hull(const std::string& name, double density_kg_m3, MakeHull make_hull) {
    if (!(density_kg_m3 > 0.0))
        throw ModelError(fmt::format("body '{}': density must be positive, got {:g} kg/m^3", name, density_kg_m3));
    try {
        return make_hull();
    } catch (const std::invalid_argument& e) {
        throw ModelError(fmt::format("body '{}': {}", name, e.what()));
    }
}

// The body of a checked hull: its centroid and principal axes become the body frame.
RigidBody3d body_of(const std::string& name, const Polyhedron& hull, double density_kg_m3) {
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

}  // namespace

RigidBody3d make_rigid_body_3d(const std::string& name, const std::vector<Vec3>& vertices_m, double density_kg_m3) {
    return body_of(name, checked_hull(name, density_kg_m3, [&] { return convex_polyhedron(vertices_m); }), density_kg_m3);
}

RigidBody3d make_rigid_body_3d(const std::string& name, const std::vector<Vec3>& vertices_m,
                               const std::vector<std::vector<std::size_t>>& faces, double density_kg_m3) {
    return body_of(name, checked_hull(name, density_kg_m3, [&] { return convex_polyhedron(vertices_m, faces); }),
                   density_kg_m3);
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
