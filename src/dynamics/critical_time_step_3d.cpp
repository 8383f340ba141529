#include "dynamics/critical_time_step_3d.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "dynamics/block_pencil.hpp"
#include "dynamics/highest_mode.hpp"
#include "geometry/quaternion.hpp"
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

namespace {

// The two tangents of a point: any unit vector off the normal, and the third of the frame (the
// shear springs and dashpots are isotropic in the tangent plane, so any pair spans them).
std::array<Vec3, 2> tangents(Vec3 n) {
    const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 t1 = normalized(cross(n, helper));
    return {t1, cross(n, t1)};
}

// A point's springs and dashpots as the law applies them: kn and ks times its share, its
// dashpots from its share of the pair's reduced mass.
struct PointLaw {
    double kn_N_m, ks_N_m, cn_N_s_m, cs_N_s_m;
};

std::vector<PointLaw> point_laws(const World3d& w, const std::vector<ContactPoint3d>& points) {
    const std::vector<double> dashpot_masses_kg = point_dashpot_masses_kg(w, points);
    std::vector<PointLaw> laws;
    laws.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const ContactParameters p = point_parameters(w.contact, points[i].stiffness_share);
        const DashpotCoefficients c = dashpot_coefficients(p, dashpot_masses_kg[i]);
        laws.push_back({p.kn_N_m, p.ks_N_m, c.cn_N_s_m, c.cs_N_s_m});
    }
    return laws;
}

}  // namespace

CriticalTimeStep3d stable_time_step_3d(const World3d& w, const std::vector<ContactPoint3d>& points) {
    std::vector<Rows> rows_k(w.bodies.size(), Rows{}), rows_c(w.bodies.size(), Rows{});
    const std::vector<PointLaw> laws = point_laws(w, points);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const ContactPoint3d& c = points[i];
        const std::array<Vec3, 2> t = tangents(c.normal);
        add_direction(w, c, c.normal, laws[i].kn_N_m, laws[i].cn_N_s_m, rows_k, rows_c);
        add_direction(w, c, t[0], laws[i].ks_N_m, laws[i].cs_N_s_m, rows_k, rows_c);
        add_direction(w, c, t[1], laws[i].ks_N_m, laws[i].cs_N_s_m, rows_k, rows_c);
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

CriticalTimeStep3d live_time_step_3d(const World3d& w) { return stable_time_step_3d(w, w.contacts); }

namespace {

// What the pencil needs of a body: 1 / sqrt(m), and M^-1/2 of its rotation in the world frame,
// R diag(I^-1/2) R^T (zero for a body that does not move: no entries in g).
struct BodyRoots {
    double over_sqrt_mass = 0.0;
    Matrix3d over_sqrt_inertia{};
};

std::vector<BodyRoots> body_roots(const World3d& w) {
    std::vector<BodyRoots> roots(w.bodies.size());
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        const RigidBody3d& b = w.bodies[i];
        const Matrix3d r = rotation_matrix(b.orientation);
        const Vec3 s{std::sqrt(b.inverse_moments_1_kg_m2.x), std::sqrt(b.inverse_moments_1_kg_m2.y),
                     std::sqrt(b.inverse_moments_1_kg_m2.z)};
        const Matrix3d scaled = Matrix3d::from_columns(s.x * r.column(0), s.y * r.column(1), s.z * r.column(2));
        roots[i] = {1.0 / std::sqrt(b.mass_kg), scaled * transpose(r)};
    }
    return roots;
}

// The points as dynamics/block_pencil.hpp reads them: each point's normal and two tangents, g's
// parts on its bodies, -(d, r_a x d) on a and +(d, r_b x d) on b mass-normalised (zero on a body
// that does not move: its roots are zero), with the point's springs and dashpots along them.
struct PencilSource3d {
    const World3d& w;
    const std::vector<ContactPoint3d>& points_;
    const std::vector<PointLaw>& laws;
    const std::vector<BodyRoots>& roots;

    std::size_t points() const { return points_.size(); }

    PencilEnds ends(std::size_t i) const {
        const ContactKey3d& k = points_[i].key;
        return {k.body_a, k.body_b, w.kinds[k.body_a] == BodyKind3d::dynamic, w.kinds[k.body_b] == BodyKind3d::dynamic};
    }

    template <class F>
    void directions(std::size_t i, F&& f) const {
        const ContactPoint3d& c = points_[i];
        const std::uint32_t ends[2] = {c.key.body_a, c.key.body_b};
        const std::array<Vec3, 2> t = tangents(c.normal);
        const Vec3 directions[3] = {c.normal, t[0], t[1]};
        const PointLaw& law = laws[i];
        const Vec3 levers[2] = {c.point_m - w.bodies[ends[0]].position_m, c.point_m - w.bodies[ends[1]].position_m};
        for (int d = 0; d < 3; ++d) {
            double g[2][6];
            for (int e = 0; e < 2; ++e) {
                const BodyRoots& root = roots[ends[e]];
                const double sign = e == 0 ? -1.0 : 1.0;
                const Vec3 translation = (sign * root.over_sqrt_mass) * directions[d];
                const Vec3 rotation = sign * (root.over_sqrt_inertia * cross(levers[e], directions[d]));
                g[e][0] = translation.x, g[e][1] = translation.y, g[e][2] = translation.z;
                g[e][3] = rotation.x, g[e][4] = rotation.y, g[e][5] = rotation.z;
            }
            f(g[0], g[1], d == 0 ? law.kn_N_m : law.ks_N_m, d == 0 ? law.cn_N_s_m : law.cs_N_s_m);
        }
    }
};

}  // namespace

