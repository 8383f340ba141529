// The narrow phase's axis cache (geometry/polygon_contact.hpp, AxisCache) must never change a
// result: a pair stepped through contact, sliding, rocking and separation gives bit-identical
// manifolds with and without the cache, while most touching steps do take the cached path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/polygon_contact.hpp"

namespace blockdem {
namespace {

// A body as the world holds it: corners and normals in its own frame, turned each step.
struct MovingPolygon {
    std::vector<Vec2> local_v, local_n, v, n;
    double radius = 0.0;
    explicit MovingPolygon(std::vector<Vec2> vertices) : local_v(std::move(vertices)) {
        for (std::size_t i = 0; i < local_v.size(); ++i) {
            local_n.push_back(edge_normal(local_v[i], local_v[(i + 1) % local_v.size()]));
            radius = std::max(radius, length(local_v[i]));
        }
        v = local_v;
        n = local_n;
    }
    void place(Vec2 position, double angle) {
        const Rotation r = Rotation::from_angle(angle);
        for (std::size_t i = 0; i < local_v.size(); ++i) {
            v[i] = position + r.apply(local_v[i]);
            n[i] = r.apply(local_n[i]);
        }
    }
    // The lowest corner when turned by angle, relative to the centre [m].
    Vec2 lowest_corner(double angle) const {
        const Rotation r = Rotation::from_angle(angle);
        Vec2 lowest{0.0, INFINITY};
        for (const Vec2& p : local_v)
            if (r.apply(p).y < lowest.y) lowest = r.apply(p);
        return lowest;
    }
    // Height of the upper boundary at x (as placed), or -infinity if x is outside [m].
    double top_at(double x) const {
        double top = -INFINITY;
        for (std::size_t i = 0; i < v.size(); ++i) {
            const Vec2 p = v[i], q = v[(i + 1) % v.size()];
            if ((p.x - x) * (q.x - x) > 0.0 || p.x == q.x) continue;
            top = std::max(top, p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x));
        }
        return top;
    }
    PolygonView view() const { return {v.data(), n.data(), static_cast<std::uint32_t>(v.size())}; }
};

std::vector<Vec2> random_convex(std::mt19937& rng, int corners, double size) {
    // Corners at sorted random angles on an ellipse: convex and counter-clockwise.
    std::uniform_real_distribution<double> u(0.0, 2.0 * M_PI);
    std::vector<double> angles(static_cast<std::size_t>(corners));
    for (double& a : angles) a = u(rng);
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> v;
    for (double a : angles) v.push_back({size * std::cos(a), 0.6 * size * std::sin(a)});
    const Vec2 c = polygon_properties(v).centroid_m;
    for (Vec2& p : v) p = p - c;
    return v;
}

bool same(const ContactManifold& x, const ContactManifold& y) {
    if (x.count != y.count) return false;
    if (x.count == 0) return true;
    if (x.normal.x != y.normal.x || x.normal.y != y.normal.y || x.reference != y.reference ||
        x.stiffness_scale != y.stiffness_scale)
        return false;
    for (std::uint32_t k = 0; k < x.count; ++k)
        if (x.points[k].feature != y.points[k].feature || x.points[k].overlap_m != y.points[k].overlap_m ||
            x.points[k].point_m.x != y.points[k].point_m.x || x.points[k].point_m.y != y.points[k].point_m.y)
            return false;
    return true;
}

struct Counts {
    int steps = 0, touching = 0, cached = 0, incident_kept = 0;
};

// B moves over A along x, presses in and lifts off, and rocks; A sways a little.
// dt [s] scales how far the bodies move per step; tumble [rad] how far B turns.
Counts run_pair(MovingPolygon a, MovingPolygon b, unsigned seed, double dt = 2e-3, double tumble = 0.25) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> phase(0.0, 6.28);
    const double p1 = phase(rng), p2 = phase(rng), p3 = phase(rng);
    AxisCache cache;
    std::uint32_t ref_cached = no_reference, ref_plain = no_reference;
    Vec2 pa_old{}, pb_old{};
    double ta_old = 0.0, tb_old = 0.0;
    Counts c;
    for (int s = 0; s < 4000; ++s, ++c.steps) {
        const double t = s * dt;
        const double ta = 0.005 * std::sin(0.9 * t + p1);
        const double tb = tumble * std::sin(0.6 * t + p2) + 0.05 * std::sin(7.0 * t);
        const double press = 1.5e-3 * std::sin(2.1 * t + p3) + 0.5e-3;  // > 0: corners below A's top
        const Vec2 pa{0.0, 0.0};
        a.place(pa, ta);
        // B's lowest corner "press" below A's upper boundary, sweeping along A.
        const Vec2 corner = b.lowest_corner(tb);
        const double x = (tumble > 0.5 ? 1.1 : 0.6) * a.radius * std::sin(0.8 * t);
        const double top = a.top_at(x);
        const Vec2 pb{x - corner.x, (std::isfinite(top) ? top : 0.0) - corner.y - press};
        b.place(pb, tb);
        if (s > 0) {
            // What the step adds (world/step.cpp), from the actual motion of this step.
            const double turn = std::abs(ta - ta_old) + std::abs(tb - tb_old);
            const double lever = norm_bound(pa - pb) + a.radius + b.radius;
            cache.drift_m += norm_bound(pa - pa_old) + norm_bound(pb - pb_old) + turn * lever + 1e-9 * (a.radius + b.radius);
            cache.turn_rad += turn;
        }
        pa_old = pa, pb_old = pb, ta_old = ta, tb_old = tb;
        // Whether the cached path may keep the incident edge without looking (its condition,
        // read before the call): the shortcut's results are tested where it applies.
        const bool incident_skippable = cache.others_max_separation_m < INFINITY && ref_cached != no_reference &&
                                        2.0 * cache.turn_rad + 1e-12 < cache.incident_margin;
        ContactManifold with_cache, without;
        collide_polygons(a.view(), b.view(), ref_cached, with_cache, &cache);
        collide_polygons(a.view(), b.view(), ref_plain, without);
        EXPECT_TRUE(same(with_cache, without)) << "step " << s << " seed " << seed;
        if (!same(with_cache, without)) return c;
        ref_cached = with_cache.count > 0 ? with_cache.reference : no_reference;
        ref_plain = without.count > 0 ? without.reference : no_reference;
        if (with_cache.count > 0) {
            ++c.touching;
            if (cache.drift_m > 0.0) ++c.cached;  // a full test sets the drift to zero
            if (cache.drift_m > 0.0 && incident_skippable) ++c.incident_kept;
        } else {
            cache.drift_m = cache.turn_rad = 0.0;
        }
    }
    return c;
}

