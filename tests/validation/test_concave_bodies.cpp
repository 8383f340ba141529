// Concave bodies (issue 13, section 4): a polygon body may be concave; it is cut into convex
// parts (geometry/outline.hpp) that move as one rigid body.
//   - mass properties of an L and a T section against the closed forms of their rectangles
//     (parallel-axis theorem), to 1e-12 relative: round-off of a few sums of products;
//   - an L block resting on a table carries its weight at its two bottom corners as statics
//     says (lever rule about the centroid);
//   - a Pi-shaped block touching a table through two parts at once (its two legs): one body
//     pair, several part pairs, each leg carrying half the weight; the interface sums them;
//   - the L block on a tilting table overturns when its centroid passes over the pivot corner,
//     tan(tilt) = x_c / y_c, within the tolerances of the rectangular blocks' tilting-table test
//     (test_tilting_table.cpp gives the reasons: the tilt keeps rising while the event grows to
//     the size at which it is detected, 0 to 0.4 deg after; the elastic lean, below 0.05 deg);
//   - a wall of keyed bricks gives the same state at one and two threads;
//   - a Pi-shaped block dropped flat on a table lands on its two legs (two part pairs, four
//     points) and rebounds with the requested e, within the 2% of the convex flat-drop test
//     (test_restitution_impact.cpp gives the reason): the body pair's reduced mass is shared
//     among all four points; sharing it per part pair would damp the drop by sqrt(2) too much.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "geometry/outline.hpp"
#include "geometry/polygon.hpp"
#include "io/summary_writer.hpp"
#include "laws/restitution.hpp"
#include "scenes/assemblies.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"
#include "world/interface_monitor.hpp"
#include "world/parallel.hpp"
#include "world/response_monitor.hpp"

