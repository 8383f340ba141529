#pragma once
// The world owns every array of a simulation: bodies as flat arrays indexed by body id, the
// contact table, the broad phase and the energy ledger. step() in step.cpp advances it by one
// time step; writers only read it.
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

#include "broad_phase/grid_broad_phase.hpp"
#include "contact/contact_table.hpp"
#include "contact/sub_contacts.hpp"
#include "dynamics/stability_rows.hpp"
#include "world/energy_ledger.hpp"
#include "world/external_loads.hpp"
#include "world/model.hpp"
#include "world/model_domain.hpp"

namespace blockdem {

/// Body state and properties, one entry per body (structure of arrays).
struct Bodies {
    std::vector<std::string> name;
    std::vector<BodyKind> kind;
    std::vector<std::uint8_t> is_static;        ///< 1 for fixed and driven bodies, and bodies taken out (model_domain.hpp)
    std::vector<std::uint8_t> record;           ///< 1: written to history.csv
    std::vector<std::string> assembly;          ///< the [[assemblies]] entry that made it ("" for [[bodies]])
    std::vector<std::uint32_t> material;        ///< id in MaterialPairs
    std::vector<double> mass_kg;                ///< [kg]
    std::vector<double> inv_mass_1_kg;          ///< [1/kg], 0 for static bodies
    std::vector<double> inertia_kg_m2;          ///< [kg m^2] about the centroid
    std::vector<double> inv_inertia_1_kg_m2;    ///< [1/(kg m^2)], 0 for static bodies
    std::vector<double> bounding_radius_m;      ///< [m] largest centroid-to-corner distance
    std::vector<double> least_width_m;          ///< [m] least width of its thinnest part (overlaps are judged against it)
    std::vector<double> thickness_m;            ///< [m] out of plane (a per-length joint's area)
    std::vector<std::uint32_t> bond_group;      ///< bodies of one nonzero group are bonded where they touch at the start
    std::vector<std::uint32_t> vertex_begin;    ///< first corner of the outline in the vertex arrays
    std::vector<std::uint32_t> vertex_count;    ///< corners of the outline
    /// [m] corners relative to the centroid at rotation 0: every body's outline, in body order,
    /// then the corners of the parts of concave bodies (a convex body's one part is its outline)
    std::vector<Vec2> local_vertices_m;
    std::vector<Vec2> world_vertices_m;         ///< [m] corners now
    std::vector<Vec2> local_normals;            ///< outward unit edge normals at rotation 0
    std::vector<Vec2> world_normals;            ///< outward unit edge normals now
    /// [m] with rounding: per corner of a part, how far its rounded core's corner lies inside it
    /// (rounded_corner_offset of world_normals at corner_offsets_rounding_m), made with the
    /// normals each step so that the narrow phase reads them instead of making four per pair
    std::vector<Vec2> world_corner_offsets_m;
    double corner_offsets_rounding_m = 0.0;     ///< [m] the rounding they are for; 0: none valid

    // Parts: the convex pieces of a body (geometry/outline.hpp), what the broad and narrow phase
    // work on. A convex body is one part; part ids run in body order.
    std::vector<std::uint32_t> part_begin;      ///< per body: its first part id
    std::vector<std::uint32_t> part_count;      ///< per body: 1 for a convex body
    std::vector<std::uint32_t> part_body;       ///< per part: the body it belongs to
    std::vector<std::uint32_t> part_vertex_begin;///< per part: first corner in the vertex arrays
    std::vector<std::uint32_t> part_vertex_count;///< per part
    std::vector<double> part_radius_m;          ///< [m] per part: largest distance from its own centroid to a corner
    std::vector<Aabb> part_box_m;               ///< [m] per part: tight bounding box now
    /// Per corner (indexed as the vertex arrays): 1 for a corner of a concave body's part that is
    /// no arc of the rounded body (geometry/rounded_outline.hpp); 0 elsewhere.
    std::vector<std::uint8_t> seam_corner;