TEST(AxisCache, SameContactsAsTheFullTestBrickOnBrick) {
    const Counts c = run_pair(MovingPolygon(rectangle_vertices(0.4, 0.2, {}, 0.0)),
                              MovingPolygon(rectangle_vertices(0.2, 0.1, {}, 0.0)), 1);
    std::printf("brick on brick: %d steps, %d touching, %d cached, incident kept %d\n", c.steps, c.touching, c.cached,
                c.incident_kept);
    EXPECT_GT(c.touching, c.steps / 3);
    EXPECT_GT(c.cached, c.touching / 2);
    EXPECT_GT(c.incident_kept, c.touching / 2);
}

TEST(AxisCache, SameContactsAsTheFullTestRandomPolygons) {
    std::mt19937 rng(7);
    int touching = 0, cached = 0, kept = 0;
    for (unsigned seed = 0; seed < 20; ++seed) {
        const int corners_a = 3 + static_cast<int>(seed % 5);
        const int corners_b = 3 + static_cast<int>((seed / 2) % 6);
        const Counts c = run_pair(MovingPolygon(random_convex(rng, corners_a, 0.3)),
                                  MovingPolygon(random_convex(rng, corners_b, 0.15)), seed);
        touching += c.touching;
        cached += c.cached;
        kept += c.incident_kept;
    }
    std::printf("random polygons: %d steps, %d touching, %d cached, incident kept %d\n", 20 * 4000, touching, cached,
                kept);
    EXPECT_GT(kept, cached / 2);
    EXPECT_GT(touching, 20 * 4000 / 4);
    EXPECT_GT(cached, touching / 3);
}

