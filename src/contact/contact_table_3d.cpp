#include "contact/contact_table_3d.hpp"

#include <algorithm>
#include <compare>
#include <cstddef>
#include <cstring>

namespace blockdem {
namespace {

// a == b as two 64-bit comparisons (the defaulted == compares the four fields one by one).
bool same_key(const ContactKey3d& a, const ContactKey3d& b) {
    static_assert(sizeof(ContactKey3d) == 2 * sizeof(std::uint64_t));
    std::uint64_t x[2], y[2];
    std::memcpy(x, &a, sizeof x);
    std::memcpy(y, &b, sizeof y);
    return ((x[0] ^ y[0]) | (x[1] ^ y[1])) == 0;
}

}  // namespace

void carry_history(const std::vector<ContactPoint3d>& previous, ContactPoint3d* run, std::size_t count,
                   std::size_t hint, bool hint_starts_a_run) {
    if (count == 0) return;
    // Start at the first point of run[0]'s pair of bodies or beyond; the merge then passes the keys
    // below run[0] as the whole table's merge would have. Found by galloping from the hint (last
    // step's table is this step's but for the points born and gone, so the run is near its own
    // place) and then bisecting, one integer comparison a probe.
    const auto bodies = [](const ContactKey3d& k) { return (std::uint64_t{k.body_a} << 32) | k.body_b; };
    const std::uint64_t first_bodies = bodies(run[0].key);
    const auto below = [&](std::size_t i) { return bodies(previous[i].key) < first_bodies; };
    const std::size_t n = previous.size();
    const std::size_t start = std::min(hint, n);
    const auto run_start = [&]() -> std::size_t {
        // The hint is the run's first point: no search.
        if (start < n && bodies(previous[start].key) == first_bodies &&
            (hint_starts_a_run || start == 0 || below(start - 1)))
            return start;
        std::size_t lo = 0, hi = n;  // below(i) for i < lo, not for i >= hi
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
        return static_cast<std::size_t>(
            std::partition_point(previous.begin() + static_cast<std::ptrdiff_t>(lo),
                                 previous.begin() + static_cast<std::ptrdiff_t>(hi),
                                 [&](const ContactPoint3d& p) { return bodies(p.key) < first_bodies; }) -
            previous.begin());
    };
    // Walked by pointers: an index into previous cost an address computation (a multiply by the
    // point's size) and a bounds test at each point.
    const ContactPoint3d* q = previous.data() + run_start();
    const ContactPoint3d* const last_end = previous.data() + n;
    // The usual point kept its key, and last step's point at q is its own: one 16-byte
    // comparison says so. Otherwise the walk passes last step's smaller keys (points gone), one
    // three-way comparison a probe, the probe that stops it saying whether it matched.
    for (ContactPoint3d* p = run; p != run + count; ++p) {
        bool found = q != last_end && same_key(q->key, p->key);
        if (!found) {
            std::strong_ordering order = std::strong_ordering::less;
            while (q != last_end && (order = q->key <=> p->key) < 0) ++q;
            found = q != last_end && order == 0;
        }
        if (found) {
            take_history(*q, *p);
            ++q;
        } else {
            start_history(*p);
        }
    }
}

void carry_history(const std::vector<ContactPoint3d>& previous, std::vector<ContactPoint3d>& current) {
    for (std::size_t first = 0; first < current.size();) {
        std::size_t end = first + 1;
        while (end < current.size() && current[end].key.body_a == current[first].key.body_a &&
               current[end].key.body_b == current[first].key.body_b)
            ++end;
        carry_history(previous, &current[first], end - first, first);
        first = end;
    }
}

}  // namespace blockdem
