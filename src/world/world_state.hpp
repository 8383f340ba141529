#pragma once
// The state a run needs to go on from step n exactly as if it had never stopped: what the state
// files hold (io/state_file.hpp). It is taken between two steps, after step_end and before the
// next step_begin (step.hpp), where nothing is half-computed: positions at t, velocities at
// t - dt/2 once the leapfrog has started (World::velocities_staggered), the contact table with
// every pair's shear history and last dashpot forces (the trapezoidal dissipation reads them),
// the broad phase's rebuild positions (they decide when it next rebuilds, and so the order of
// the contact table), the energy ledger, the stability watch, the bodies that left the model
// and a caller's external loads and held velocities (world/external_loads.hpp).
// Everything else in World is either built from the scenario (geometry, masses, materials, the
// table motion) or recomputed by the next step_begin (corners, forces, accelerations).
//
// No random stream exists at run time (synthetic motions are drawn from their seed while the
// scenario is read), so none is kept.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "world/world.hpp"

namespace blockdem {

struct WorldState {
    double time_s = 0.0;                  ///< [s]
    std::int64_t step_index = 0;
    double dt_s = 0.0;                    ///< [s] the step it was run with
    double critical_dt_s = 0.0;           ///< [s]
    double proven_stable_dt_s = 0.0;      ///< [s]
    double settling_time_s = 0.0;         ///< [s]
    std::optional<SettlingRecord> settling;  ///< what settling did before t = 0 (summary.json reports it)
    bool velocities_staggered = false;
    std::int64_t broad_phase_rebuilds = 0;

    // Per body, in body id order.
    std::vector<std::string> name;
    std::vector<BodyKind> kind;
    std::vector<std::uint32_t> vertex_count;
    std::vector<Vec2> local_vertices_m;     ///< [m] the geometry, to recognise the bodies
    std::vector<double> mass_kg;            ///< [kg] to recognise a changed density (empty: a file from before them)
    std::vector<double> inertia_kg_m2;      ///< [kg m^2] about the centroid, likewise
    std::vector<std::uint8_t> is_static;    ///< 1 also for bodies taken out of the model
    std::vector<Vec2> position_m;           ///< [m] at t
    std::vector<double> rotation_rad;       ///< [rad] at t
    std::vector<Vec2> velocity_m_s;         ///< [m/s] at t - dt/2 (at t when !velocities_staggered)
    std::vector<double> angular_velocity_rad_s;  ///< [rad/s] likewise
    std::vector<Vec2> velocity_at_t_m_s;    ///< [m/s] at t (the mean of the half steps): the start's kinetic energy
    std::vector<double> angular_velocity_at_t_rad_s;  ///< [rad/s] likewise
    std::vector<Vec2> initial_position_m;   ///< [m] at t = 0
    std::vector<Vec2> world_vertices_m;     ///< [m] corners as the last step saw them (the response monitor reads them at t = 0)
    std::vector<Vec2> world_normals;        ///< likewise, the outward edge normals
    std::vector<Vec2> position_at_rebuild_m;     ///< [m] empty before the first rebuild
    std::vector<double> rotation_at_rebuild_rad; ///< [rad] likewise

    std::vector<PairContact> contacts;    ///< the whole table, pairs apart included
    std::vector<SubContacts> sub_contacts;  ///< aligned with contacts, or empty (contact/sub_contacts.hpp)
    EnergyLedger energy;
    StabilityWatch stability;
    std::vector<BodyLeftModel> left;      ///< bodies taken out of the model, in the order they left
    ExternalLoads external_loads;         ///< a caller's loads and held velocities (none: empty)
};

/// The state of w, taken between two steps.
WorldState capture_state(const World& w);

/// Why the state cannot belong to w's scenario (another body count, name, kind or shape), or
/// nullopt when it can.
std::optional<std::string> state_mismatch(const World& w, const WorldState& s);

/// Why a restart cannot go on from s in w (a dynamic body whose mass or moment of inertia
/// differs: the state's momenta and energy ledger are those of other bodies), or nullopt. A
/// state without masses (written before they were saved) passes. A run started from s as its
/// initial state may change them (its ledger starts at the state).
std::optional<std::string> mass_mismatch(const World& w, const WorldState& s);

/// Puts w in the saved state, clock included, and a caller's external loads with it: the run goes
/// on from s.step_index. w must be built from the same scenario (state_mismatch) with the same dt.
void restore_state(World& w, const WorldState& s);

/// Starts a new run from a saved state (a settled assembly): the dynamic bodies' positions,
/// velocities and contacts with their history come from s; the clock restarts at t = 0, the
/// start positions become the initial positions, the driven bodies take the new table motion's
/// place at t = 0, and the energy ledger starts again from the state's stored energy.
/// Fixed and driven bodies keep the scenario's geometry. A caller's loads in s are not taken: the
/// new run's caller sets its own (as it sets them on a run that settled itself).
void start_from_state(World& w, const WorldState& s);

}  // namespace blockdem
