#include "contact/contact_table_3d.hpp"

#include <algorithm>
#include <compare>

namespace blockdem {

void carry_history(const std::vector<ContactPoint3d>& previous, ContactPoint3d* run, std::size_t count,
                   std::size_t hint) {
    if (count == 0) return;
    // Start at the first point of run[0]'s pair of bodies or beyond; the merge then passes the keys
    // below run[0] as the whole table's merge would have. Found by galloping from the hint (last
    // step's table is this step's but for the points born and gone, so the run is near its own
    // place) and then bisecting, one integer comparison a probe.
    const auto bodies = [](const ContactKey3d& k) { return (std::uint64_t{k.body_a} << 32) | k.body_b; };
    const std::uint64_t first_bodies = bodies(run[0].key);
    const auto below = [&](std::size_t i) { return bodies(previous[i].key) < first_bodies; };
    const std::size_t n = previous.size();
    std::size_t lo = 0, hi = n;  // below(i) for i < lo, not for i >= hi
    const std::size_t start = std::min(hint, n);
    if (start < n && below(start)) {
        lo = start + 1;
        for (std::size_t step = 1; lo + step - 1 < n; step *= 2) {
            if (!below(lo + step - 1)) { hi = lo + step - 1; break; }
            lo += step;
        }
    } else {
        hi = start;
        for (std::size_t step = 1; step <= hi; step *= 2) {
            if (below(hi - step)) { lo = hi - step + 1; break; }
            hi -= step;
        }
    }
    std::size_t j = static_cast<std::size_t>(
        std::partition_point(previous.begin() + static_cast<std::ptrdiff_t>(lo),
                             previous.begin() + static_cast<std::ptrdiff_t>(hi),
                             [&](const ContactPoint3d& p) { return bodies(p.key) < first_bodies; }) -
        previous.begin());
    // One three-way comparison a probe: the probe that stops the walk also says whether it matched.
    for (std::size_t i = 0; i < count; ++i) {
        ContactPoint3d& p = run[i];
        std::strong_ordering order = std::strong_ordering::less;
        while (j < n && (order = previous[j].key <=> p.key) < 0) ++j;
        if (j < n && order == 0) {
            p.normal_dashpot_n = previous[j].normal_dashpot_n;
            p.shear = previous[j].shear;
            const double before = previous[j].stiffness_share;
            if (p.stiffness_share != before)
                p.shear.spring_n = before > 0.0 ? (p.stiffness_share / before) * p.shear.spring_n : Vec3{};
        } else {
            p.normal_dashpot_n = 0.0;
            p.shear = {};
        }
    }
}

void carry_history(const std::vector<ContactPoint3d>& previous, std::vector<ContactPoint3d>& current) {
    carry_history(previous, current.data(), current.size(), 0);
}

}  // namespace blockdem
