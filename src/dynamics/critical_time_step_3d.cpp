#include "dynamics/critical_time_step_3d.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "dynamics/block_pencil.hpp"
#include "dynamics/highest_mode.hpp"
#include "dynamics/gershgorin_rows.hpp"
#include "dynamics/point_runs.hpp"
#include "geometry/quaternion.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "world/parallel.hpp"

namespace blockdem {
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
    std::vector<PointLaw> laws(points.size());
    parallel_for(static_cast<std::ptrdiff_t>(points.size()), [&](std::ptrdiff_t i) {
        const ContactParameters p = point_parameters(w.contact, points[i].stiffness_share);
        const DashpotCoefficients c = dashpot_coefficients(p, dashpot_masses_kg[i]);
        laws[i] = {p.kn_N_m, p.ks_N_m, c.cn_N_s_m, c.cs_N_s_m};
    });
    return laws;
}

// What the pencil needs of a body: 1 / sqrt(m), and M^-1/2 of its rotation in the world frame,
// R diag(I^-1/2) R^T (zero for a body that does not move: no entries in g).
struct BodyRoots {
    double over_sqrt_mass = 0.0;
    Matrix3d over_sqrt_inertia{};
};

std::vector<BodyRoots> body_roots(const World3d& w) {
    std::vector<BodyRoots> roots(w.bodies.size());
    parallel_for(static_cast<std::ptrdiff_t>(w.bodies.size()), [&](std::ptrdiff_t i) {
        if (w.kinds[i] != BodyKind3d::dynamic) return;
        const RigidBody3d& b = w.bodies[i];
        const Matrix3d r = rotation_matrix(b.orientation);
        const Vec3 s{std::sqrt(b.inverse_moments_1_kg_m2.x), std::sqrt(b.inverse_moments_1_kg_m2.y),
                     std::sqrt(b.inverse_moments_1_kg_m2.z)};
        const Matrix3d scaled = Matrix3d::from_columns(s.x * r.column(0), s.y * r.column(1), s.z * r.column(2));
        roots[i] = {1.0 / std::sqrt(b.mass_kg), scaled * transpose(r)};
    });
    return roots;
}

// The points as dynamics/point_runs.hpp reads them: each point's normal and two tangents, g's
// parts on its bodies, -(d, r_a x d) on a and +(d, r_b x d) on b mass-normalised (zero on a body
// that does not move: its roots are zero), with the point's springs and dashpots along them.
struct PencilSource3d {
    const World3d& w;
    const std::vector<ContactPoint3d>& points_;
    const std::vector<PointLaw>& laws;
    const std::vector<BodyRoots>& roots;

    std::size_t points() const { return points_.size(); }

    PointEnds ends(std::size_t i) const {
        const ContactKey3d& k = points_[i].key;
        return {k.body_a, k.body_b, w.kinds[k.body_a] == BodyKind3d::dynamic, w.kinds[k.body_b] == BodyKind3d::dynamic};
    }

    template <class F>
    void directions(std::size_t i, F&& f) const {
        const ContactPoint3d& c = points_[i];
        const std::array<Vec3, 2> t = tangents(c.normal);
        const Vec3 directions[3] = {c.normal, t[0], t[1]};
        const Vec3 lever_a = c.point_m - w.bodies[c.key.body_a].position_m;
        const Vec3 lever_b = c.point_m - w.bodies[c.key.body_b].position_m;
        for (int d = 0; d < 3; ++d) {
            double ga[6], gb[6];
            end_part(roots[c.key.body_a], -1.0, lever_a, directions[d], ga);
            end_part(roots[c.key.body_b], 1.0, lever_b, directions[d], gb);
            f(ga, gb, spring(i, d), dashpot(i, d));
        }
    }