    std::vector<Vec2> position_m;               ///< [m] centroid at t
    std::vector<double> rotation_rad;           ///< [rad] at t, counter-clockwise from the start
    std::vector<Vec2> velocity_m_s;             ///< [m/s] at t - dt/2 before the step, t + dt/2 after
    std::vector<double> angular_velocity_rad_s; ///< [rad/s] likewise
    std::vector<Vec2> acceleration_m_s2;        ///< [m/s^2] at t
    std::vector<double> angular_acceleration_rad_s2; ///< [rad/s^2] at t
    std::vector<Vec2> velocity_at_t_m_s;        ///< [m/s] at t (mean of the two half steps): for output
    std::vector<double> angular_velocity_at_t_rad_s;  ///< [rad/s] at t, for output
    std::vector<Vec2> force_n;                  ///< [N] total force at t
    std::vector<double> torque_n_m;             ///< [N m] total torque at t

    std::vector<Vec2> initial_position_m;       ///< [m] centroid at t = 0
    std::vector<Vec2> position_at_rebuild_m;    ///< [m] at the last broad-phase rebuild
    std::vector<double> rotation_at_rebuild_rad;///< [rad] at the last broad-phase rebuild

    std::size_t size() const { return name.size(); }
    std::size_t part_total() const { return part_body.size(); }
    /// Corners of the outlines (they come first in the vertex arrays): what outputs and state files hold.
    std::size_t outline_corners() const { return name.empty() ? 0 : vertex_begin.back() + vertex_count.back(); }
};

/// [m] body i's tight bounding box now: the union of its parts' boxes.
Aabb body_box(const Bodies& b, std::size_t i);

/// One pair's contact forces this step: what each of its points adds to the two bodies.
struct PairForces {
    Vec2 on_b_n[2];              ///< [N] force on b from point k (a gets minus it)
    double torque_on_a_n_m[2];   ///< [N m] torque on a from point k
    double torque_on_b_n_m[2];   ///< [N m] torque on b from point k
    std::uint32_t count = 0;        ///< points this step (a copy, so the sum per body stays in this array)
};

/// Wall-clock seconds spent in each phase of the step, summed while enabled (benchmarks and
/// `blockdem bench`; off by default, when the step reads no clock).
struct StepTimings {
    bool enabled = false;
    double geometry_s = 0.0;      ///< [s] body corners and normals
    double broad_phase_s = 0.0;   ///< [s] staleness check and rebuilds
    double contacts_s = 0.0;      ///< [s] narrow phase and contact law, pair by pair
    double bodies_s = 0.0;        ///< [s] each body's force sum, velocity and energy; stability check
    double positions_s = 0.0;     ///< [s] positions to t + dt
};

/// What the run learns about its own trustworthiness as it goes (world/step.cpp): the stable
/// limit of the live contacts, and the deepest overlap.
struct StabilityWatch {
    double start_bound_s = 0.0;          ///< [s] Gershgorin bound of the start contacts
    /// [-] the highest mode's limit over the Gershgorin bound, for the contacts it was last
    /// estimated on (the start's, or live ones): the live limit is the live bound times it; 0: none yet
    double limit_ratio = 0.0;
    double ratio_bound_s = 0.0;          ///< [s] the Gershgorin bound of the contacts the ratio was estimated on
    std::int64_t estimates = 0;          ///< highest-mode estimates made on live contacts
    /// [s] least stable limit seen: the live contacts' Gershgorin bound times limit_ratio, or a
    /// body's own blocks' limit where lower (world/step.cpp, watch_live_time_step)
    double least_limit_s = 0.0;
    std::string least_limit_body;        ///< the body that set it
    double least_limit_time_s = 0.0;     ///< [s] when
    double first_exceeded_s = -1.0;      ///< [s] first time dt was above the live limit; -1: never
    std::string exceeded_body;           ///< the body whose contacts were too stiff then
    double max_overlap_ratio = 0.0;      ///< [-] deepest overlap / least width of the thinner body
    double max_overlap_time_s = 0.0;     ///< [s]
    std::uint32_t max_overlap_pair_a = 0;///< body ids of that pair
    std::uint32_t max_overlap_pair_b = 0;
    double max_overlap_m = 0.0;          ///< [m]
    double max_overlap_kn_N_m = 0.0;     ///< [N/m] the pair's normal stiffness then
};

/// What the settling stage did before t = 0 (world/settling.hpp), for the summary and check.
struct SettlingRecord {
    double time_s = 0.0;                 ///< [s] simulated settling
    std::int64_t steps = 0;
    bool friction_held = true;           ///< friction was held (every contact stuck) while settling
    double kinetic_ratio = 0.0;          ///< [-] the largest E_k / (m g L) of the last window
    double largest_move_m = 0.0;         ///< [m] the largest centroid displacement of any body
    std::string largest_move_body;       ///< the body that moved most
    double largest_turn_rad = 0.0;       ///< [rad] the largest |rotation| of any body
    std::string largest_turn_body;       ///< the body that turned most
};

struct World {
    SimulationSettings settings;
    MaterialPairs contact;
    TableMotion table_motion;
    Bodies bodies;

