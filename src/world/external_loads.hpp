#pragma once
// Loads and velocity changes applied to bodies from outside the model, by a caller that steps
// the world itself (the Python module: Simulation.set_external_force, set_velocity). A force at
// the centroid and a torque per body, held until changed; none by default, and then the step
// reads nothing. Their work is booked in the energy ledger (external_work_j), so that the
// balance and its guard stay closed.
#include <cstdint>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

struct World;

struct ExternalLoads {
    std::vector<Vec2> force_n;        ///< [N] per body, at its centroid (empty: no loads)
    std::vector<double> torque_n_m;   ///< [N m] per body, counter-clockwise
    // A held velocity is an external load too: each step, the force and torque that bring the
    // body's half-step velocity to the held one (written into force_n, torque_n_m), so that its
    // work is booked as any load's and the ledger stays closed with no other term.
    std::vector<std::uint8_t> held;               ///< per body: 1 while its velocity is held
    std::vector<Vec2> held_velocity_m_s;          ///< [m/s] per body, while held
    std::vector<double> held_angular_velocity_rad_s;   ///< [rad/s] per body, while held

    bool any() const { return !force_n.empty(); }
};

/// Sets body i's external force and torque from the next step on (a dynamic body's only).
void set_external_load(World& w, std::uint32_t i, Vec2 force_n, double torque_n_m);
/// Removes every external load.
void clear_external_loads(World& w);
/// Adds body i's external load to its force and torque sums (step.cpp, after the contacts'); for a
/// held body, first sets that load to what holds its velocity.
void add_external_load(World& w, std::size_t i);
/// [J] the work the external loads do over the coming step, at the half-step velocities
/// (step.cpp, before the positions move: the same increments as the positions').
double external_load_work(const World& w);
/// Holds body i's velocity [m/s] and angular velocity [rad/s] from t on (set_body_velocity, its
/// kinetic energy change booked as external work), until
/// released, whatever the contacts and gravity do (its external load while held is the force
/// that does it, and replaces any load set on it).
void hold_body_velocity(World& w, std::uint32_t i, Vec2 velocity_m_s, double angular_velocity_rad_s);
/// Releases body i's held velocity; its external load is then none.
void release_body_velocity(World& w, std::uint32_t i);
/// Sets body i's velocity [m/s] and angular velocity [rad/s] for the coming step (the state at
/// t is complete: the change acts from t on); the kinetic energy it adds is booked as external
/// work.
void set_body_velocity(World& w, std::uint32_t i, Vec2 velocity_m_s, double angular_velocity_rad_s);

}  // namespace blockdem
