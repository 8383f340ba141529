#pragma once
// The 3-D world: many rigid convex polyhedra as plain arrays, the table's three-component motion,
// the contact law's parameters, the contact table and the energy ledger (docs/3d.md). The 3-D
// counterpart of world/world.hpp; the step is world/step_3d.hpp.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "broad_phase/grid_broad_phase_3d.hpp"
#include "broad_phase/skin_pair_list.hpp"
#include "contact/contact_table_3d.hpp"
#include "dynamics/rigid_body_3d.hpp"
#include "geometry/box_frame_3d.hpp"
#include "geometry/polyhedron_contact_3d.hpp"
#include "geometry/polyhedron_edges_3d.hpp"
#include "laws/contact_parameters.hpp"
#include "motion/table_motion.hpp"
#include "world/energy_ledger.hpp"
#include "world/external_loads_3d.hpp"
#include "world/model_domain_3d.hpp"

namespace blockdem {

/// How a body moves: by the contact forces and gravity, not at all, or with the table.
enum class BodyKind3d : std::uint8_t { dynamic, fixed, driven };

/// The table's motion: two horizontal components and the vertical one.
struct TableMotion3d {
    ComponentMotion x = RestMotion{};
    ComponentMotion y = RestMotion{};
    ComponentMotion z = RestMotion{};
};

/// The table's displacement at t_s [m].
inline Vec3 table_displacement(const TableMotion3d& m, double t_s) {
    return {sample(m.x, t_s).displacement_m, sample(m.y, t_s).displacement_m, sample(m.z, t_s).displacement_m};
}

/// A pair of bodies in contact this step: its run of points in the contact table, and the sums
/// of their forces that the bodies take (world/step_3d.cpp, the law per pair).
struct ContactPairSums3d {
    std::uint32_t candidate = 0;    ///< index in WorldScratch3d::pairs
    std::uint32_t first_point = 0;  ///< index in World3d::contacts
    std::uint32_t points = 0;
    double dashpot_mass_per_share_kg = 0.0;  ///< [kg] M / S: a point's dashpot mass is its share w times this
    Vec3 force_n;                   ///< [N] the sum of the points' forces on b (minus it on a)
    Vec3 torque_about_a_n_m;        ///< [N m] their moment about a's centroid
};

/// A candidate pair of a chunk that the narrow phase found touching, and its number of points.
struct TouchingCandidate3d {
    std::uint32_t candidate = 0;  ///< index in WorldScratch3d::pairs
    std::uint32_t points = 0;
};

/// One fixed chunk of the candidate pairs, as the narrow phase left it (world/step_3d.cpp): which
/// of its candidates touch, and where its pairs' points wait for the table's fill: one flat array,
/// in candidate order, lent from WorldScratch3d::point_buffers. Flat, so that the table's fill
/// streams through it (a vector per candidate was a heap block a pair, scattered), and per chunk,
/// so that the table's layout does not depend on the thread count.
/// One a cache line (64 bytes): threads find neighbouring chunks at once, and two chunks' lists
/// sharing a line passed it between the cores at every pair found touching (the list's end written,
/// its capacity read), which took two threads' narrow-phase loop from 4 % to 7 % of the step.
struct alignas(64) CandidateChunk3d {
    std::vector<TouchingCandidate3d> touching;  ///< kept to the step's end: the gather's index reads it
    std::uint32_t buffer = 0;                   ///< its entry in point_buffers, from its narrow phase to its fill
    bool found = false;                         ///< its narrow phase has ended (this step)
    bool filled = false;                        ///< its runs are filled and its law done (this step)
};

/// The law's energy terms over some pairs [J] (world/step_3d.cpp): a chunk's, added up in chunk
/// order, so that the ledger has the same bits at any thread count.
struct LawTotals3d {
    double elastic_j = 0.0;
    double normal_dashpot_j = 0.0;
    double shear_dashpot_j = 0.0;
    double friction_j = 0.0;
    double table_work_j = 0.0;
    LawTotals3d& operator+=(const LawTotals3d& o) {
        elastic_j += o.elastic_j;
        normal_dashpot_j += o.normal_dashpot_j;
        shear_dashpot_j += o.shear_dashpot_j;
        friction_j += o.friction_j;
        table_work_j += o.table_work_j;
        return *this;
    }
};

/// What the narrow phase's views of the bodies (WorldScratch3d::posed) point into: the world's
/// arrays of bodies, edges and frames, the pose arrays, and the number of bodies. A view's
/// pointers follow from these and the pose arrays' offsets alone, so while they are the same the
/// views are (world/step_3d.cpp, size_pose_arrays); a world copied or moved, or a body added (the
/// count, and a vector that grew), changes one of them, and the views are written again. What it
/// cannot see is a body's shape changed in place (a vector copy-assigned over one of the same size
/// keeps its buffer): the step's pose arrays, sized by the shapes, assume World3d's rule that
/// bodies are only added (add_body), never reshaped.
struct PosedSources3d {
    const void* bodies = nullptr;
    const void* edges = nullptr;
    const void* box_frames = nullptr;
    const Vec3* vertices_m = nullptr;
    const Vec3* normals = nullptr;
    const Vec3* directions = nullptr;
    const Vec3* centroids_m = nullptr;
    std::size_t count = 0;
    bool operator==(const PosedSources3d&) const = default;
};

/// A candidate pair's mark for the bodies' gather (world/step_3d.cpp): in contact this step when
/// step is the step's stamp, and then its entry in WorldScratch3d::contact_pairs.
struct CandidateContact3d {
    std::uint32_t step = 0;  ///< WorldScratch3d::contact_stamp of the step that marked it
    std::uint32_t pair = 0;  ///< index in WorldScratch3d::contact_pairs
};

/// Arrays rebuilt every step, kept so that a step allocates nothing in steady state.
struct WorldScratch3d {
    std::vector<std::uint32_t> vertex_start;  ///< per body, its first entry in world_vertices_m (and one past the last)
    std::vector<std::uint32_t> face_start;    ///< likewise in world_normals
    std::vector<std::uint32_t> direction_start;///< likewise in world_directions
    std::vector<Vec3> world_vertices_m;       ///< [m]
    std::vector<Vec3> world_normals;
    std::vector<Vec3> world_directions;
    std::vector<Vec3> centroids_m;            ///< [m] per body, its centroid at t, where the narrow phase reads it
    std::vector<Vec3> body_directions;        ///< per body's direction_start run, its edge directions in the body frame
                                              ///< (World3d::edges' copied once: the pose reads them with no pointer chase)
    std::vector<Vec3> angular_velocity_world_rad_s;  ///< [rad/s] per body, over the last step (the contact law's)
    std::vector<Matrix3d> rotations;          ///< per body, its orientation's matrix at t (the pose's; the kick's)
    std::vector<Aabb3d> boxes;
    std::vector<std::uint8_t> is_static;
    std::vector<BodyPair> pairs;
    std::vector<CandidateChunk3d> candidate_chunks;           ///< per fixed chunk of pairs (kept: no allocation)
    std::vector<std::vector<ContactGeometry3d>> point_buffers;///< the narrow phase's points of a chunk until its fill, lent
                                                              ///< to the chunks in flight (a few), so that they stay in cache
    std::vector<std::uint32_t> free_point_buffers;            ///< point_buffers not lent, the last given back on top
    std::vector<std::vector<std::uint32_t>> thread_free_point_buffers;  ///< per thread, those it was lent and got back
                                                              ///< in the step (lent to it again first)
    std::vector<std::uint32_t> point_buffer_lender;           ///< per point buffer, the thread it was last lent to
    std::vector<ContactPoint3d> previous;
    std::vector<ContactPairSums3d> contact_pairs;             ///< this step's pairs in contact, in table order
    std::vector<std::uint32_t> run_starts;                    ///< per pair in contact, its first point in World3d::contacts
    std::vector<std::uint32_t> previous_run_starts;           ///< last step's: where a pair's run in previous is looked for first
    std::vector<std::uint32_t> chunk_pairs;                   ///< per fixed chunk of the candidates: pairs in contact before it
    std::vector<std::uint32_t> chunk_points;                  ///< likewise, points before it
    std::vector<std::uint32_t> previous_chunk_points;         ///< last step's chunk_points (where the fill's lines are guessed)
    std::vector<LawTotals3d> chunk_law_totals;                ///< per fixed chunk, its law's energy terms this step
    std::vector<std::uint32_t> late_chunks;                   ///< the chunks filled after the whole narrow phase this step
    std::vector<BodyPair> indexed_pairs;                      ///< the candidates body_candidates was built from (pairs then)
    std::vector<std::uint32_t> body_candidate_start;          ///< per body, its first entry in body_candidates (and one past the last)
    std::vector<std::uint32_t> body_candidates;               ///< per body, its candidates (indices in pairs), in candidate order
    std::vector<CandidateContact3d> candidate_contact;        ///< per candidate: the step it last touched, its pair then
    std::vector<std::uint8_t> chunk_changed;                  ///< per fixed chunk of pairs: 1 if it differs from indexed_pairs
    std::uint32_t contact_stamp = 0;                          ///< this step's stamp in candidate_contact (0: none yet)
    std::size_t candidates_per_chunk = 512;                   ///< the candidates' chunks once there are more than 64
                                                              ///< (world/step_3d.cpp; a test sets fewer, to reach many
                                                              ///< chunks on a small wall)
    bool fill_as_placed = true;                               ///< fill a chunk's runs and run its law once its place is known
                                                              ///< (false: after the whole narrow phase, the plain passes)
    std::size_t chunks_filled_late = 0;                       ///< last step's chunks filled after the whole narrow phase
    std::vector<ContactScratch3d> clipping;                   ///< one per thread
    std::vector<PosedPolyhedron> posed;                       ///< per body, as the narrow phase reads it (pointers into the pose arrays)
    PosedSources3d posed_sources;                             ///< what posed was written from (size_pose_arrays)
    SkinPairList3d broad_phase;                               ///< the grid, searched again only when a body left its skin
};

/// The stable step of the live contacts, watched during a run (world/run_checks_3d.hpp) as the
/// 2-D StabilityWatch: a body landing on a lighter one, or a stack gaining points, may need a
/// smaller dt than the start did.
struct StabilityWatch3d {
    double start_bound_s = 0.0;          ///< [s] the proven bound of the start contacts (infinite: none)
    /// [-] the highest mode's limit over the proven bound, for the contacts it was last estimated
    /// on (the start's, or live ones): the live limit is the live bound times it; 0: none yet
    double limit_ratio = 0.0;
    double ratio_bound_s = 0.0;          ///< [s] the proven bound of the contacts the ratio was estimated on
    std::int64_t estimates = 0;          ///< highest-mode estimates made on live contacts
    double least_limit_s = 0.0;          ///< [s] least live limit seen; 0: not yet evaluated
    std::string least_limit_body;        ///< the body that set it
    double least_limit_time_s = 0.0;     ///< [s] when
    double first_exceeded_s = -1.0;      ///< [s] first time dt was above the live limit; -1: never
    std::string exceeded_body;           ///< the body whose contacts were too stiff then
    double max_overlap_ratio = 0.0;      ///< [-] deepest overlap / least width of the thinner body of its pair
    double max_overlap_m = 0.0;          ///< [m] that overlap
    double max_overlap_time_s = 0.0;     ///< [s] when
    std::uint32_t max_overlap_body_a = 0;///< the pair's bodies
    std::uint32_t max_overlap_body_b = 0;
};

struct World3d {
    std::vector<RigidBody3d> bodies;        ///< added by add_body, never reshaped in place (the step's pose arrays are sized by their shapes)
    std::vector<BodyKind3d> kinds;
    std::vector<PolyhedronEdges> edges;     ///< per body, numbered once
    std::vector<BoxFrame3d> box_frames;     ///< per body: a box's frame for the box-box test, or is_box = false
    std::vector<Vec3> rest_positions_m;     ///< [m] a driven body's centroid with the table at rest
    std::vector<std::string> assembly;      ///< per body, the [[assemblies]] entry that made it ("" for [[bodies]])
    ContactParameters contact;
    TableMotion3d table;
    double gravity_m_s2 = 9.81;             ///< [m/s^2] along -z
    double dt_s = 1e-4;                     ///< [s]
    double time_s = 0.0;                    ///< [s]
    std::int64_t steps = 0;
    double duration_s = 0.0;                ///< [s] the run's end (the run loop reads it)
    double output_interval_s = 1e-3;        ///< [s] between rows of history.csv and energy.csv
    EnergyLedger ledger;
    StabilityWatch3d stability;
    ModelDomain3d domain;                   ///< the model's extent and the bodies that left it
    std::vector<ContactPoint3d> contacts;   ///< this step's points, sorted by key
    ExternalLoads3d external_loads;         ///< loads a caller applies (the Python module); none by default
    WorldScratch3d scratch;
};

/// Adds a body (made by make_rigid_body_3d) and returns its index.
std::uint32_t add_body(World3d& w, RigidBody3d body, BodyKind3d kind, std::string assembly = {});

/// Total linear momentum [kg m/s] and angular momentum about the origin [kg m^2/s] of the dynamic
/// bodies, from the half-step velocities and angular momenta of the last kick and the positions
/// after the last drift: the form the scheme conserves exactly when the forces between bodies are
/// equal and opposite at a common point (the drift moves a body along its half-step velocity, so
/// r x m v does not change in it).
struct Momentum3d {
    Vec3 linear_kg_m_s;
    Vec3 angular_kg_m2_s;
};
Momentum3d momentum(const World3d& w);

/// Bytes the world holds (bodies, shapes, edges, contacts and scratch), for the memory per body.
std::size_t memory_bytes(const World3d& w);

/// The mass a pair's dashpots use [kg] (docs/physics.md, "Which mass the damping uses"): the
/// reduced mass of two dynamic bodies, else the dynamic one's.
inline double pair_reduced_mass_kg(const World3d& w, std::uint32_t a, std::uint32_t b) {
    const bool da = w.kinds[a] == BodyKind3d::dynamic;
    const bool db = w.kinds[b] == BodyKind3d::dynamic;
    const double ma = w.bodies[a].mass_kg;
    const double mb = w.bodies[b].mass_kg;
    if (da && db) return ma * mb / (ma + mb);
    return da ? ma : mb;
}

/// The mass each point's dashpots take [kg], for a table sorted by key (a step's, so a pair's
/// points are one run): the step's rule (world/step_3d.cpp, fill_chunk), the pair's M in proportion
/// to the points' stiffness shares w, M w / S, or M / n where no point has stiffness (S = 0); with
/// the step's sums, so the same bits as the masses its law takes. The step keeps only M / S a pair
/// (ContactPairSums3d): the critical time step and `blockdem check` read the points' masses here.
std::vector<double> point_dashpot_masses_kg(const World3d& w, const std::vector<ContactPoint3d>& table);

/// Sets the contact table from outside the step (a state file read), with what the step keeps
/// about the table it left: nothing. The step looks for a pair's run of last step's points where
/// last step's pair of the same rank began, and trusts that place to start a run
/// (contact/contact_table_3d.hpp); offsets into another table would drop history.
inline void replace_contacts(World3d& w, std::vector<ContactPoint3d> contacts) {
    w.contacts = std::move(contacts);
    w.scratch.run_starts.clear();
    w.scratch.previous_run_starts.clear();
}

}  // namespace blockdem