// Blocks laid exactly touching (separation exactly 0, as generated walls are) count as apart
// with or without the cache, also right after a contact and while a stale separating edge is
// kept: the cache must not turn a round-off touch into a contact point.
TEST(AxisCache, ExactTouchesAreApartWithOrWithoutTheCache) {
    // Sizes and positions are binary fractions, so that "touching" is exact in floating point.
    MovingPolygon a(rectangle_vertices(0.5, 0.25, {}, 0.0));
    MovingPolygon b(rectangle_vertices(0.25, 0.125, {}, 0.0));
    // Depths of B's bottom face into A's top face [m]: contact, exact touch, gaps, contact...
    const double d = std::ldexp(1.0, -13), tiny = std::ldexp(1.0, -40);
    const double press[] = {d, 0.0, 0.0, d, 2 * d, 0.0, -d, 0.0, d, 0.0, tiny, 0.0, -tiny, 0.0, 4 * d, 0.0};
    AxisCache cache;
    std::uint32_t ref_cached = no_reference, ref_plain = no_reference;
    int contacts = 0;
    for (int round = 0; round < 4; ++round)
        for (std::size_t s = 0; s < std::size(press); ++s) {
            const double x = static_cast<double>(s % 5) / 64.0 - static_cast<double>(round) / 32.0;
            a.place({0.0, 0.0}, 0.0);
            b.place({x, 0.1875 - press[s]}, 0.0);
            cache.drift_m += 5e-4;  // more than any step's motion here
            ContactManifold with_cache, without;
            collide_polygons(a.view(), b.view(), ref_cached, with_cache, &cache);
            collide_polygons(a.view(), b.view(), ref_plain, without);
            ASSERT_TRUE(same(with_cache, without)) << "round " << round << " step " << s;
            if (press[s] <= 0.0) EXPECT_EQ(without.count, 0u) << "round " << round << " step " << s;
            contacts += without.count > 0 ? 1 : 0;
            ref_cached = with_cache.count > 0 ? with_cache.reference : no_reference;
            ref_plain = without.count > 0 ? without.reference : no_reference;
        }
    EXPECT_GE(contacts, 4 * 6);
}

// Two blocks of a tilted stack touching in exact arithmetic: after round-off one face may
// read as exactly touching and the other as 1e-16 m inside. The full test then finds the
// touching face and calls the pair apart; the cache must too.
TEST(AxisCache, RoundOffTouchesOfTiltedStacksAsTheFullTest) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-0.6, 0.6), shift(-0.15, 0.15);
    MovingPolygon a(rectangle_vertices(0.4, 0.2, {}, 0.0));
    MovingPolygon b(rectangle_vertices(0.2, 0.1, {}, 0.0));
    int apart = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double tilt = angle(rng);
        const double along = shift(rng);
        const Rotation r = Rotation::from_angle(tilt);
        AxisCache cache;
        std::uint32_t ref_cached = no_reference, ref_plain = no_reference;
        for (const double press : {1e-4, 5e-5, 0.0, 0.0, 1e-4, 0.0}) {
            a.place({0.0, 0.0}, tilt);
            b.place(r.apply(Vec2{along, 0.15 - press}), tilt);
            cache.drift_m += 1e-4;
            ContactManifold with_cache, without;
            collide_polygons(a.view(), b.view(), ref_cached, with_cache, &cache);
            collide_polygons(a.view(), b.view(), ref_plain, without);
            ASSERT_TRUE(same(with_cache, without)) << "trial " << trial << " press " << press;
            apart += without.count == 0 ? 1 : 0;
            ref_cached = with_cache.count > 0 ? with_cache.reference : no_reference;
            ref_plain = without.count > 0 ? without.reference : no_reference;
        }
    }
    EXPECT_GT(apart, 1000);  // many round-off touches read as apart by the full test
}

// Large steps, B tumbling and sliding off A's ends: the reference edge changes often, and a
// motion bound that were too small would keep a stale one.
TEST(AxisCache, SameContactsAsTheFullTestTumblingAndSlidingOff) {
    std::mt19937 rng(11);
    int touching = 0, cached = 0;
    for (unsigned seed = 0; seed < 20; ++seed) {
        const Counts c = run_pair(MovingPolygon(random_convex(rng, 4 + static_cast<int>(seed % 3), 0.3)),
                                  MovingPolygon(random_convex(rng, 3 + static_cast<int>(seed % 5), 0.15)), seed, 2e-2, 1.5);
        touching += c.touching;
        cached += c.cached;
    }
    std::printf("tumbling: %d steps, %d touching, %d cached\n", 20 * 4000, touching, cached);
    EXPECT_GT(touching, 20 * 4000 / 4);
    EXPECT_GT(cached, touching / 4);
}

}  // namespace
}  // namespace blockdem
