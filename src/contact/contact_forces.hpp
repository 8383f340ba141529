#pragma once
// Applies the contact law to every closed contact point and adds the forces and torques to the
// two bodies. The law runs on all pairs in parallel, each writing its own slot (PairForces);
// then each body adds its pairs' slots in table order (sorted by body ids), so every body's sum
// has the same terms in the same order as a serial loop over the table: the results depend
// neither on how the pairs were found nor on the number of threads (world/parallel.hpp).
//
// Which mass the dashpots use: a pair's reduced mass m_a m_b / (m_a + m_b) (the dynamic body's
// own mass against a fixed or driven one) shared equally by the pair's active points. A block
// lying flat on the table has two points, each damped with M = m/2, so the two dashpots
// together give the whole block the requested damping ratio and a flat impact rebounds with the
// requested e; sizing each point with the whole mass would over-damp it by sqrt(2). A block on
// one corner has M = m at that point, but the corner moves with the smaller effective mass
// m_eff = 1 / (1/m + r_perp^2 / I), so its local damping ratio is h sqrt(m / m_eff) and a
// one-corner impact rebounds less than e (docs/physics.md, tests/validation/test_restitution).
// A concave body touches another through several part pairs at once (a Pi-shaped block on both
// legs): the share is then over all the points of the body pair, counted before the law
// (count_body_pair_points), or the body would get about sqrt(part pairs) times the damping ratio.
#include <cstdint>

#include "world/world.hpp"

namespace blockdem {

/// What the contacts add to the energy ledger: dissipated during this step, stored now [J].
struct ContactEnergy {
    double normal_dashpot_j = 0.0;  ///< [J] dissipated by the normal dashpots this step
    double shear_dashpot_j = 0.0;   ///< [J] dissipated by the shear dashpots this step
    double friction_j = 0.0;        ///< [J] dissipated by sliding this step
    double bond_breakage_j = 0.0;   ///< [J] released by bonds that broke this step
    double elastic_j = 0.0;         ///< [J] stored in the springs after this step's update
    /// The deepest overlap this step, as a fraction of the least width of the thinner body of
    /// its pair, and that pair (penetration check, world/step.cpp).
    double deepest_overlap_ratio = 0.0;
    std::uint32_t deepest_pair = 0;
    ContactEnergy& operator+=(const ContactEnergy& o) {
        normal_dashpot_j += o.normal_dashpot_j;
        shear_dashpot_j += o.shear_dashpot_j;
        friction_j += o.friction_j;
        bond_breakage_j += o.bond_breakage_j;
        elastic_j += o.elastic_j;
        // (Strictly greater: of equal depths the first pair in table order is kept, whatever
        // the thread count.)
        if (o.deepest_overlap_ratio > deepest_overlap_ratio) {
            deepest_overlap_ratio = o.deepest_overlap_ratio;
            deepest_pair = o.deepest_pair;
        }
        return *this;
    }
};

/// Sizes the force slots and the per-body lists if the table changed (call before the pass).
void prepare_pair_forces(World& w);

/// The law at every point of pair p: updates the points' forces and history and writes the
/// pair's force slot. Touches nothing but pair p's entry and slot, so pairs may run in
/// parallel. mass_sharing_points: the active points of p's body pair, which share its reduced
/// mass (p's own count while every body is convex; else count_body_pair_points). Returns the
/// pair's energy terms, with the last share of the dashpots' work of the points that opened this
/// step (the narrow phase's OpenedPoints; see the .cpp).
ContactEnergy apply_pair_law(World& w, std::size_t p, std::uint32_t mass_sharing_points,
                             const OpenedPoints& opened = OpenedPoints());

/// True when every material pair has per-length stiffness (a world of joints only: the step
/// then calls apply_joint_pair_law).
bool every_pair_per_length(const MaterialPairs& contact);

/// apply_pair_law for a world whose material pairs all have per-length stiffness: the same
/// results, without the per-point law's branch (the joint law in one body of code with the
/// pair's bookkeeping, which saved a bonded wall 1 % of its step: docs/performance.md).
ContactEnergy apply_joint_pair_law(World& w, std::size_t p, std::uint32_t mass_sharing_points,
                                   const OpenedPoints& opened = OpenedPoints());

/// The narrow phase (contact/narrow_phase.hpp) and then the law at every pair of a world whose
/// bodies are all convex (each pair's own points share its reduced mass), pair by pair in one body
/// of code: update_pair_contact then apply_pair_law, or in a world of joints only
/// (every_pair_per_length) update_joint_pair_contact then apply_joint_pair_law, with the same
/// results. Returns the pairs' energy terms summed in the fixed order of world/parallel.hpp.
ContactEnergy update_convex_contacts_and_forces(World& w);

/// Sets World::body_pair_points: for every table entry, the active points of its body pair this
/// step, summed over the body pair's part pairs (after the narrow phase, before the law). One
/// serial pass over the table (integer sums: the same at any thread count).
void count_body_pair_points(World& w);

/// Sets body i's force and torque: gravity plus its pairs' slots, in table order. Touches only
/// body i.
void sum_body_force(World& w, std::size_t i);

/// Lists each body's pairs in table order (World::body_pair_start/entries) and sizes the force
/// slots; called whenever the table's pairs change (a broad-phase rebuild).
void index_pairs_by_body(World& w);

/// The stiffness and joint area of each point of a pair with per-length stiffness (its points
/// share one tributary length: laws/mohr_coulomb_joint.hpp), softened as the pair is.
/// rounding_m: [contact] rounding [m], the least tributary length of a one-point contact. points:
/// how many the contact has with its sub-contacts (contact/sub_contacts.hpp): then this is an
/// end's, and an interior point has twice it.
JointPoint joint_point_of(const Bodies& b, const PairContact& pair, const ContactParameters& p, double rounding_m,
                          std::uint32_t points = 2);

/// Elastic energy stored in all contact springs [J].
double contact_elastic_energy(const World& w);

}  // namespace blockdem