namespace blockdem {
namespace {

using validation::g;
using validation::deg;

struct Rect {
    double x0, y0, x1, y1;  ///< [m]
    double area() const { return (x1 - x0) * (y1 - y0); }
    Vec2 centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
    double own_polar() const { return area() * ((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0)) / 12.0; }
};

// Area, centroid and polar moment about the centroid of disjoint rectangles: the closed form
// (sum of areas, area-weighted centres, b h (b^2 + h^2) / 12 plus the parallel-axis terms).
PolygonProperties union_of(const std::vector<Rect>& rects) {
    PolygonProperties p;
    Vec2 moment;
    for (const Rect& r : rects) {
        p.area_m2 += r.area();
        moment += r.area() * r.centre();
    }
    p.centroid_m = (1.0 / p.area_m2) * moment;
    for (const Rect& r : rects) {
        const Vec2 d = r.centre() - p.centroid_m;
        p.polar_moment_m4 += r.own_polar() + r.area() * dot(d, d);
    }
    return p;
}

BodyDef polygon_body(const std::string& name, std::vector<Vec2> vertices, double density_kg_m3) {
    BodyDef b;
    b.name = name;
    b.vertices_m = std::move(vertices);
    b.density_kg_m3 = density_kg_m3;
    return b;
}

// An L: a foot 0.4 x 0.15 m, a stem 0.1 m wide up to 0.8 m on its left; origin at (x, y).
std::vector<Vec2> l_section(double x, double y) {
    return {{x, y}, {x + 0.4, y}, {x + 0.4, y + 0.15}, {x + 0.1, y + 0.15}, {x + 0.1, y + 0.8}, {x, y + 0.8}};
}
std::vector<Rect> l_rectangles(double x, double y) { return {{x, y, x + 0.4, y + 0.15}, {x, y + 0.15, x + 0.1, y + 0.8}}; }

void expect_relative(double got, double want, double tolerance, const char* what) {
    EXPECT_LE(std::abs(got - want), tolerance * std::abs(want)) << what << ": " << got << " vs " << want;
}

void expect_mass_properties(const std::vector<Vec2>& outline, const std::vector<Rect>& rects, double size_m) {
    const double density = 2300.0, thickness = 0.25;
    BodyDef def = polygon_body("section", outline, density);
    def.thickness_m = thickness;
    Model m = testing::model_with({def}, testing::contact(1e8, 0.6, 0.1, 0.1), 1e-5, 0.0);
    const World w = build_world(m);
    const PolygonProperties want = union_of(rects);
    const double mass = density * thickness * want.area_m2;
    std::printf("area %.15g m^2 (closed form %.15g), centroid (%.15g, %.15g) m ((%.15g, %.15g)), J %.15g kg m^2 (%.15g), "
                "%u convex parts\n",
                w.bodies.mass_kg[0] / (density * thickness), want.area_m2, w.bodies.position_m[0].x, w.bodies.position_m[0].y,
                want.centroid_m.x, want.centroid_m.y, w.bodies.inertia_kg_m2[0], mass * want.polar_moment_m4 / want.area_m2,
                w.bodies.part_count[0]);
    expect_relative(w.bodies.mass_kg[0], mass, 1e-12, "mass");
    // (The centroid relative to the section's size: its coordinates may be near zero.)
    EXPECT_LE(length(w.bodies.position_m[0] - want.centroid_m), 1e-12 * size_m);
    expect_relative(w.bodies.inertia_kg_m2[0], mass * want.polar_moment_m4 / want.area_m2, 1e-12, "inertia");
    // The parts tile the outline: convex, and their areas sum to the section's.
    EXPECT_GT(w.bodies.part_count[0], 1u);
    double parts_area = 0.0;
    for (const std::vector<Vec2>& part : outline_parts(outline)) {
        EXPECT_FALSE(convexity_problem(part));
        parts_area += polygon_properties(part).area_m2;
    }
    expect_relative(parts_area, want.area_m2, 1e-12, "area of the parts");
}

TEST(ConcaveBodies, MassPropertiesOfAnLSection) {
    expect_mass_properties(l_section(0.0, 0.0), l_rectangles(0.0, 0.0), 0.8);
    // Far from the origin (round-off of the shoelace sums stays relative to the section).
    expect_mass_properties(l_section(1234.5, -678.25), l_rectangles(1234.5, -678.25), 0.8);
}

TEST(ConcaveBodies, MassPropertiesOfATSection) {
    // A web 0.1 x 0.5 m under a flange 0.6 x 0.1 m.
    const std::vector<Vec2> t{{-0.05, 0.0}, {0.05, 0.0}, {0.05, 0.5}, {0.3, 0.5},
                              {0.3, 0.6},   {-0.3, 0.6}, {-0.3, 0.5}, {-0.05, 0.5}};
    expect_mass_properties(t, {{-0.05, 0.0, 0.05, 0.5}, {-0.3, 0.5, 0.3, 0.6}}, 0.6);
}

// A dynamic body on a fixed table, settled (friction held), at t = 0 after one step_begin.
World settled_on_table(const std::vector<Vec2>& outline) {
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 2.0, 0.2, {0.2, -0.1});
    Model m = testing::model_with({table, polygon_body("block", outline, 2500.0)}, testing::contact(1e8, 0.6, 0.3, 0.3),
                                  0.0, g, 1.0);
    m.settings.dt_s.reset();
    m.settling = SettlingSettings{};
    m.settling->kinetic_ratio = 1e-13;  // (see settled_tolerance)
    World w = build_world(m);
    step_begin(w);
    return w;
}

// Sum of the table's normal forces on the block at points with x in [lo, hi).
double support_between(const World& w, double lo_m, double hi_m) {
    double sum = 0.0;
    for (const PairContact& pair : w.contacts)
        for (std::uint32_t k = 0; k < pair.count; ++k)
            if (pair.points[k].point_m.x >= lo_m && pair.points[k].point_m.x < hi_m) sum += pair.points[k].normal_force_n;
    return sum;
}

// Tolerance of the settled supports: settling stops once the kinetic energy stays below
// 1e-13 m g L; a vibration of that energy on the contacts' springs (stiffness about kn) moves
// their forces by at most sqrt(2 1e-13 L kn / (m g)) of the weight, 7e-5 here (at the default
// 1e-8 it would be 2%, measured 0.1%). 1e-3 of the weight is asserted.
constexpr double settled_tolerance = 1e-3;

TEST(ConcaveBodies, LBlockRestsOnItsCornersAsStaticsSays) {
    const World w = settled_on_table(l_section(0.0, 0.0));
    const double weight = w.bodies.mass_kg[1] * g;
    const double xc = union_of(l_rectangles(0.0, 0.0)).centroid_m.x;
    // Two supports at x = 0 and x = 0.4 m: lever rule about the centroid.
    const double left = support_between(w, -0.01, 0.01), right = support_between(w, 0.39, 0.41);
    std::printf("L block: supports %.6g N at x = 0 (statics %.6g N), %.6g N at x = 0.4 m (statics %.6g N)\n", left,
                weight * (0.4 - xc) / 0.4, right, weight * xc / 0.4);
    EXPECT_NEAR(left, weight * (0.4 - xc) / 0.4, settled_tolerance * weight);
    EXPECT_NEAR(right, weight * xc / 0.4, settled_tolerance * weight);
    EXPECT_NEAR(support_between(w, -1.0, 1.0), weight, settled_tolerance * weight);
}

TEST(ConcaveBodies, PiBlockTouchesTheTableThroughTwoParts) {
    // Two legs 0.1 m wide under a 0.4 m top, the gap between them 0.2 m wide and 0.2 m high.
    const std::vector<Vec2> pi{{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.2}, {0.3, 0.2}, {0.3, 0.0}, {0.4, 0.0}, {0.4, 0.3}, {0.0, 0.3}};
    const World w = settled_on_table(pi);
    const double weight = w.bodies.mass_kg[1] * g;
    std::vector<std::uint32_t> touching_parts;
    for (const PairContact& pair : w.contacts) {
        EXPECT_NE(pair.a, pair.b);
        if (pair.count > 0) touching_parts.push_back(pair.part_b);
    }
    ASSERT_GE(touching_parts.size(), 2u) << "one body pair, at least two part pairs in contact";
    EXPECT_NE(touching_parts.front(), touching_parts.back());
    const double left = support_between(w, -0.01, 0.11), right = support_between(w, 0.29, 0.41);
    std::printf("Pi block: %zu part pairs touch; legs carry %.6g N and %.6g N of %.6g N\n", touching_parts.size(), left,
                right, weight);
    EXPECT_NEAR(left, 0.5 * weight, settled_tolerance * weight);
    EXPECT_NEAR(right, 0.5 * weight, settled_tolerance * weight);
    // One interface for the body pair, summing its part pairs.
    InterfaceMonitor monitor(InterfaceSelection{true, {}});
    monitor.observe(w);
    ASSERT_EQ(monitor.interfaces().size(), 1u);
    EXPECT_NEAR(monitor.interfaces()[0].normal_force_n, weight, settled_tolerance * weight);
    EXPECT_GE(monitor.interfaces()[0].points, 4u);
}

// The Pi block of the test above, 1 mm over a fixed table and moving down at 1 m/s, without
// gravity (the rebound is the contact's alone, as in test_restitution_impact.cpp); kn = 1e6 N/m
// and dt = 1e-6 s resolve the impact in about 10^4 steps. Returns the rebound ratio of the
// centroid's vertical velocity once every point has opened, and the most points and part pairs
// of the one body pair that touched at once.
struct PiDrop {
    double rebound = 0.0;
    int most_points = 0;
    int most_part_pairs = 0;
};

PiDrop pi_drop(double h_n) {
    const std::vector<Vec2> pi{{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.2}, {0.3, 0.2}, {0.3, 0.0}, {0.4, 0.0}, {0.4, 0.3}, {0.0, 0.3}};
    std::vector<Vec2> raised;
    for (const Vec2 v : pi) raised.push_back(v + Vec2{0.0, 0.001});
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 2.0, 0.2, {0.2, -0.1});
    BodyDef block = polygon_body("block", raised, 2500.0);
    block.velocity_m_s = {0.0, -1.0};
    Model m = testing::model_with({table, block}, testing::contact(1e6, 0.0, h_n, 0.0), 1e-6, 0.0);
    World w = build_world(m);
    const std::uint32_t id = w.body_id("block");
    PiDrop drop;
    bool touched = false;
    testing::step_until(w, 0.2, [&](const World& world) {
        const int points = testing::contact_points_of(world, id);
        int part_pairs = 0;
        for (const PairContact& pair : world.contacts) part_pairs += pair.count > 0 ? 1 : 0;
        drop.most_points = std::max(drop.most_points, points);
        drop.most_part_pairs = std::max(drop.most_part_pairs, part_pairs);
        if (points > 0) touched = true;
        return touched && points == 0;
    });
    EXPECT_TRUE(touched);
    drop.rebound = w.bodies.velocity_m_s[id].y / 1.0;
    return drop;
}