    double dt_s = 0.0;                    ///< [s] the time step in use
    double critical_dt_s = 0.0;           ///< [s] the stable limit it was checked against (highest mode at the start)
    double proven_stable_dt_s = 0.0;      ///< [s] the Gershgorin bound at the start: every dt below is stable
    double time_s = 0.0;                  ///< [s] time of the current state
    std::int64_t step_index = 0;
    double settling_time_s = 0.0;         ///< [s] simulated before t = 0 by the settling stage (0: none)
    std::optional<SettlingRecord> settling;  ///< what the settling stage did (none: no settling)
    /// [m/s^2] gravity at time_s in the model's frame (gravity_at(settings, time_s)), set once a
    /// step before the forces (the tilt may change with time)
    Vec2 gravity_now_m_s2{0.0, -9.81};
    /// false until the first step: the bodies' velocities are then those of the initial state at
    /// t, and the first step starts the leapfrog with a half step (central_difference.hpp).
    bool velocities_staggered = false;

    GridBroadPhase broad_phase;
    double broad_phase_margin_m = 0.0;    ///< [m] boxes are enlarged by this; rebuild after margin/2 motion
    std::vector<Aabb> boxes;              ///< enlarged part boxes at the last rebuild
    std::vector<std::uint8_t> part_is_static;  ///< scratch of the rebuild (worlds with concave bodies)
    std::vector<BodyPair> candidate_pairs;///< pairs of parts of different bodies
    std::vector<PairContact> contacts;    ///< sorted by (part_a, part_b), so also by a
    std::vector<PairContact> contacts_scratch;
    /// The interior points of each pair, aligned with contacts; empty unless [contact]
    /// sub_contacts > 2 (contact/sub_contacts.hpp).
    std::vector<SubContacts> sub_contacts;
    std::vector<SubContacts> sub_contacts_scratch;
    /// The contact law's result per pair, written in parallel, summed per body in table order.
    std::vector<PairForces> pair_forces;
    /// For each body, the pairs it belongs to in table order (entry = 2 pair + (body is b)):
    /// entries body_pair_start[i] to body_pair_start[i + 1]. Rebuilt with the candidate pairs.
    std::vector<std::uint32_t> body_pair_start;
    std::vector<std::uint32_t> body_pair_entries;
    std::vector<std::uint32_t> contacts_fill;   ///< scratch of the indexing
    /// Per table entry, in worlds with concave bodies: the active points of its body pair this
    /// step, over all the body pair's part pairs (the dashpots share the reduced mass among them:
    /// contact/contact_forces.hpp). Convex worlds leave it empty: a part pair is a body pair.
    std::vector<std::uint32_t> body_pair_points;
    std::vector<std::uint32_t> points_by_body;  ///< scratch of the counting, zero between uses
    std::vector<OpenedPoints> opened_scratch;   ///< per table entry: the narrow phase's opened points (concave worlds)
    std::vector<std::uint32_t> driven_bodies;   ///< ids of driven bodies (the table work sums over them)
    std::int64_t broad_phase_rebuilds = 0;

    EnergyLedger energy;
    StabilityWatch stability;
    StabilityRows stability_rows;         ///< scratch of the live stable-step check
    ModelDomain domain;                   ///< the model's extent and the bodies that left it
    StepTimings timings;
    ExternalLoads external_loads;         ///< loads a caller applies (the Python module); none by default

    std::uint32_t body_id(const std::string& name) const;  ///< throws std::out_of_range
};

/// Bytes held by the world's arrays (capacities, not sizes; names included), for benchmarks.
std::size_t memory_bytes(const World& w);

/// Builds a world from a model: mass properties, material ids, the time step and its check.
/// Throws ModelError naming the body when a body is invalid, bodies overlap at the start, or
/// the time step is above the stable limit (bad input); throws SimulationError when an
/// assembly does not settle (the run started and failed: exit status 3).
World build_world(const Model& model, const std::atomic<bool>* stop_requested = nullptr);

/// A model that cannot be simulated (invalid body, overlap at start, unstable dt).
class ModelError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace blockdem
