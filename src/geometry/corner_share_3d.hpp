#pragma once
// How much of a contact's stiffness each corner of a face-clipped overlap polygon carries
// (docs/3d.md, "The ledger on a shaken wall").
//
// Why. A face contact is the incident face clipped by the reference face's side planes; each
// corner below the reference plane is a contact point. With a full kn at every corner, the
// stiffness jumps when the polygon gains or loses a corner: two bricks of equal width lying flush
// have an incident edge running along a reference side plane, turned by ~1e-7 rad, and the clip
// cuts it anywhere along its length. That cut is a corner, born or gone with the depth it has
// there, so kn d^2 / 2 appears or vanishes at once, tens of thousands of times on a shaken wall.
//
// The share. Corner i weighs w_i = turn_i / (pi / 2), turn_i the exterior (turning) angle of the
// polygon at that corner: the angle between the side that arrives there and the side that leaves.
// It is measured in the polygon's own plane (the clipped polygon lies in the incident face), so a
// box face's corner weighs 1 however the face is tilted to the reference. A convex polygon's
// exterior angles sum to 2 pi, so the weights of a polygon always sum to 4: a rectangle's corners
// weigh 1 each (box on box as before: "kn is per corner of a square patch"), a corner on a
// near-straight side (the flicker's cut) weighs ~0, and a corner cut in two by a side plane
// splits its weight between the two cuts continuously. Corners that coincide (a side between
// them shorter than 1e-9 of the longest, whose direction is round-off) share their group's
// turn equally. A polygon of fewer than 3 distinct corners follows the same rule: a segment's
// two ends turn by pi (weight 2 each), a point is the whole turn (4, shared by the corners there).
// The shares depend only on where the corners are, not on which features made them, so a
// polygon from any clip (the general one, a box face's rectangle clip) gets the same shares.
// Cost (docs/performance.md, "Branch np3d"): a corner the caller knows to be a right angle (a box
// face's own corner, kept by the clip) is given 1 without a turn; a turn near a quarter or near
// zero, as a brick wall's cuts are, takes the arctangent's series rather than atan2; the last
// corner not known to be a right angle is not measured but takes what the others leave of 4
// (branch clip1p: the same share to round-off, one turn fewer a polygon).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>  // std::integral_constant, the count a caller may fix

#include "geometry/vec3.hpp"

namespace blockdem {
namespace corner_share_detail {

// atan x for |x| <= 1e-3 by its odd series: the first term left out, x^7 / 7, is below 1.5e-22,
// far under a double's rounding of the turns it makes (a quarter, or x itself).
inline double small_arctangent(double x) {
    const double x2 = x * x;
    return x * (1.0 - x2 * (1.0 / 3.0 - 0.2 * x2));
}

// The turn [rad] from side a to side b, in [0, pi]: the angle between them, atan2(|a x b|, a . b),
// which for a plane convex polygon is its exterior angle there (no normal needed, so neither
// orientation matters). Near a quarter turn (a cut across a box face's edge) and near zero (a cut
// on a nearly straight side) the arctangent of a ratio below 1e-3 is its series: the same turn to
// round-off without atan2, which was a third of the shares' cost on a brick wall
// (docs/performance.md, "Branch np3d").
inline double turn_rad(Vec3 a, Vec3 b) {
    const double sine_part = length(cross(a, b));  // |a| |b| sin(turn), >= 0
    const double cosine_part = dot(a, b);          // |a| |b| cos(turn)
    constexpr double series_ratio = 1e-3;
    if (std::abs(cosine_part) <= series_ratio * sine_part)
        return 0.5 * std::numbers::pi - small_arctangent(cosine_part / sine_part);
    if (sine_part <= series_ratio * cosine_part) return small_arctangent(sine_part / cosine_part);
    return std::atan2(sine_part, cosine_part);
}

}  // namespace corner_share_detail

/// corner_shares_3d for a polygon none of whose sides is short (below 1e-9 of the longest), its
/// corners read where they are: corners.at(i) gives corner i (a Vec3), corners.known(i) whether
/// its turn is known to be a right angle. Returns false, shares unset, when a side is short (the
/// caller then takes corner_shares_3d, which groups). Why a template: the narrow phase's box clip
/// keeps its polygon in its own records, and copying them into an array of Vec3 and flags for
/// the shares cost a tenth of the shares (docs/performance.md, "Branch face4"). The same
/// arithmetic as corner_shares_3d, so the same bits. count is a std::size_t, or a
/// std::integral_constant where the caller knows it, so that the loops unroll.
template <class Corners, class Count>
bool corner_shares_without_groups(const Corners& corners, Count count, double* shares) {
    if (count == 0) return true;
    // With the count known when compiled, each side is formed once and kept (the turns read it
    // again; formed from the corners, it was formed anew there, the stores of the shares in
    // between being possible writes to the corners). The same arithmetic either way.
    constexpr std::size_t kept_sides = [] {
        if constexpr (std::is_integral_v<Count>) return std::size_t{1};
        else return Count::value;
    }();
    Vec3 sides_kept[kept_sides];
    if constexpr (!std::is_integral_v<Count>)
        for (std::size_t i = 0; i < count; ++i) sides_kept[i] = corners.at(i + 1 == count ? 0 : i + 1) - corners.at(i);
    const auto side = [&](std::size_t i) {
        if constexpr (std::is_integral_v<Count>) return corners.at(i + 1 == count ? 0 : i + 1) - corners.at(i);
        else return sides_kept[i];
    };
    // A side shorter than 1e-9 of the longest has a direction made of round-off: its ends count
    // as one corner. (Squared lengths: no root taken for the test.)
    double longest_m2 = 0.0;
    double shortest_m2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 s = side(i);
        const double s_m2 = dot(s, s);
        longest_m2 = std::max(longest_m2, s_m2);
        shortest_m2 = std::min(shortest_m2, s_m2);
    }
    if (!(shortest_m2 > 1e-18 * longest_m2)) return false;
    // Each corner is its own group, turning from the side that arrives to the side that leaves. A
    // convex polygon's turns sum to a whole turn, its shares to 4: the last corner not known to be
    // a right angle takes what the others leave (one turn fewer, the same share to round-off;
    // never below 0). A known corner needs no side; a measured one the two at it.
    constexpr double quarter_turn_rad = 0.5 * std::numbers::pi;
    std::size_t last_measured = count - 1;
    while (last_measured > 0 && corners.known(last_measured)) --last_measured;
    const bool all_known = corners.known(last_measured);
    double others = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (corners.known(i)) {
            shares[i] = 1.0;
            others += 1.0;
        } else if (i != last_measured) {
            shares[i] = corner_share_detail::turn_rad(side(i == 0 ? count - 1 : i - 1), side(i)) / quarter_turn_rad;
            others += shares[i];
        }
    }
    if (!all_known) shares[last_measured] = std::max(0.0, 4.0 - others);
    return true;
}

/// shares[i] = corner i's share of the contact stiffness (its turn over pi / 2), for the count
/// corners of a plane convex polygon in order round it (either way round). quarter_turns, when
/// given, marks (nonzero) the corners whose turn the caller knows to be a right angle: a box face's
/// own corner that the clip kept, both its sides lying along the face's edges. Such a corner
/// weighs exactly 1, not 1 to round-off, and costs no turn (when no side of the polygon is short;
/// otherwise every corner is measured, as the groups need).
void corner_shares_3d(const Vec3* corners_m, std::size_t count, double* shares,
                      const std::uint8_t* quarter_turns = nullptr);

}  // namespace blockdem
