#include "laws/material_stiffness.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {
namespace {

// The median of values (the upper one of the middle two for an even count: a real block's size).
double median(std::vector<double> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

double shear_modulus_pa(const ElasticMaterial& m) { return m.young_modulus_pa / (2.0 * (1.0 + m.poisson_ratio)); }

JointStiffness block_joint_stiffness(const JointSide& a, const JointSide& b) {
    JointStiffness s;
    // Each block lends half its height to this joint: springs in series.
    s.kn_per_area_pa_m = 1.0 / (0.5 * a.block.height_m / a.material.young_modulus_pa +
                                0.5 * b.block.height_m / b.material.young_modulus_pa);
    s.ks_per_area_pa_m = 1.0 / (0.5 * a.block.height_m / shear_modulus_pa(a.material) +
                                0.5 * b.block.height_m / shear_modulus_pa(b.material));
    // The shared face is the narrower block's, shared by its two corner points.
    s.tributary_length_m = 0.5 * std::min(a.block.width_m, b.block.width_m);
    s.thickness_m = std::min(a.block.thickness_m, b.block.thickness_m);
    const double area_m2 = s.tributary_length_m * s.thickness_m;
    s.kn_N_m = s.kn_per_area_pa_m * area_m2;
    s.ks_N_m = s.ks_per_area_pa_m * area_m2;
    return s;
}

BlockDimensions block_dimensions(std::span<const Vec2> vertices_m, double thickness_m) {
    double x_low = INFINITY, x_high = -INFINITY, y_low = INFINITY, y_high = -INFINITY;
    for (const Vec2& v : vertices_m) {
        x_low = std::min(x_low, v.x);
        x_high = std::max(x_high, v.x);
        y_low = std::min(y_low, v.y);
        y_high = std::max(y_high, v.y);
    }
    return {y_high - y_low, x_high - x_low, thickness_m};
}

BlockDimensions typical_block(const std::vector<BlockDimensions>& blocks) {
    std::vector<double> heights, widths, thicknesses;
    for (const BlockDimensions& b : blocks) {
        heights.push_back(b.height_m);
        widths.push_back(b.width_m);
        thicknesses.push_back(b.thickness_m);
    }
    return {median(std::move(heights)), median(std::move(widths)), median(std::move(thicknesses))};
}

}  // namespace blockdem
