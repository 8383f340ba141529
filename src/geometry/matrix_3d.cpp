// Jacobi eigenvalue iteration for a symmetric 3x3 matrix (Golub and Van Loan, Matrix
// Computations, section 8.5: the classical two-sided rotation with the stable choice of angle).
#include "geometry/matrix_3d.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace blockdem {

SymmetricEigen symmetric_eigen(const Matrix3d& symmetric) {
    Matrix3d a = symmetric;
    Matrix3d v = Matrix3d::identity();
    constexpr int max_sweeps = 50;
    for (int sweep = 0; sweep < max_sweeps; ++sweep) {
        const double off = std::abs(a.m[0][1]) + std::abs(a.m[0][2]) + std::abs(a.m[1][2]);
        const double diagonal = std::abs(a.m[0][0]) + std::abs(a.m[1][1]) + std::abs(a.m[2][2]);
        if (off <= 1e-17 * diagonal || off == 0.0) break;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a.m[p][q] == 0.0) continue;
                // The rotation in the (p, q) plane that zeroes a_pq, its tangent the smaller root.
                const double theta = (a.m[q][q] - a.m[p][p]) / (2.0 * a.m[p][q]);
                const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0);
                const double s = t * c;
                Matrix3d j = Matrix3d::identity();
                j.m[p][p] = c;
                j.m[q][q] = c;
                j.m[p][q] = s;
                j.m[q][p] = -s;
                a = transpose(j) * a * j;
                a.m[p][q] = a.m[q][p] = 0.0;
                v = v * j;
            }
        }
    }
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int i, int j) { return a.m[i][i] < a.m[j][j]; });
    SymmetricEigen e;
    e.values = {a.m[order[0]][order[0]], a.m[order[1]][order[1]], a.m[order[2]][order[2]]};
    Vec3 c0 = v.column(order[0]), c1 = v.column(order[1]);
    // The third axis from the first two, so that the axes are a right-handed frame (a rotation).
    e.vectors = Matrix3d::from_columns(c0, c1, cross(c0, c1));
    return e;
}

}  // namespace blockdem
