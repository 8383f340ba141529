#pragma once
// Loads and velocity changes applied to 3-D bodies from outside the model, by a caller that steps
// the world itself (the Python module: Simulation3d.set_external_force, set_velocity): the 3-D
// counterpart of world/external_loads.hpp, with the same structure. A force at the centroid and a
// torque (world frame) per body, held until changed; none by default, and then the step reads
// nothing. Their work is booked in the energy ledger (external_work_j), so that the balance and
// its guard stay closed.
//
// (A separate file and not the 2-D one templated on the vector types: the 2-D bodies are arrays
// per quantity with a scalar torque and a scalar angular velocity, the 3-D ones a struct per body
// that carries the angular momentum, so that the held torque and the kinetic energy are worked
// out differently; only the shape of the concept is shared.)
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"

namespace blockdem {

struct World3d;

struct ExternalLoads3d {
    std::vector<Vec3> force_n;        ///< [N] per body, at its centroid, world frame (empty: no loads)
    std::vector<Vec3> torque_n_m;     ///< [N m] per body, about its centroid, world frame
    // A held velocity is an external load too: each step, the force and torque that bring the
    // body's half-step velocity and angular momentum to the held ones (written into force_n,
    // torque_n_m), so that its work is booked as any load's and the ledger stays closed.
    std::vector<std::uint8_t> held;                    ///< per body: 1 while its velocity is held
    std::vector<Vec3> held_velocity_m_s;               ///< [m/s] per body, while held
    std::vector<Vec3> held_angular_velocity_rad_s;     ///< [rad/s] per body, world frame, while held

    bool any() const { return !force_n.empty(); }
};

/// Sets body i's external force [N] and torque [N m] (world frame) from the next step on (a
/// dynamic body's only).
void set_external_load(World3d& w, std::uint32_t i, Vec3 force_n, Vec3 torque_n_m);
/// Removes every external load and held velocity.
void clear_external_loads(World3d& w);
/// Adds body i's external load to its force and torque sums (step_3d.cpp, after the contacts');
/// for a held body, first sets that load to what holds its velocity.
void add_external_load(World3d& w, std::size_t i);
/// [J] the work the external loads did over the step just drifted (step_3d.cpp, after the drift):
/// the force on the centroid's displacement and the torque on the turn, the increments the
/// positions and orientations took.
double external_load_work(const World3d& w);
/// Holds body i's velocity [m/s] and angular velocity [rad/s, world frame] from t on
/// (set_body_velocity, its kinetic energy change booked as external work), until released,
/// whatever the contacts and gravity do (its external load while held is the force that does it,
/// and replaces any load set on it).
void hold_body_velocity(World3d& w, std::uint32_t i, Vec3 velocity_m_s, Vec3 angular_velocity_rad_s);
/// Releases body i's held velocity; its external load is then none.
void release_body_velocity(World3d& w, std::uint32_t i);
/// Sets body i's velocity [m/s] and angular velocity [rad/s, world frame] for the coming step (the
/// state at t is complete: the change acts from t on); the kinetic energy it adds is booked as
/// external work (before the first step it is the initial state, in the ledger's initial energy).
void set_body_velocity(World3d& w, std::uint32_t i, Vec3 velocity_m_s, Vec3 angular_velocity_rad_s);

}  // namespace blockdem
