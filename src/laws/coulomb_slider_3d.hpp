#pragma once
// The shear half of the contact law (laws/linear_spring_dashpot.hpp) in 3-D: the shear spring
// force is a vector in the contact's tangent plane, built incrementally from the tangential slip,
// with the Coulomb cap on its length, so that friction is isotropic and the slip's direction is
// the force's. Everything else is the 2-D slider's, term by term (coulomb_slider): the spring
// first relaxes to a cap that fell, the dashpot acts only while the point sticks, and the work
// is taken by the trapezoid so that the energy ledger closes.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/vec3.hpp"

namespace blockdem {

/// Shear history of one 3-D contact point (zero for a new contact).
struct ShearHistory3d {
    Vec3 spring_n;   ///< [N] shear spring force on b, in the tangent plane
    Vec3 dashpot_n;  ///< [N] last step's shear dashpot force on b
};

/// This step's shear forces and dissipation.
struct ShearForce3d {
    Vec3 spring_n;                      ///< [N] shear spring force on b: the history to carry
    Vec3 total_n;                       ///< [N] spring plus dashpot, capped
    Vec3 dashpot_n;                     ///< [N] the dashpot's part of total_n
    bool sliding = false;
    double friction_work_j = 0.0;       ///< [J] dissipated by sliding over the last interval
    double shear_dashpot_work_j = 0.0;  ///< [J] dissipated by the shear dashpot over the last interval
};

/// Squares below this bound have a root within limit: sqrt(|v|^2), correctly rounded, cannot
/// exceed limit, so the cap needs no square root (limit >= 0: a cap mu F_n, and mu >= 0 is
/// checked where it is read). Why the margin: limit^2 rounds to
/// limit^2 (1 + e), |e| <= u (u = 2^-53), and the margin's product rounds once more, so a
/// square below limit^2 (1 - 1e-15) has its exact root below limit (1 - 3e-16), and a root
/// below a representable limit rounds to at most limit. Where limit^2 is not a normal number
/// (its relative error is then unbounded) or is NaN, the bound is -1: no square is below it and
/// the square root decides.
inline double surely_within_below(double limit) {
    const double limit_squared = limit * limit;
    return limit_squared >= std::numeric_limits<double>::min() ? limit_squared * (1.0 - 1e-15) : -1.0;
}

/// v scaled down to length at most limit (v itself when shorter). within_below =
/// surely_within_below(limit) lets the usual case, well inside the cap, skip the square root:
/// the same bits either way.
inline Vec3 capped_length(Vec3 v, double limit, double within_below) {
    const double length_squared = dot(v, v);
    if (length_squared < within_below) return v;
    const double l = std::sqrt(length_squared);
    return l > limit ? (l > 0.0 ? (limit / l) * v : Vec3{}) : v;
}

/// v laid into the plane normal to n (a unit vector) with its length kept: the history's
/// carry into a contact frame whose normal turned, which turns v with the frame to first order
/// in the turn. The length ratio |v| / |v - (v.n) n| is taken as one root,
/// sqrt(|v|^2 / (|v|^2 - (v.n)^2)) (|n| = 1), rather than as two lengths; and where (v.n)^2 is
/// below half an ulp of |v|^2 (a normal turned by less than about 1e-8 rad since the vector was
/// laid into its plane) the ratio's argument is 1 exactly, so its root, 1, is not taken: the
/// same bits as the formula either way.
inline Vec3 carried_into_plane(Vec3 v, Vec3 n) {
    const double along = dot(v, n);
    const Vec3 in_plane = v - along * n;
    const double length_squared = dot(v, v);
    const double in_plane_squared = length_squared - along * along;
    if (in_plane_squared == length_squared) return in_plane;
    return in_plane_squared > 0.0 ? std::sqrt(length_squared / in_plane_squared) * in_plane : Vec3{};
}

/// The history carried into a contact frame whose normal is new_normal (unit): both vectors laid
/// into its tangent plane with their lengths kept (carried_into_plane). A vector along the normal
/// (no part in the plane) is dropped.
inline ShearHistory3d carry_to_normal(ShearHistory3d h, Vec3 new_normal) {
    return {carried_into_plane(h.spring_n, new_normal), carried_into_plane(h.dashpot_n, new_normal)};
}

/// The history as coulomb_slider_3d takes it in the frame of new_normal (unit): the spring laid
/// into the new plane (carried_into_plane); last step's dashpot force only scaled to the length
/// the carry gives it. The slider takes that force only through its work with this step's slip
/// increment, the relative velocity less its normal part times dt: n . increment is round-off
/// (a few u times |relative velocity| dt), so the normal part left in the force, (d . n) n, changes
/// that work by a few u |d| |relative velocity| dt times the turn: carry_to_normal's work to
/// round-off, without the vector's projection (3-D law: -2.8 M instructions on the 1000-brick
/// wall over 20 steps).
inline ShearHistory3d carry_to_normal_for_slider(ShearHistory3d h, Vec3 new_normal) {
    const Vec3 d = h.dashpot_n;
    const double along = dot(d, new_normal);
    const double length_squared = dot(d, d);
    const double in_plane_squared = length_squared - along * along;
    const Vec3 dashpot_n = in_plane_squared == length_squared ? d
                           : in_plane_squared > 0.0        ? std::sqrt(length_squared / in_plane_squared) * d
                                                           : Vec3{};
    return {carried_into_plane(h.spring_n, new_normal), dashpot_n};
}

/// ks [N/m], cs [N s/m], limit_n = mu F_n [N], tangential_velocity_m_s: (v_b - v_a) at the point,
/// in the tangent plane, over the interval that ends now.
inline ShearForce3d coulomb_slider_3d(double ks_N_m, double cs_N_s_m, double limit_n, Vec3 tangential_velocity_m_s,
                                      const ShearHistory3d& previous, double dt_s) {
    // The cap's square roots only where a length can reach the cap (surely_within_below): a
    // sticking point takes none. The trial's length is taken once, for the test and for the cap.
    // Each branch builds its whole result at once, not a default one overwritten field by field.
    const double within_below = surely_within_below(limit_n);
    const Vec3 last = previous.spring_n;
    const Vec3 capped_last = capped_length(last, limit_n, within_below);
    const Vec3 increment_m = dt_s * tangential_velocity_m_s;
    const Vec3 trial = capped_last - ks_N_m * increment_m;
    const double trial_squared = dot(trial, trial);
    const bool trial_within = trial_squared < within_below;
    const double trial_length = trial_within ? 0.0 : std::sqrt(trial_squared);
    const bool trial_over = !trial_within && trial_length > limit_n;
    if (trial_over || !(capped_last == last)) {
        const Vec3 spring_n = trial_over ? (limit_n / trial_length) * trial : trial;
        const double work_on_bodies_j = 0.5 * dot(last + spring_n, increment_m);
        const double stored_change_j =
            ks_N_m > 0.0 ? 0.5 * (dot(spring_n, spring_n) - dot(last, last)) / ks_N_m : 0.0;
        // Sliding: no dashpot (its part is zero).
        return {spring_n, spring_n, Vec3{}, true, -work_on_bodies_j - stored_change_j,
                -0.5 * dot(previous.dashpot_n + Vec3{}, increment_m)};
    }
    const Vec3 total_n = capped_length(trial - cs_N_s_m * tangential_velocity_m_s, limit_n, within_below);
    const Vec3 dashpot_n = total_n - trial;
    return {trial, total_n, dashpot_n, false, 0.0, -0.5 * dot(previous.dashpot_n + dashpot_n, increment_m)};
}

}  // namespace blockdem
