#pragma once
// The 3-D contact table: this step's contact points, sorted by key, each with the history it
// carries to the next step. A point's key is (body a, body b, feature of a, feature of b)
// (geometry/polyhedron_contact_3d.hpp), so a point that the narrow phase finds again from the
// same pair of features keeps its shear spring; one found for the first time starts at zero, and
// one not found again is dropped (the 2-D table's rule, contact/contact_table.hpp).
#include <compare>
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"
#include "laws/contact_parameters.hpp"
#include "laws/coulomb_slider_3d.hpp"

namespace blockdem {

struct ContactKey3d {
    std::uint32_t body_a = 0;
    std::uint32_t body_b = 0;     ///< body_a < body_b
    std::uint32_t feature_a = 0;  ///< feature_3d of a
    std::uint32_t feature_b = 0;  ///< feature_3d of b
    friend constexpr auto operator<=>(const ContactKey3d&, const ContactKey3d&) = default;
};

struct ContactPoint3d {
    ContactKey3d key;
    Vec3 point_m;                   ///< [m]
    Vec3 normal;                    ///< unit, from a to b
    double overlap_m = 0.0;         ///< [m] > 0
    double stiffness_share = 1.0;   ///< [-] its share w of kn and ks (geometry/corner_share_3d.hpp)
    double dashpot_mass_kg = 0.0;   ///< [kg] the pair's reduced mass shared by the points' w
    // History carried to the next step.
    double normal_dashpot_n = 0.0;  ///< [N] last step's normal dashpot force on b
    ShearHistory3d shear;           ///< [N] shear spring and dashpot force on b, in the tangent plane
    bool sliding = false;           ///< this step's state, for output
    Vec3 force_n;                   ///< [N] this step's force on b (minus it on a), world frame
};

/// The law's parameters at a point: kn and ks times its stiffness share (the dashpots follow
/// through dashpot_coefficients, C = 2 h sqrt(M w k)).
inline ContactParameters point_parameters(const ContactParameters& p, double stiffness_share) {
    ContactParameters q = p;
    q.kn_N_m *= stiffness_share;
    q.ks_N_m *= stiffness_share;
    return q;
}

/// Gives each point of current (sorted by key, fresh from the narrow phase) the history of the
/// point of previous (sorted by key) with the same key, by one merge pass, and a point with no
/// such key a zero history (whatever it held: the step's table fill leaves it unwritten). The
/// shear spring is the point's tangential displacement times its stiffness w ks: when w changes
/// it is scaled by w_now / w_before, so that the displacement is what is carried.
void carry_history(const std::vector<ContactPoint3d>& previous, std::vector<ContactPoint3d>& current);

/// The same for a run of count points of current (sorted by key), all of one pair of bodies: last
/// step's run of that pair is found in previous at hint (where the run is expected in previous:
/// where last step's pair of the same rank began, or the run's index in current), or by galloping
/// from it, and then merged: runs of one table can be carried in parallel, with the whole
/// table's result, whatever the hints. hint_starts_a_run: the caller knows that hint is where a
/// run of last step's table began (where last step's pair of the same rank began), so where the
/// point there is of run's pair, it is that pair's first and the point before it is not read.
void carry_history(const std::vector<ContactPoint3d>& previous, ContactPoint3d* run, std::size_t count,
                   std::size_t hint, bool hint_starts_a_run = false);

}  // namespace blockdem
