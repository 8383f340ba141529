#include "dynamics/critical_time_step_3d.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "laws/linear_spring_dashpot.hpp"

namespace blockdem {
namespace {

// M^-1/2 of a body's rotation applied to a world vector: R diag(I^-1/2) R^T v.
Vec3 inverse_sqrt_inertia(const RigidBody3d& b, Vec3 v) {
    const Vec3 s{std::sqrt(b.inverse_moments_1_kg_m2.x), std::sqrt(b.inverse_moments_1_kg_m2.y),
                 std::sqrt(b.inverse_moments_1_kg_m2.z)};
    return rotate(b.orientation, hadamard(s, rotate_inverse(b.orientation, v)));
}

double l1(Vec3 v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

using Rows = std::array<double, 6>;  // x, y, z, rotation about x, y, z

// Adds k |g_p| |g|_1 to each row p of the dynamic bodies of one direction d at point c.
void add_direction(const World3d& w, const ContactPoint3d& c, Vec3 d, double k, double damping,
                   std::vector<Rows>& rows_k, std::vector<Rows>& rows_c) {
    const std::uint32_t ends[2] = {c.key.body_a, c.key.body_b};
    std::array<Vec3, 2> translation{}, rotation{};
    std::array<bool, 2> moves{};
    double norm1 = 0.0;
    for (int e = 0; e < 2; ++e) {
        const std::uint32_t i = ends[e];
        moves[e] = w.kinds[i] == BodyKind3d::dynamic;
        if (!moves[e]) continue;
        const RigidBody3d& b = w.bodies[i];
        // Signs do not matter: only absolute values enter the row sums.
        translation[e] = (1.0 / std::sqrt(b.mass_kg)) * d;
        rotation[e] = inverse_sqrt_inertia(b, cross(c.point_m - b.position_m, d));
        norm1 += l1(translation[e]) + l1(rotation[e]);
    }
    for (int e = 0; e < 2; ++e) {
        if (!moves[e]) continue;
        const Vec3 t = translation[e], r = rotation[e];
        const double g[6] = {std::abs(t.x), std::abs(t.y), std::abs(t.z), std::abs(r.x), std::abs(r.y), std::abs(r.z)};
        for (int p = 0; p < 6; ++p) {
            rows_k[ends[e]][p] += k * g[p] * norm1;
            rows_c[ends[e]][p] += damping * g[p] * norm1;
        }
    }
}

}  // namespace

CriticalTimeStep3d live_time_step_3d(const World3d& w) {
    std::vector<Rows> rows_k(w.bodies.size(), Rows{}), rows_c(w.bodies.size(), Rows{});
    const std::vector<double> dashpot_masses_kg = point_dashpot_masses_kg(w, w.contacts);
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const ContactPoint3d& c = w.contacts[i];
        const ContactParameters p = point_parameters(w.contact, c.stiffness_share);
        const DashpotCoefficients k = dashpot_coefficients(p, dashpot_masses_kg[i]);
        // Two tangents: any unit vector off the normal, and the third of the frame.
        const Vec3 n = c.normal;
        const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        const Vec3 t1 = normalized(cross(n, helper));
        const Vec3 t2 = cross(n, t1);
        add_direction(w, c, n, p.kn_N_m, k.cn_N_s_m, rows_k, rows_c);
        add_direction(w, c, t1, p.ks_N_m, k.cs_N_s_m, rows_k, rows_c);
        add_direction(w, c, t2, p.ks_N_m, k.cs_N_s_m, rows_k, rows_c);
    }
    CriticalTimeStep3d r;
    double lambda_k = 0.0, lambda_c = 0.0;
    for (std::uint32_t i = 0; i < rows_k.size(); ++i) {
        for (int q = 0; q < 6; ++q) {
            if (rows_k[i][q] > lambda_k) {
                lambda_k = rows_k[i][q];
                r.body = i;
            }
            lambda_c = std::max(lambda_c, rows_c[i][q]);
        }
    }
    if (!(lambda_k > 0.0)) {
        r.dt_s = std::numeric_limits<double>::infinity();
        return r;
    }
    // The positive root of (Lambda_K / 4) dt^2 + (Lambda_C / 2) dt - 1 = 0.
    r.dt_s = (std::sqrt(0.25 * lambda_c * lambda_c + lambda_k) - 0.5 * lambda_c) / (0.5 * lambda_k);
    r.omega_rad_s = std::sqrt(lambda_k);
    r.h = lambda_c / (2.0 * r.omega_rad_s);
    return r;
}

}  // namespace blockdem
