#include "geometry/corner_share_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace blockdem {

void corner_shares_3d(const Vec3* corners_m, std::size_t count, double* shares, const std::uint8_t* quarter_turns) {
    // Corners in an array, the known right angles flagged in another (or none).
    struct CornerArray {
        const Vec3* corners_m;
        const std::uint8_t* quarter_turns;
        Vec3 at(std::size_t i) const { return corners_m[i]; }
        bool known(std::size_t i) const { return quarter_turns != nullptr && quarter_turns[i] != 0; }
    };
    if (corner_shares_without_groups(CornerArray{corners_m, quarter_turns}, count, shares)) return;
    // A short side: corners joined by short sides share their group's turn.
    const auto side = [&](std::size_t i) { return corners_m[i + 1 == count ? 0 : i + 1] - corners_m[i]; };
    double longest_m2 = 0.0;
    for (std::size_t i = 0; i < count; ++i) longest_m2 = std::max(longest_m2, dot(side(i), side(i)));
    const double short_m2 = 1e-18 * longest_m2;
    constexpr double quarter_turn_rad = 0.5 * std::numbers::pi;
    using corner_share_detail::turn_rad;
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