    template <class F>
    void end_directions(std::size_t i, bool b_end, F&& f) const {
        const ContactPoint3d& c = points_[i];
        const std::uint32_t body = b_end ? c.key.body_b : c.key.body_a;
        const std::array<Vec3, 2> t = tangents(c.normal);
        const Vec3 directions[3] = {c.normal, t[0], t[1]};
        const Vec3 lever = c.point_m - w.bodies[body].position_m;
        for (int d = 0; d < 3; ++d) {
            double g[6];
            end_part(roots[body], b_end ? 1.0 : -1.0, lever, directions[d], g);
            f(g, spring(i, d), dashpot(i, d));
        }
    }

private:
    double spring(std::size_t i, int d) const { return d == 0 ? laws[i].kn_N_m : laws[i].ks_N_m; }
    double dashpot(std::size_t i, int d) const { return d == 0 ? laws[i].cn_N_s_m : laws[i].cs_N_s_m; }

    // sign (d, r x d), mass-normalised, into g.
    static void end_part(const BodyRoots& root, double sign, Vec3 lever, Vec3 d, double* g) {
        const Vec3 translation = (sign * root.over_sqrt_mass) * d;
        const Vec3 rotation = sign * (root.over_sqrt_inertia * cross(lever, d));
        g[0] = translation.x, g[1] = translation.y, g[2] = translation.z;
        g[3] = rotation.x, g[4] = rotation.y, g[5] = rotation.z;
    }
};

// A set of points' laws and their bodies' roots, and the source over them; the runs of its points.
struct StiffnessPoints3d {
    std::vector<PointLaw> laws;
    std::vector<BodyRoots> roots;
    PencilSource3d source;
    StiffnessPoints3d(const World3d& w, const std::vector<ContactPoint3d>& points)
        : laws(point_laws(w, points)), roots(body_roots(w)), source{w, points, laws, roots} {}
    StiffnessPoints3d(const StiffnessPoints3d&) = delete;
    StiffnessPoints3d& operator=(const StiffnessPoints3d&) = delete;
};


using Rows = std::array<double, 6>;  // x, y, z, rotation about x, y, z

}  // namespace

CriticalTimeStep3d stable_time_step_3d(const World3d& w, const std::vector<ContactPoint3d>& points) {
    const std::size_t n = w.bodies.size();
    const StiffnessPoints3d stiffness(w, points);
    const GershgorinRows<6> rows = gershgorin_rows<6>(stiffness.source, PointRuns(stiffness.source, n));
    const std::vector<Rows>& rows_k = rows.stiffness_1_s2;
    const std::vector<Rows>& rows_c = rows.damping_1_s;
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

// Each body's blocks from its own points, in parallel (the sign of g on an end does not matter
// in g g^T).
CriticalTimeStep3d body_block_limit_3d(const World3d& w, double dt_s) {
    std::vector<BodyBlocks<6>> blocks(w.bodies.size());
    const StiffnessPoints3d stiffness(w, w.contacts);
    const PointRuns runs(stiffness.source, w.bodies.size());
    parallel_for(static_cast<std::ptrdiff_t>(w.bodies.size()), [&](std::ptrdiff_t i) {
        runs.for_each_direction(stiffness.source, static_cast<std::size_t>(i),
                                [&](const double* g, double k, double c) { blocks[i].add(g, k, c); });
    });
    const auto [body, mode] = most_unstable_body(blocks, dt_s);
    if (!mode.found) return {.dt_s = std::numeric_limits<double>::infinity()};
    return {mode.dt_s, static_cast<std::uint32_t>(body), mode.omega_rad_s, mode.h};
}

CriticalTimeStep3d highest_mode_time_step_3d(const World3d& w, const std::vector<ContactPoint3d>& points,
                                             const CriticalTimeStep3d& bound) {
    if (!std::isfinite(bound.dt_s)) return bound;
    const StiffnessPoints3d stiffness(w, points);
    const HighestMode mode = pencil_highest_mode<6>(stiffness.source, w.bodies.size(), bound.dt_s);
    if (!mode.found || mode.dt_s <= bound.dt_s) return bound;
    return {mode.dt_s, static_cast<std::uint32_t>(body_moving_most(mode.mode, 6)), mode.omega_rad_s, mode.h};
}

}  // namespace blockdem