TEST(ConcaveBodies, PiBlockDroppedFlatReboundsWithTheRequestedRestitution) {
    for (double e : {0.2, 0.6, 0.95}) {
        const PiDrop drop = pi_drop(damping_ratio_rebound(e));
        std::printf("Pi block flat drop: requested e = %.3f, measured %.4f (error %.2f%%); %d points on %d part pairs\n", e,
                    drop.rebound, 100.0 * (drop.rebound - e) / e, drop.most_points, drop.most_part_pairs);
        EXPECT_EQ(drop.most_part_pairs, 2) << "the two legs";
        EXPECT_EQ(drop.most_points, 4);
        EXPECT_NEAR(drop.rebound, e, 0.02 * e) << "requested rebound e = " << e;
    }
}

TEST(ConcaveBodies, LBlockOverturnsOnATiltingTableWhenItsCentroidPassesThePivot) {
    constexpr double ramp_deg_s = 0.5;
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 2.0, 0.2, {0.0, -0.1});
    Model m = testing::model_with({table, polygon_body("block", l_section(0.0, 0.0), 2500.0)},
                                  testing::contact(1e8, 0.6, 0.3, 1.0), 0.0, g, 6.0);
    m.settings.dt_s.reset();
    m.settings.tilt_rad = 21.0 * deg;
    m.settings.tilt_rate_rad_s = ramp_deg_s * deg;
    m.settling = SettlingSettings{};
    World w = build_world(m);
    ResponseMonitor monitor(w);
    while (true) {
        step_begin(w);
        monitor.observe(w);
        if (w.time_s >= m.settings.duration_s) break;
        step_end(w);
    }
    const nlohmann::json summary = make_summary(w, monitor, RunInfo{"tilting", "completed", ""});
    const nlohmann::json& at = summary["bodies"][1]["table_tilt_deg_at"];
    const Vec2 c = union_of(l_rectangles(0.0, 0.0)).centroid_m;
    const double expected = std::atan(c.x / c.y) / deg;  // the centroid over the pivot corner (0, 0)
    ASSERT_TRUE(at["rocking_onset"].is_number()) << "the L block never tipped";
    ASSERT_TRUE(at["overturning"].is_number()) << "the L block never overturned";
    const double rocking = at["rocking_onset"].get<double>(), overturning = at["overturning"].get<double>();
    std::printf("L block: tipped at a table tilt of %.4f deg, overturned at %.4f deg; statics atan(x_c / y_c) = %.4f deg\n",
                rocking, overturning, expected);
    EXPECT_GE(rocking, expected);
    EXPECT_LT(rocking, expected + 0.4);
    EXPECT_NEAR(overturning, expected, 0.05);
    EXPECT_TRUE(at["slip_onset"].is_null() || at["slip_onset"].get<double>() > rocking);
}

