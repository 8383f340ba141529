#pragma once
// 3x3 matrices: inertia tensors and rotation matrices, and the eigen-decomposition of a
// symmetric one (the principal axes of an inertia tensor).
#include <array>

#include "geometry/vec3.hpp"

namespace blockdem {

/// Row-major 3x3 matrix.
struct Matrix3d {
    std::array<std::array<double, 3>, 3> m{};

    static constexpr Matrix3d identity() { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }
    /// The matrix whose columns are a, b, c.
    static constexpr Matrix3d from_columns(Vec3 a, Vec3 b, Vec3 c) {
        return {{{{a.x, b.x, c.x}, {a.y, b.y, c.y}, {a.z, b.z, c.z}}}};
    }
    /// The outer product a b^T.
    static constexpr Matrix3d outer(Vec3 a, Vec3 b) {
        return {{{{a.x * b.x, a.x * b.y, a.x * b.z}, {a.y * b.x, a.y * b.y, a.y * b.z}, {a.z * b.x, a.z * b.y, a.z * b.z}}}};
    }
    constexpr Vec3 column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
    constexpr double trace() const { return m[0][0] + m[1][1] + m[2][2]; }
};

constexpr Matrix3d operator+(const Matrix3d& a, const Matrix3d& b) {
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][j] + b.m[i][j];
    return r;
}
constexpr Matrix3d operator*(double s, const Matrix3d& a) {
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = s * a.m[i][j];
    return r;
}
constexpr Matrix3d operator-(const Matrix3d& a, const Matrix3d& b) { return a + (-1.0) * b; }
constexpr Vec3 operator*(const Matrix3d& a, Vec3 v) {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z, a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
constexpr Matrix3d operator*(const Matrix3d& a, const Matrix3d& b) {
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}
constexpr Matrix3d transpose(const Matrix3d& a) {
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
    return r;
}
constexpr double determinant(const Matrix3d& a) {
    return dot(a.column(0), cross(a.column(1), a.column(2)));
}

/// Eigenvalues and eigenvectors of a symmetric matrix.
struct SymmetricEigen {
    Vec3 values;      ///< ascending
    Matrix3d vectors; ///< unit eigenvectors as columns, in the order of values; a rotation (det +1)
};

/// Cyclic Jacobi rotations until the off-diagonal part is at round-off: for 3x3 this takes a
/// handful of sweeps and is accurate for repeated eigenvalues too (a cube's, a cylinder's two
/// equal moments), where closed-form cubic roots lose half their digits.
SymmetricEigen symmetric_eigen(const Matrix3d& symmetric);

}  // namespace blockdem