CriticalTimeStep3d body_block_limit_3d(const World3d& w, double dt_s) {
    std::vector<BodyBlocks<6>> blocks(w.bodies.size());
    const std::vector<PointLaw> laws = point_laws(w, w.contacts);
    const std::vector<BodyRoots> roots = body_roots(w);
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const ContactPoint3d& c = w.contacts[i];
        const std::array<Vec3, 2> t = tangents(c.normal);
        const Vec3 directions[3] = {c.normal, t[0], t[1]};
        for (std::uint32_t body : {c.key.body_a, c.key.body_b}) {
            if (w.kinds[body] != BodyKind3d::dynamic) continue;
            const BodyRoots& root = roots[body];
            const Vec3 lever = c.point_m - w.bodies[body].position_m;
            for (int d = 0; d < 3; ++d) {
                // (The sign of g on this end does not matter in g g^T.)
                const Vec3 n = directions[d], q = root.over_sqrt_inertia * cross(lever, n);
                const double g[6] = {root.over_sqrt_mass * n.x, root.over_sqrt_mass * n.y, root.over_sqrt_mass * n.z,
                                     q.x, q.y, q.z};
                blocks[body].add(g, d == 0 ? laws[i].kn_N_m : laws[i].ks_N_m, d == 0 ? laws[i].cn_N_s_m : laws[i].cs_N_s_m);
            }
        }
    }
    const auto [body, mode] = most_unstable_body(blocks, dt_s);
    if (!mode.found) return {.dt_s = std::numeric_limits<double>::infinity()};
    return {mode.dt_s, static_cast<std::uint32_t>(body), mode.omega_rad_s, mode.h};
}

CriticalTimeStep3d highest_mode_time_step_3d(const World3d& w, const std::vector<ContactPoint3d>& points,
                                             const CriticalTimeStep3d& bound) {
    if (!std::isfinite(bound.dt_s)) return bound;
    const std::vector<PointLaw> laws = point_laws(w, points);
    const std::vector<BodyRoots> roots = body_roots(w);
    const HighestMode mode = pencil_highest_mode<6>(PencilSource3d{w, points, laws, roots}, w.bodies.size(), bound.dt_s);
    if (!mode.found || mode.dt_s <= bound.dt_s) return bound;
    return {mode.dt_s, static_cast<std::uint32_t>(body_moving_most(mode.mode, 6)), mode.omega_rad_s, mode.h};
}

}  // namespace blockdem
