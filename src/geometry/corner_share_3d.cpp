#include "geometry/corner_share_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace blockdem {
namespace {

// atan x for |x| <= 1e-3 by its odd series: the first term left out, x^7 / 7, is below 1.5e-22,
// far under a double's rounding of the turns it makes (a quarter, or x itself).
double small_arctangent(double x) {
    const double x2 = x * x;
    return x * (1.0 - x2 * (1.0 / 3.0 - 0.2 * x2));
}

// The turn [rad] from side a to side b, in [0, pi]: the angle between them, atan2(|a x b|, a . b),
// which for a plane convex polygon is its exterior angle there (no normal needed, so neither
// orientation matters). Near a quarter turn (a cut across a box face's edge) and near zero (a cut
// on a nearly straight side) the arctangent of a ratio below 1e-3 is its series: the same turn to
// round-off without atan2, which was a third of the shares' cost on a brick wall
// (docs/performance.md, "Branch np3d").
double turn_rad(Vec3 a, Vec3 b) {
    const double sine_part = length(cross(a, b));  // |a| |b| sin(turn), >= 0
    const double cosine_part = dot(a, b);          // |a| |b| cos(turn)
    constexpr double series_ratio = 1e-3;
    if (std::abs(cosine_part) <= series_ratio * sine_part)
        return 0.5 * std::numbers::pi - small_arctangent(cosine_part / sine_part);
    if (sine_part <= series_ratio * cosine_part) return small_arctangent(sine_part / cosine_part);
    return std::atan2(sine_part, cosine_part);
}

}  // namespace

void corner_shares_3d(const Vec3* corners_m, std::size_t count, double* shares, const std::uint8_t* quarter_turns) {
    if (count == 0) return;
    const auto side = [&](std::size_t i) { return corners_m[i + 1 == count ? 0 : i + 1] - corners_m[i]; };
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
    const double short_m2 = 1e-18 * longest_m2;
    constexpr double quarter_turn_rad = 0.5 * std::numbers::pi;
    if (shortest_m2 > short_m2) {
        // No short side (the usual case): each corner is its own group, turning from the side that
        // arrives to the side that leaves, each side taken once. A convex polygon's turns sum to a
        // whole turn, its shares to 4: the last corner not known to be a right angle takes what
        // the others leave (one turn fewer, the same share to round-off; never below 0).
        const auto known = [&](std::size_t i) { return quarter_turns != nullptr && quarter_turns[i] != 0; };
        std::size_t last_measured = count - 1;
        while (last_measured > 0 && known(last_measured)) --last_measured;
        const bool all_known = known(last_measured);
        // A known corner needs no side; a measured one the two at it (the same differences of the
        // same corners as a walk round the polygon would carry, so the same bits).
        double others = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            if (known(i)) {
                shares[i] = 1.0;
                others += 1.0;
            } else if (i != last_measured) {
                shares[i] = turn_rad(side(i == 0 ? count - 1 : i - 1), side(i)) / quarter_turn_rad;
                others += shares[i];
            }
        }
        if (!all_known) shares[last_measured] = std::max(0.0, 4.0 - others);
        return;
    }
    const auto is_long = [&](std::size_t i) { return dot(side(i), side(i)) > short_m2; };
    std::size_t first_long = count;
    for (std::size_t i = 0; i < count && first_long == count; ++i)
        if (is_long(i)) first_long = i;
    if (first_long == count) {  // all corners at one place: the whole turn, shared
        for (std::size_t i = 0; i < count; ++i) shares[i] = 4.0 / static_cast<double>(count);
        return;
    }
    // Groups of corners joined by short sides, from the corner after the first long side round to
    // it: each group turns from the long side before it to the long side after it.
    std::size_t arriving = first_long;
    std::size_t corner = first_long + 1 == count ? 0 : first_long + 1;
    std::size_t done = 0;
    while (done < count) {
        std::size_t members = 1;
        std::size_t last = corner;
        while (members < count && !is_long(last)) {
            last = last + 1 == count ? 0 : last + 1;
            ++members;
        }
        const double share = turn_rad(side(arriving), side(last)) / quarter_turn_rad / static_cast<double>(members);
        for (std::size_t k = 0, i = corner; k < members; ++k, i = i + 1 == count ? 0 : i + 1) shares[i] = share;
        done += members;
        arriving = last;
        corner = last + 1 == count ? 0 : last + 1;
    }
}

}  // namespace blockdem
