// Sliding of a block on a sinusoidally shaken table (the paper's Fig. 5 case) against Newmark's
// rigid-plastic solution (src/analysis/rigid_plastic_sliding), an independent integration with
// no springs.
//
// Tolerances, and why: the DEM block rides on springs of finite stiffness, so it lags the
// rigid-plastic block by its elastic shear deformation u_e = mu m g / (2 ks) = 74 um at the
// paper's ks = 2e4 N/m, and each stick-slip transition is smeared over the shear spring's
// period (about 25 ms). The residual slip after n cycles is therefore matched to 2% plus u_e.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/rigid_plastic_sliding.hpp"
#include "scenes/basic_scenes.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;

struct SlidingRun {
    std::vector<double> t, a_block, relative_x;
    std::vector<int> sliding_points;  // contact points sliding at each step
};

SlidingRun run(Model model) {
    World w = build_world(model);
    const std::uint32_t block = w.body_id("block");
    const std::uint32_t table = w.body_id("table");
    SlidingRun out;
    while (w.time_s <= model.settings.duration_s) {
        step_begin(w);
        int sliding = 0;
        for (const auto& pair : w.contacts)
            for (std::uint32_t k = 0; k < pair.count; ++k) sliding += pair.points[k].sliding ? 1 : 0;
        out.t.push_back(w.time_s);
        out.a_block.push_back(w.bodies.acceleration_m_s2[block].x);
        out.relative_x.push_back((w.bodies.position_m[block].x - w.bodies.initial_position_m[block].x) -
                                 (w.bodies.position_m[table].x - w.bodies.initial_position_m[table].x));
        out.sliding_points.push_back(sliding);
        step_end(w);
    }
    return out;
}

double value_at(const std::vector<double>& t, const std::vector<double>& v, double when) {
    const auto i = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), when - 1e-12) - t.begin());
    return v[std::min(i, v.size() - 1)];
}

