#include "world/external_loads_3d.hpp"

#include "dynamics/rigid_body_3d.hpp"
#include "geometry/quaternion.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

namespace {

ExternalLoads3d& allocated_loads(World3d& w) {
    ExternalLoads3d& loads = w.external_loads;
    if (!loads.any()) {
        loads.force_n.assign(w.bodies.size(), Vec3{});
        loads.torque_n_m.assign(w.bodies.size(), Vec3{});
        loads.held.assign(w.bodies.size(), 0);
        loads.held_velocity_m_s.assign(w.bodies.size(), Vec3{});
        loads.held_angular_velocity_rad_s.assign(w.bodies.size(), Vec3{});
    }
    return loads;
}

// [J] the body's kinetic energy at its stored (half-step) velocity and angular momentum, at its
// orientation now.
double stored_kinetic_energy(const RigidBody3d& b) {
    const Vec3 omega_body = hadamard(b.inverse_moments_1_kg_m2, rotate_inverse(b.orientation, b.angular_momentum_kg_m2_s));
    return 0.5 * b.mass_kg * dot(b.velocity_m_s, b.velocity_m_s) +
           0.5 * dot(omega_body, hadamard(b.principal_moments_kg_m2, omega_body));
}

}  // namespace

void set_external_load(World3d& w, std::uint32_t i, Vec3 force_n, Vec3 torque_n_m) {
    ExternalLoads3d& loads = allocated_loads(w);
    loads.force_n[i] = force_n;
    loads.torque_n_m[i] = torque_n_m;
}

void clear_external_loads(World3d& w) {
    w.external_loads = ExternalLoads3d{};
}

void hold_body_velocity(World3d& w, std::uint32_t i, Vec3 velocity_m_s, Vec3 angular_velocity_rad_s) {
    // From t on, as set_body_velocity (this step's half-step velocity is already computed); the
    // held load keeps it from the next kick on.
    set_body_velocity(w, i, velocity_m_s, angular_velocity_rad_s);
    ExternalLoads3d& loads = allocated_loads(w);
    loads.held[i] = 1;
    loads.held_velocity_m_s[i] = velocity_m_s;
    loads.held_angular_velocity_rad_s[i] = angular_velocity_rad_s;
}

void release_body_velocity(World3d& w, std::uint32_t i) {
    if (!w.external_loads.any()) return;
    w.external_loads.held[i] = 0;
    set_external_load(w, i, Vec3{}, Vec3{});
}

void add_external_load(World3d& w, std::size_t i) {
    if (w.kinds[i] != BodyKind3d::dynamic) return;  // (only dynamic bodies are kicked)
    RigidBody3d& b = w.bodies[i];
    ExternalLoads3d& loads = w.external_loads;
    if (loads.held[i] != 0) {
        // The total force and torque that take the stored velocity and angular momentum to the
        // held ones over the coming kick (rigid_rotation_3d.hpp: a whole step, or the first half
        // step while the velocities are not yet staggered); the load is what the contacts and
        // gravity lack. The held angular velocity's momentum is at the orientation at t.
        const double span_s = w.steps == 0 ? 0.5 * w.dt_s : w.dt_s;
        const Vec3 total_n = (b.mass_kg / span_s) * (loads.held_velocity_m_s[i] - b.velocity_m_s);
        const Vec3 total_n_m =
            (1.0 / span_s) * (angular_momentum_of(b, loads.held_angular_velocity_rad_s[i]) - b.angular_momentum_kg_m2_s);
        loads.force_n[i] = total_n - b.force_n;
        loads.torque_n_m[i] = total_n_m - b.torque_n_m;
    }
    b.force_n += loads.force_n[i];
    b.torque_n_m += loads.torque_n_m[i];
}

double external_load_work(const World3d& w) {
    // After the drift: the centroid moved by dt v(t + dt/2), and the body turned by dt times its
    // body-frame angular velocity over the step, which the orientation at t (the pose's matrix)
    // takes to the world frame (the axis of a turn is the same before and after it).
    double work_j = 0.0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic || is_taken_out(w.domain, i)) continue;
        const RigidBody3d& b = w.bodies[i];
        const Vec3 omega_rad_s = w.scratch.rotations[i] * b.angular_velocity_body_rad_s;
        work_j += (dot(w.external_loads.force_n[i], b.velocity_m_s) + dot(w.external_loads.torque_n_m[i], omega_rad_s)) * w.dt_s;
    }
    return work_j;
}

void set_body_velocity(World3d& w, std::uint32_t i, Vec3 velocity_m_s, Vec3 angular_velocity_rad_s) {
    RigidBody3d& b = w.bodies[i];
    const double before_j = stored_kinetic_energy(b);
    b.velocity_m_s = velocity_m_s;
    b.angular_momentum_kg_m2_s = angular_momentum_of(b, angular_velocity_rad_s);
    // Before the first step the velocity is part of the initial state, which the first step
    // books as the initial energy (its ledger has no scale yet): it is not work then.
    if (w.ledger.peak_scale_j > 0.0) w.ledger.external_work_j += stored_kinetic_energy(b) - before_j;
}

}  // namespace blockdem
