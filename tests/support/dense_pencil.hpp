#pragma once
// Dense references for the highest contact mode's limit (dynamics/highest_mode.hpp): a symmetric
// matrix's eigenvalues by cyclic Jacobi rotations, and the dt at which the largest eigenvalue of
// (dt^2/4) K~ + (dt/2) C~ reaches 1, by bisection. Independent of the power iteration they check.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace blockdem::testing {

using Dense = std::vector<std::vector<double>>;

// Eigenvalues and eigenvectors (columns of v) of a symmetric matrix, by cyclic Jacobi sweeps.
inline std::vector<double> jacobi_eigen(Dense a, Dense* vectors = nullptr) {
    const std::size_t n = a.size();
    Dense v(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) v[i][i] = 1.0;
    for (int sweep = 0; sweep < 100; ++sweep) {
        double off = 0.0, scale = 0.0;
        for (std::size_t p = 0; p < n; ++p)
            for (std::size_t q = 0; q < n; ++q) (p == q ? scale : off) += a[p][q] * a[p][q];
        if (off <= 1e-30 * scale) break;
        for (std::size_t p = 0; p + 1 < n; ++p) {
            for (std::size_t q = p + 1; q < n; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (std::size_t k = 0; k < n; ++k) {  // columns p, q
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (std::size_t k = 0; k < n; ++k) {  // rows p, q
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (std::size_t k = 0; k < n; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
        }
    }
    if (vectors) *vectors = v;
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = a[i][i];
    return values;
}

struct DensePencil {
    Dense k, c;  // mass-normalised stiffness [1/s^2] and damping [1/s], a row per degree of freedom
};

// The dt at which the largest eigenvalue of (dt^2/4) K~ + (dt/2) C~ is 1, by bisection.
inline double dense_limit_s(const DensePencil& m) {
    if (m.k.empty()) return INFINITY;
    auto top = [&](double dt) {
        Dense b = m.k;
        for (std::size_t i = 0; i < b.size(); ++i)
            for (std::size_t j = 0; j < b.size(); ++j) b[i][j] = 0.25 * dt * dt * m.k[i][j] + 0.5 * dt * m.c[i][j];
        double most = 0.0;
        for (double v : jacobi_eigen(b)) most = std::max(most, v);
        return most;
    };
    double lo = 0.0, hi = 1.0;
    while (top(hi) < 1.0) hi *= 2.0;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (top(mid) < 1.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace blockdem::testing