TEST(Sliding, BelowFrictionCapacityOnlyElasticShear) {
    Model m = scenes::paper_sliding(1.0, 5.0);
    const double amplitude = 0.8 * 0.3 * g;  // 80% of mu g
    m.table_motion.horizontal = SineMotion{amplitude, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    const SlidingRun r = run(m);
    const double elastic = 1.0 * amplitude / (2.0 * 2.0e4);  // m a / (2 ks) [m]
    double peak = 0.0;
    for (double x : r.relative_x) peak = std::max(peak, std::abs(x));
    // At t = 0 the block is placed at zero overlap, so its first steps carry no normal force and
    // any shear slips; after settling (0.2 s) no corner may slide.
    const auto settled = static_cast<std::size_t>(0.2 / 1e-4);
    EXPECT_EQ(*std::max_element(r.sliding_points.begin() + settled, r.sliding_points.end()), 0);
    EXPECT_LT(peak, 2.0 * elastic) << "peak relative displacement " << peak << " m, elastic " << elastic << " m";
    std::printf("below capacity: peak relative displacement %.3g m (elastic shear m a / 2 ks = %.3g m)\n", peak, elastic);
}

TEST(Sliding, AccelerationClippedAtMuG) {
    const SlidingRun r = run(scenes::paper_sliding(1.0, 5.0));
    // Samples well inside sliding phases: both corners sliding for the previous 20 ms.
    const double mu_g = 0.3 * g;
    const std::size_t settle = 200;  // steps of 1e-4 s
    std::size_t count = 0;
    double worst = 0.0;
    std::size_t run_length = 0;
    // The table starts at 3.5 m/s^2 > mu g while the block is still settling onto its normal
    // springs (about 0.15 s of vertical vibration), so the first 0.2 s are left out.
    for (std::size_t i = static_cast<std::size_t>(0.2 / 1e-4); i < r.t.size(); ++i) {
        run_length = r.sliding_points[i] == 2 ? run_length + 1 : 0;
        if (run_length < settle) continue;
        ++count;
        worst = std::max(worst, std::abs(std::abs(r.a_block[i]) - mu_g) / mu_g);
    }
    EXPECT_GT(count, 10000u);
    EXPECT_LT(worst, 0.01) << "largest deviation of |a| from mu g while sliding";
    std::printf("sliding plateau: %zu samples, largest | |a| - mu g | / mu g = %.4f\n", count, worst);
}

TEST(Sliding, VerticalTableMotionChangesTheFrictionCapacity) {
    // The table also accelerates downwards at 0.3 g (after a smooth 0.3 s start): the normal
    // force drops to m (g - 0.3 g), and a horizontal shaking at 0.8 mu g that could not move the
    // block before now makes it slide at mu (g - 0.3 g).
    Model m = scenes::paper_sliding(1.0, 2.0);
    m.table_motion.horizontal = SineMotion{0.8 * 0.3 * g, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    m.table_motion.vertical = make_acceleration_series({0.0, 0.3, 2.0}, {0.0, -0.3 * g, -0.3 * g});
    const SlidingRun r = run(m);
    const double capacity = 0.3 * 0.7 * g;
    std::size_t count = 0;
    double worst = 0.0;
    std::size_t run_length = 0;
    for (std::size_t i = static_cast<std::size_t>(0.5 / 1e-4); i < r.t.size(); ++i) {
        run_length = r.sliding_points[i] == 2 ? run_length + 1 : 0;
        if (run_length < 200) continue;
        ++count;
        worst = std::max(worst, std::abs(std::abs(r.a_block[i]) - capacity) / capacity);
    }
    EXPECT_GT(count, 1000u);
    EXPECT_LT(worst, 0.01);
    std::printf("vertical -0.3 g: sliding plateau %zu samples, largest deviation from mu (g + a_v) %.4f\n", count, worst);
}

TEST(Sliding, ResidualSlipMatchesNewmarkRigidPlastic) {
    for (double h_s : {1.0, 0.5}) {
        Model m = scenes::paper_sliding(h_s, 5.0);
        const SlidingRun r = run(m);
        const auto reference = rigid_plastic_sliding(m.table_motion.horizontal, 0.3, g, 5.0, 1e-5);
        const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
        for (double cycles : {1.0, 5.0}) {
            const double dem = value_at(r.t, r.relative_x, cycles);
            const double ref = reference[static_cast<std::size_t>(std::llround(cycles / 1e-5))].relative_displacement_m;
            EXPECT_NEAR(dem, ref, 0.02 * std::abs(ref) + u_e) << "h_s = " << h_s << " after " << cycles << " cycles";
            std::printf("h_s = %.2f, after %.0f cycle(s): DEM slip %.4f mm, Newmark rigid-plastic %.4f mm (%.2f%%)\n",
                        h_s, cycles, 1e3 * dem, 1e3 * ref, 100.0 * (dem - ref) / ref);
        }
    }
}

TEST(Sliding, StifferContactsConvergeToRigidPlastic) {
    // Ten times stiffer springs (and a step to match) bring the slip closer to the rigid-plastic one.
    Model soft = scenes::paper_sliding(1.0, 5.0);
    Model stiff = soft;
    for (auto& p : stiff.contact.parameters) {
        p.kn_N_m *= 10.0;
        p.ks_N_m *= 10.0;
    }
    stiff.settings.dt_s = 3e-5;
    const auto reference = rigid_plastic_sliding(soft.table_motion.horizontal, 0.3, g, 5.0, 1e-5);
    const double ref = reference.back().relative_displacement_m;
    const double soft_error = std::abs(value_at(run(soft).t, run(soft).relative_x, 5.0) - ref);
    const SlidingRun s = run(stiff);
    const double stiff_error = std::abs(value_at(s.t, s.relative_x, 5.0) - ref);
    EXPECT_LT(stiff_error, soft_error);
    std::printf("slip error at 5 s: ks = 2e4 N/m %.4f mm, ks = 2e5 N/m %.4f mm\n", 1e3 * soft_error, 1e3 * stiff_error);
}

}  // namespace
}  // namespace blockdem