// FNV-1a over the bytes of the bodies' state and the contacts' shear history.
std::uint64_t keyed_wall_hash(int threads, std::size_t& pairs) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    Model m = scenes::keyed_wall_scene(300, 1.0);
    m.table_motion.horizontal = SineMotion{0.8 * 9.81, 0.5, 0.0, 0.0, 0.0};  // past sliding: contacts slip
    World w = build_world(m);
    w.broad_phase_margin_m = 1e-5;  // many rebuilds on the way
    for (int i = 0; i < 150; ++i) step(w);
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&h](const auto& value) {
        unsigned char bytes[sizeof(value)];
        std::memcpy(bytes, &value, sizeof(value));
        for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    };
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        add(w.bodies.position_m[i]);
        add(w.bodies.rotation_rad[i]);
        add(w.bodies.velocity_m_s[i]);
        add(w.bodies.angular_velocity_rad_s[i]);
    }
    for (const PairContact& pair : w.contacts)
        for (std::uint32_t k = 0; k < pair.count; ++k) add(pair.points[k].shear_spring_n);
    pairs = w.contacts.size();
    return h;
}

TEST(ConcaveBodies, KeyedWallSameStateAtOneAndTwoThreads) {
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#endif
    std::size_t pairs_1 = 0, pairs_2 = 0;
    const std::uint64_t one = keyed_wall_hash(1, pairs_1);
    const std::uint64_t two = keyed_wall_hash(2, pairs_2);
    EXPECT_GT(pairs_1, static_cast<std::size_t>(parallel_threshold));  // the pair loops really run on threads
    EXPECT_EQ(pairs_1, pairs_2);
    EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace blockdem
