#include "motion/linear_oscillator.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem {
namespace {

using Matrix4 = std::array<std::array<double, 4>, 4>;

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 c{};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j) c[i][j] += a[i][k] * b[k][j];
    return c;
}

double norm_inf(const Matrix4& a) {
    double n = 0.0;
    for (const auto& row : a) n = std::max(n, std::abs(row[0]) + std::abs(row[1]) + std::abs(row[2]) + std::abs(row[3]));
    return n;
}

// exp(A) by scaling and squaring with a Taylor series: ||A / 2^s|| <= 0.25 and 16 terms leave a
// truncation error far below double rounding. More than max_squarings halvings (||A|| > 4e18)
// means an oscillator far outside any physical range (a period of 1e-200 s): refused rather
// than looped on (an infinite norm never halves below 0.25).
constexpr int max_squarings = 64;

Matrix4 exponential(Matrix4 a) {
    if (!std::isfinite(norm_inf(a))) throw std::invalid_argument("oscillator step: the system matrix overflows");
    int squarings = 0;
    while (norm_inf(a) > 0.25) {
        if (squarings == max_squarings) throw std::invalid_argument("oscillator step: the system matrix is too large to integrate");
        for (auto& row : a)
            for (double& x : row) x *= 0.5;
        ++squarings;
    }
    Matrix4 sum{}, term{};
    for (int i = 0; i < 4; ++i) sum[i][i] = term[i][i] = 1.0;
    for (int k = 1; k <= 16; ++k) {
        term = multiply(term, a);
        for (auto& row : term)
            for (double& x : row) x /= k;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) sum[i][j] += term[i][j];
    }
    for (int s = 0; s < squarings; ++s) sum = multiply(sum, sum);
    return sum;
}

}  // namespace

OscillatorStep::OscillatorStep(double omega_rad_s, double zeta, double h_s) : omega_(omega_rad_s), zeta_(zeta), h_(h_s) {
    if (!(omega_rad_s > 0.0) || !(zeta >= 0.0) || !(h_s > 0.0) || !std::isfinite(omega_rad_s * omega_rad_s * h_s) ||
        !std::isfinite(zeta * omega_rad_s * h_s))
        throw std::invalid_argument(fmt::format("an oscillator step needs finite omega > 0, zeta >= 0 and h > 0 (omega = {:g} "
                                                "rad/s, zeta = {:g}, h = {:g} s)", omega_rad_s, zeta, h_s));
    // d/dt [x, v, f, f'] = M [x, v, f, f'] with f' constant over the step.
    Matrix4 m{};
    m[0][1] = h_s;
    m[1][0] = -omega_rad_s * omega_rad_s * h_s;
    m[1][1] = -2.0 * zeta * omega_rad_s * h_s;
    m[1][2] = h_s;
    m[2][3] = h_s;
    const Matrix4 e = exponential(m);
    map_ = {e[0], e[1]};
}

OscillatorState OscillatorStep::advance(OscillatorState s, double f0, double f1) const {
    const double slope = (f1 - f0) / h_;
    return {map_[0][0] * s.x + map_[0][1] * s.v + map_[0][2] * f0 + map_[0][3] * slope,
            map_[1][0] * s.x + map_[1][1] * s.v + map_[1][2] * f0 + map_[1][3] * slope};
}

}  // namespace blockdem
