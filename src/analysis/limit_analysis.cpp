// The static theorem as an LP (limit_analysis.hpp). Columns: per interface end, two
// non-negative multiples of its friction cone's edges, n + mu t and n - mu t (associative, every
// mu at most cone_edges_max_mu), or n >= 0 and a free s (non-associative, or a larger mu); last,
// the free lambda. Rows: per dynamic body, force x, force y and moment about its centroid
// (equalities: the interface forces plus lambda x live load equal minus the dead load); with n
// and s, also per interface end s - mu n <= 0 and -s - mu n <= 0 (divided by mu where mu > 1).
// Forces are scaled by the heaviest body's weight and lengths by the largest body's size, so that
// the coefficients are of order one whatever the units of the model.
// GLPK's primal simplex (no presolve, so that an infeasible or unbounded problem still reports
// its status and an optimum its dual values; its presolver, dual simplex and interior point
// were no faster on walls of 1000 bricks: docs/limit_analysis.md). Non-associative friction
// rewrites the friction rows as shear capacities and re-solves from the last basis.
#include "analysis/limit_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include <glpk.h>

#include "analysis/glpk_guard.hpp"
#include "geometry/polygon.hpp"

namespace blockdem {
namespace {

// Antiparallel edges: their normals within this angle of opposite.
constexpr double parallel_tolerance_rad = 1e-4;

bool movable(const BodyDef& b) { return b.kind == BodyKind::dynamic; }

struct Box {
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
};

Box bounding_box(const std::vector<Vec2>& v) {
    Box b;
    for (Vec2 p : v) {
        b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
        b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
    }
    return b;
}

bool boxes_touch(const Box& a, const Box& b, double tolerance_m) {
    return a.lo.x <= b.hi.x + tolerance_m && b.lo.x <= a.hi.x + tolerance_m && a.lo.y <= b.hi.y + tolerance_m &&
           b.lo.y <= a.hi.y + tolerance_m;
}

// The common segment of edge p0-p1 (of a) and edge q0-q1 (of b), if they touch.
bool common_segment(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1, double tolerance_m, std::array<Vec2, 2>& ends, Vec2& normal) {
    const double edge_length = length(p1 - p0);
    if (!(edge_length > tolerance_m)) return false;
    const Vec2 along = (1.0 / edge_length) * (p1 - p0);
    const Vec2 n{along.y, -along.x};  // outward for a counter-clockwise polygon
    const Vec2 other = normalized(q1 - q0);
    if (dot(along, other) > -std::cos(parallel_tolerance_rad)) return false;
    if (std::abs(dot(q0 - p0, n)) > tolerance_m || std::abs(dot(q1 - p0, n)) > tolerance_m) return false;
    const double u0 = dot(q0 - p0, along);
    const double u1 = dot(q1 - p0, along);
    const double lo = std::max(0.0, std::min(u0, u1));
    const double hi = std::min(edge_length, std::max(u0, u1));
    if (!(hi - lo > tolerance_m)) return false;
    ends = {p0 + lo * along, p0 + hi * along};
    normal = n;
    return true;
}

// A corner of one polygon resting on an edge of the other: the corner lies on the edge's line,
// inside the edge (more than the tolerance from its ends), and both its neighbouring corners
// lie outside, beyond the tolerance (a corner whose edge lies along the other edge belongs to
// an edge-to-edge interface; a corner on a corner has no normal). The point is at the corner,
// the normal is the edge's outward normal.
bool corner_on_edge(Vec2 before, Vec2 corner, Vec2 after, Vec2 q0, Vec2 q1, double tolerance_m, Vec2& normal) {
    const double edge_length = length(q1 - q0);
    if (!(edge_length > 2.0 * tolerance_m)) return false;
    const Vec2 along = (1.0 / edge_length) * (q1 - q0);
    const Vec2 n{along.y, -along.x};  // outward for a counter-clockwise polygon
    const double u = dot(corner - q0, along);
    if (std::abs(dot(corner - q0, n)) > tolerance_m || u <= tolerance_m || u >= edge_length - tolerance_m) return false;
    if (dot(before - q0, n) <= tolerance_m || dot(after - q0, n) <= tolerance_m) return false;
    normal = n;
    return true;
}

double largest_extent_m(const Model& model) {
    double extent = 0.0;
    for (const BodyDef& b : model.bodies) {
        const Box box = bounding_box(b.vertices_m);
        extent = std::max({extent, box.hi.x - box.lo.x, box.hi.y - box.lo.y});
    }
    return extent;
}

double mass_of(const BodyDef& b, const PolygonProperties& p) {
    return b.mass_kg.value_or(b.density_kg_m3 * p.area_m2 * b.thickness_m);
}

// GLPK's sparse matrix, 1-based (entry 0 unused).
struct Triplets {
    std::vector<int> row{0};
    std::vector<int> column{0};
    std::vector<double> value{0.0};
    // Coefficients are of order one; a round-off remainder (cos 90 deg = 6e-17) is left out.
    void add(int r, int c, double v) {
        if (std::abs(v) < 1e-13) return;
        row.push_back(r);
        column.push_back(c);
        value.push_back(v);
    }
};

// Column of interface k's end j: n at 2 (2k + j) + 1, s right after it (1-based).
int normal_column(std::size_t k, int j) { return static_cast<int>(2 * (2 * k + static_cast<std::size_t>(j)) + 1); }

}  // namespace

const char* to_string(LimitStatus status) {
    switch (status) {
        case LimitStatus::collapse: return "collapse";
        case LimitStatus::no_equilibrium: return "no_equilibrium";
        case LimitStatus::unbounded: return "unbounded";
    }
    return "?";
}

const char* to_string(InterfaceMotion motion) {
    switch (motion) {
        case InterfaceMotion::locked: return "locked";
        case InterfaceMotion::hinge_at_end_0: return "hinge_at_end_0";
        case InterfaceMotion::hinge_at_end_1: return "hinge_at_end_1";
        case InterfaceMotion::opens: return "opens";
        case InterfaceMotion::slides: return "slides";
    }
    return "?";
}

std::vector<Vec2> body_centroids_m(const Model& model) {
    std::vector<Vec2> out;
    out.reserve(model.bodies.size());
    for (const BodyDef& b : model.bodies) out.push_back(polygon_properties(b.vertices_m).centroid_m);
    return out;
}

// Sort and sweep: the bodies in order of their boxes' low end along the longer axis of the
// model; a body is tested only against those whose boxes start before its own ends. A wall of
// n x m bricks tests each brick against about the bricks of its column band, not all N
// (O(N log N + N k); 1e4 bricks: milliseconds, docs/limit_analysis.md).
std::vector<BlockInterface> find_interfaces(const Model& model, double tolerance_m) {
    const auto& bodies = model.bodies;
    std::vector<Box> boxes;
    Box all;
    for (const BodyDef& b : bodies) {
        boxes.push_back(bounding_box(b.vertices_m));
        all.lo = {std::min(all.lo.x, boxes.back().lo.x), std::min(all.lo.y, boxes.back().lo.y)};
        all.hi = {std::max(all.hi.x, boxes.back().hi.x), std::max(all.hi.y, boxes.back().hi.y)};
    }
    const bool along_x = bodies.empty() || all.hi.x - all.lo.x >= all.hi.y - all.lo.y;
    auto low = [&](std::uint32_t i) { return along_x ? boxes[i].lo.x : boxes[i].lo.y; };
    auto high = [&](std::uint32_t i) { return along_x ? boxes[i].hi.x : boxes[i].hi.y; };
    std::vector<std::uint32_t> order(bodies.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return low(a) < low(b) || (low(a) == low(b) && a < b); });

    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t p = 0; p < order.size(); ++p) {
        for (std::size_t q = p + 1; q < order.size() && low(order[q]) <= high(order[p]) + tolerance_m; ++q) {
            const std::uint32_t i = std::min(order[p], order[q]);
            const std::uint32_t j = std::max(order[p], order[q]);
            if (!movable(bodies[i]) && !movable(bodies[j])) continue;
            if (boxes_touch(boxes[i], boxes[j], tolerance_m)) pairs.emplace_back(i, j);
        }
    }
    // The pairs in the order of the bodies (as a pairwise loop gives them): the LP, its
    // mechanism and the printed interfaces do not depend on the sweep.
    std::sort(pairs.begin(), pairs.end());

    std::vector<BlockInterface> out;
    for (auto [i, j] : pairs) {
        const auto& a = bodies[i].vertices_m;
        const auto& b = bodies[j].vertices_m;
        const double mu = model.contact.at(model.contact.id(bodies[i].material), model.contact.id(bodies[j].material)).mu;
        for (std::size_t e = 0; e < a.size(); ++e) {
            for (std::size_t f = 0; f < b.size(); ++f) {
                BlockInterface face{i, j, {}, {}, mu};
                if (common_segment(a[e], a[(e + 1) % a.size()], b[f], b[(f + 1) % b.size()], tolerance_m, face.end_m, face.normal))
                    out.push_back(face);
            }
        }
        // One-point interfaces: a corner of a on an edge of b (normal from a to b: minus b's
        // outward one), a corner of b on an edge of a; both ends at the corner.
        for (auto [p, q, sign] : {std::tuple{&a, &b, -1.0}, std::tuple{&b, &a, 1.0}}) {
            const std::size_t np = p->size(), nq = q->size();
            for (std::size_t v = 0; v < np; ++v) {
                for (std::size_t f = 0; f < nq; ++f) {
                    Vec2 n;
                    if (!corner_on_edge((*p)[(v + np - 1) % np], (*p)[v], (*p)[(v + 1) % np], (*q)[f], (*q)[(f + 1) % nq], tolerance_m, n))
                        continue;
                    out.push_back({i, j, {(*p)[v], (*p)[v]}, sign * n, mu});
                }
            }
        }
    }
    return out;
}

std::vector<InterfaceKinematics> interface_kinematics(const Model& model, const std::vector<BlockInterface>& interfaces,
                                                      const std::vector<BodyMotion>& motions, bool dilation,
                                                      double relative_tolerance) {
    const std::vector<Vec2> centroids = body_centroids_m(model);
    auto velocity_at = [&](std::uint32_t body, Vec2 p) {
        return motions[body].velocity + cross(motions[body].rotation, p - centroids[body]);
    };
    std::vector<InterfaceKinematics> out(interfaces.size());
    double largest_raw = 0.0;
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
        const BlockInterface& f = interfaces[k];
        for (int j = 0; j < 2; ++j) {
            const Vec2 relative = velocity_at(f.body_b, f.end_m[j]) - velocity_at(f.body_a, f.end_m[j]);
            out[k].slip[j] = dot(relative, perp(f.normal));
            out[k].opening[j] = dot(relative, f.normal);
            largest_raw = std::max({largest_raw, std::abs(out[k].slip[j]), std::abs(out[k].opening[j])});
        }
    }
    // A slip below the resolution of the LP's duals (GLPK's tolerances, 1e-7) is none: times a
    // large mu (1e9, or 1e300: a joint that cannot slip) it would be a dilation that swamps every
    // real motion. A real slip there dilates by at most the largest motion, so mu |slip| <= 1e-7 x
    // it needs mu < 1e7 to matter, and then it is below 5 % anyway.
    const double round_off = 1e-7 * largest_raw;
    double largest = 0.0;
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
        for (int j = 0; j < 2; ++j) {
            const double slip = std::abs(out[k].slip[j]);
            if (dilation && slip > round_off) out[k].opening[j] -= interfaces[k].mu * slip;
            largest = std::max({largest, slip, std::abs(out[k].opening[j])});
        }
    }
    const double tolerance = relative_tolerance * largest;
    for (InterfaceKinematics& k : out) {
        const bool open0 = k.opening[0] > tolerance;
        const bool open1 = k.opening[1] > tolerance;
        // A joint that separates at both ends is open, whatever it does along itself.
        if (open0 && open1) k.motion = InterfaceMotion::opens;
        else if (std::abs(k.slip[0]) > tolerance || std::abs(k.slip[1]) > tolerance) k.motion = InterfaceMotion::slides;
        else if (open1) k.motion = InterfaceMotion::hinge_at_end_0;
        else if (open0) k.motion = InterfaceMotion::hinge_at_end_1;
        else k.motion = InterfaceMotion::locked;
    }
    return out;
}

namespace {

// The dynamic bodies' rows (3 each, 1-based; 0 for supports), mass properties and the scales.
struct Rows {
    std::vector<int> first_row;
    std::vector<PolygonProperties> props;
    std::vector<double> mass_kg;
    int equilibrium_rows = 0;
    double weight_scale_N = 0.0;
    double length_scale_m = 0.0;
};

Rows body_rows(const Model& model) {
    const double g = model.settings.gravity_m_s2;
    const std::size_t n = model.bodies.size();
    Rows r{std::vector<int>(n, 0), std::vector<PolygonProperties>(n), std::vector<double>(n, 0.0)};
    for (std::size_t i = 0; i < n; ++i) {
        r.props[i] = polygon_properties(model.bodies[i].vertices_m);
        r.mass_kg[i] = mass_of(model.bodies[i], r.props[i]);
        if (!movable(model.bodies[i])) continue;
        r.first_row[i] = r.equilibrium_rows + 1;
        r.equilibrium_rows += 3;
        r.weight_scale_N = std::max(r.weight_scale_N, r.mass_kg[i] * g);
        r.length_scale_m = std::max(r.length_scale_m, std::sqrt(r.props[i].area_m2));
    }
    return r;
}

// The unknowns at an interface end. Associative friction needs no friction rows: the end's force
// is a non-negative sum of the two edges of its friction cone, n + mu t and n - mu t (Livesley
// 1978), which leaves only the equilibrium rows (3 per body instead of 3 per body plus 4 per
// interface: the simplex's basis is 4 to 5 times smaller on a wall). Non-associative friction
// changes the friction rows into shear capacities, so it keeps n >= 0, a free s and the rows.
enum class Formulation { cone_edges, normal_and_shear };

// The cone's edges n + mu t and n - mu t turn antiparallel as mu grows: a shear is mu (c1 - c2),
// a difference of two columns of order n, so the simplex's tolerances on the columns grow by mu on
// the shears and lambda loses about log10(mu) digits (mu = 1e9: 1e-7 of lambda; 1e10: lambda of
// the wrong sign; 1e300: GLPK's scaling breaks down). Above this mu the LP keeps n, s and friction
// rows, whose coefficients stay within 1 whatever mu (friction_rows_of); up to it the cone's
// smaller basis is kept. Measured on examples/limit/wall_with_window.toml, the two agree to 1e-15
// up to mu = 5, the cone is 3e-7 off at mu = 10 and 6e-5 at mu = 100 (docs/limit_analysis.md).
constexpr double cone_edges_max_mu = 2.0;

Formulation formulation_for(const std::vector<BlockInterface>& faces, FrictionFlow friction) {
    if (friction == FrictionFlow::non_associative) return Formulation::normal_and_shear;
    const bool steep = std::any_of(faces.begin(), faces.end(), [](const BlockInterface& f) { return !(f.mu <= cone_edges_max_mu); });
    return steep ? Formulation::normal_and_shear : Formulation::cone_edges;
}

// |s| <= mu n as two rows, s - mu n <= 0 and -s - mu n <= 0, divided by mu where mu > 1 so that
// their coefficients stay within 1 and a row's tolerance is a force whatever mu; past mu = 1e13
// 1 / mu falls below Triplets' round-off cut and the rows read n >= 0: a joint that cannot slip.
void friction_rows_of(Triplets& m, int first_row, int normal_col, double mu) {
    const double scale = 1.0 / std::max(1.0, mu);
    m.add(first_row, normal_col + 1, scale);
    m.add(first_row, normal_col, -mu * scale);
    m.add(first_row + 1, normal_col + 1, -scale);
    m.add(first_row + 1, normal_col, -mu * scale);
}

// The friction rows of interface k's end j (1-based): the upper face of the cone, then the lower one.
int friction_row(const Rows& rows, std::size_t k, int j) { return rows.equilibrium_rows + static_cast<int>(4 * k) + 2 * j + 1; }

int lambda_column(const std::vector<BlockInterface>& faces) { return static_cast<int>(4 * faces.size()) + 1; }

// Rows, columns, bounds and the matrix of the LP.
void build_problem(GlpkProblem& problem, const Model& model, const std::vector<BlockInterface>& faces, const Rows& rows, Vec2 live,
                   Formulation formulation) {
    const bool cone = formulation == Formulation::cone_edges;
    glp_prob* lp = problem.lp;
    glp_set_obj_dir(lp, GLP_MAX);
    glp_add_rows(lp, rows.equilibrium_rows + (cone ? 0 : static_cast<int>(4 * faces.size())));
    const int lambda = lambda_column(faces);
    glp_add_cols(lp, lambda);
    Triplets m;
    for (std::size_t i = 0; i < model.bodies.size(); ++i) {
        const int r = rows.first_row[i];
        if (!r) continue;
        const double weight = rows.mass_kg[i] * model.settings.gravity_m_s2 / rows.weight_scale_N;
        // interface forces + lambda live = - dead (dead = weight downwards)
        glp_set_row_bnds(lp, r, GLP_FX, 0.0, 0.0);
        glp_set_row_bnds(lp, r + 1, GLP_FX, weight, weight);
        glp_set_row_bnds(lp, r + 2, GLP_FX, 0.0, 0.0);
        m.add(r, lambda, weight * live.x);
        m.add(r + 1, lambda, weight * live.y);
    }
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const BlockInterface& f = faces[k];
        const Vec2 t = perp(f.normal);
        for (int j = 0; j < 2; ++j) {
            const int cn = normal_column(k, j);
            const int cs = cn + 1;
            // Either n and s, or the two edges of the friction cone (n + mu t, n - mu t).
            const Vec2 first = cone ? f.normal + f.mu * t : f.normal;
            const Vec2 second = cone ? f.normal - f.mu * t : t;
            glp_set_col_bnds(lp, cn, GLP_LO, 0.0, 0.0);
            glp_set_col_bnds(lp, cs, cone ? GLP_LO : GLP_FR, 0.0, 0.0);
            // On b: the force at end j; on a: the opposite.
            for (auto [body, sign] : {std::pair{f.body_b, 1.0}, std::pair{f.body_a, -1.0}}) {
                const int r = rows.first_row[body];
                if (!r) continue;
                const Vec2 arm = (1.0 / rows.length_scale_m) * (f.end_m[j] - rows.props[body].centroid_m);
                m.add(r, cn, sign * first.x);
                m.add(r + 1, cn, sign * first.y);
                m.add(r + 2, cn, sign * cross(arm, first));
                m.add(r, cs, sign * second.x);
                m.add(r + 1, cs, sign * second.y);
                m.add(r + 2, cs, sign * cross(arm, second));
            }
            if (cone) continue;
            const int rf = friction_row(rows, k, j);
            glp_set_row_bnds(lp, rf, GLP_UP, 0.0, 0.0);
            glp_set_row_bnds(lp, rf + 1, GLP_UP, 0.0, 0.0);
            friction_rows_of(m, rf, cn, f.mu);
        }
    }
    glp_set_col_bnds(lp, lambda, GLP_FR, 0.0, 0.0);
    glp_set_obj_coef(lp, lambda, 1.0);
    glpk_guarded(problem, [&] { glp_load_matrix(lp, static_cast<int>(m.row.size()) - 1, m.row.data(), m.column.data(), m.value.data()); });
}

// Solves from the current basis (from a fresh one if that fails) and says how it ended.
LimitStatus solve(GlpkProblem& problem) {
    glp_prob* lp = problem.lp;
    glp_smcp parameters;
    glp_init_smcp(&parameters);
    parameters.msg_lev = GLP_MSG_OFF;
    parameters.presolve = GLP_OFF;
    int code = 0;
    glpk_guarded(problem, [&] {
        glp_scale_prob(lp, GLP_SF_AUTO);
        code = glp_simplex(lp, &parameters);
        if (code == 0) return;
        glp_adv_basis(lp, 0);
        code = glp_simplex(lp, &parameters);
    });
    if (code != 0) throw std::runtime_error("limit analysis: the LP solver (GLPK) failed, code " + std::to_string(code));
    const int status = glp_get_status(lp);
    if (status == GLP_NOFEAS || status == GLP_INFEAS) return LimitStatus::no_equilibrium;
    if (status == GLP_UNBND) return LimitStatus::unbounded;
    if (status != GLP_OPT) throw std::runtime_error("limit analysis: GLPK ended without an optimum, status " + std::to_string(status));
    return LimitStatus::collapse;
}

// Non-associative friction: each end's friction becomes a shear capacity c = mu n from the last
// solution (a capacity independent of n: slip without dilation), moved halfway towards the new
// mu n each time, and the LP solved again from its last basis until lambda settles (Gilbert,
// Casapulla and Ahmed 2006). A heuristic: it may stop at a solution that is not the least
// non-associative one (docs/limit_analysis.md).
// Above this mu a joint cannot slip, so the flow rule does not matter there: its friction rows are
// kept as the first (associative) solve had them, within 1 whatever mu (friction_rows_of). As a
// capacity mu n its bound reached 1e13 N and more, and from mu = 1e9 on the wall with a window
// every LP of the iteration read "no equilibrium" (1e8 gave the right 0.6667).
constexpr double non_associative_no_slip_mu = 1.0e6;

LimitStatus iterate_non_associative(GlpkProblem& problem, const std::vector<BlockInterface>& faces, const Rows& rows,
                                    const LimitOptions& options, LimitResult& result) {
    glp_prob* lp = problem.lp;
    auto mu_n = [&](std::size_t k, int j) { return faces[k].mu * std::max(0.0, glp_get_col_prim(lp, normal_column(k, j))); };
    std::vector<double> capacity(2 * faces.size());
    for (std::size_t k = 0; k < faces.size(); ++k)
        for (int j = 0; j < 2; ++j) capacity[2 * k + j] = mu_n(k, j);
    double previous = glp_get_col_prim(lp, lambda_column(faces));
    result.converged = false;
    for (result.iterations = 1; result.iterations <= options.max_iterations; ++result.iterations) {
        for (std::size_t k = 0; k < faces.size(); ++k) {
            if (faces[k].mu > non_associative_no_slip_mu) continue;
            for (int j = 0; j < 2; ++j) {
                const int rf = friction_row(rows, k, j);
                int index[2] = {0, normal_column(k, j) + 1};
                double plus[2] = {0.0, 1.0}, minus[2] = {0.0, -1.0};
                glp_set_mat_row(lp, rf, 1, index, plus);        // s <= c
                glp_set_mat_row(lp, rf + 1, 1, index, minus);   // -s <= c
                // mu n past the largest double (mu = 1e308 on a joint carrying two weights) bounds nothing.
                const double c = capacity[2 * k + j];
                const int bound = std::isfinite(c) ? GLP_UP : GLP_FR;
                glp_set_row_bnds(lp, rf, bound, 0.0, std::isfinite(c) ? c : 0.0);
                glp_set_row_bnds(lp, rf + 1, bound, 0.0, std::isfinite(c) ? c : 0.0);
            }
        }
        const LimitStatus status = solve(problem);
        if (status != LimitStatus::collapse) return status;
        const double lambda = glp_get_col_prim(lp, lambda_column(faces));
        for (std::size_t k = 0; k < faces.size(); ++k)
            for (int j = 0; j < 2; ++j) capacity[2 * k + j] = 0.5 * (capacity[2 * k + j] + mu_n(k, j));
        if (std::abs(lambda - previous) <= options.lambda_tolerance) {
            result.converged = true;
            break;
        }
        previous = lambda;
    }
    result.iterations = std::min(result.iterations, options.max_iterations);
    return LimitStatus::collapse;
}

InterfaceForces forces_of(glp_prob* lp, const BlockInterface& face, std::size_t k, double weight_scale_N, Formulation formulation) {
    InterfaceForces forces;
    for (int j = 0; j < 2; ++j) {
        const double first = glp_get_col_prim(lp, normal_column(k, j));
        const double second = glp_get_col_prim(lp, normal_column(k, j) + 1);
        if (formulation == Formulation::cone_edges) {
            forces.normal_N[j] = std::max(0.0, first + second) * weight_scale_N;
            forces.shear_N[j] = face.mu * (first - second) * weight_scale_N;
        } else {
            forces.normal_N[j] = std::max(0.0, first) * weight_scale_N;
            forces.shear_N[j] = second * weight_scale_N;
        }
    }
    const double total = forces.normal_N[0] + forces.normal_N[1];
    forces.thrust_fraction = total > 0.0 ? forces.normal_N[1] / total : std::numeric_limits<double>::quiet_NaN();
    forces.thrust_point_m = total > 0.0 ? face.end_m[0] + forces.thrust_fraction * (face.end_m[1] - face.end_m[0])
                                        : 0.5 * (face.end_m[0] + face.end_m[1]);
    return forces;
}

// The duals of the equilibrium rows: the virtual motion (a moment row's dual is a rotation times
// the length scale). Scaled so that the fastest point of any body moves at 1, signed so that the
// live load does positive work.
std::vector<BodyMotion> mechanism_of(glp_prob* lp, const Model& model, const Rows& rows, Vec2 live) {
    std::vector<BodyMotion> out(model.bodies.size());
    double live_work = 0.0, fastest = 0.0;
    for (std::size_t i = 0; i < model.bodies.size(); ++i) {
        const int r = rows.first_row[i];
        if (!r) continue;
        BodyMotion& u = out[i];
        u.velocity = {glp_get_row_dual(lp, r), glp_get_row_dual(lp, r + 1)};
        u.rotation = glp_get_row_dual(lp, r + 2) / rows.length_scale_m;
        live_work += rows.mass_kg[i] * dot(live, u.velocity);
        for (Vec2 v : model.bodies[i].vertices_m)
            fastest = std::max(fastest, length(u.velocity + cross(u.rotation, v - rows.props[i].centroid_m)));
    }
    if (fastest > 0.0) {
        const double scale = (live_work < 0.0 ? -1.0 : 1.0) / fastest;
        for (BodyMotion& u : out) {
            u.velocity = scale * u.velocity;
            u.rotation *= scale;
        }
    }
    return out;
}

}  // namespace

LimitResult solve_limit_analysis(const Model& model, const LimitOptions& options) {
    if (!(model.settings.gravity_m_s2 > 0.0)) throw std::invalid_argument("limit analysis needs gravity (the dead load): gravity is 0");
    const double d_length = length(options.live_load_direction);
    if (!(d_length > 0.0)) throw std::invalid_argument("limit analysis needs a live load direction");
    const Vec2 live = (1.0 / d_length) * options.live_load_direction;
    const Rows rows = body_rows(model);
    if (rows.equilibrium_rows == 0) throw std::invalid_argument("limit analysis needs at least one dynamic body");

    LimitResult result;
    const double tolerance_m = options.touch_tolerance_m > 0.0 ? options.touch_tolerance_m : 1e-6 * largest_extent_m(model);
    const auto search_start = std::chrono::steady_clock::now();
    result.interfaces = find_interfaces(model, tolerance_m);
    const auto lp_start = std::chrono::steady_clock::now();
    result.interface_search_s = std::chrono::duration<double>(lp_start - search_start).count();
    const auto& faces = result.interfaces;
    std::vector<bool> touched(model.bodies.size(), false);
    for (const BlockInterface& f : faces) touched[f.body_a] = touched[f.body_b] = true;
    for (std::uint32_t i = 0; i < model.bodies.size(); ++i)
        if (movable(model.bodies[i]) && !touched[i]) result.unsupported.push_back(i);

    const GlpkSilence silence;
    GlpkProblem problem;
    const Formulation formulation = formulation_for(faces, options.friction);
    build_problem(problem, model, faces, rows, live, formulation);
    glpk_guarded(problem, [&] { glp_adv_basis(problem.lp, 0); });
    result.status = solve(problem);
    if (result.status == LimitStatus::collapse && options.friction == FrictionFlow::non_associative)
        result.status = iterate_non_associative(problem, faces, rows, options, result);
    result.lp_solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - lp_start).count();
    if (result.status != LimitStatus::collapse) return result;

    result.lambda = glp_get_col_prim(problem.lp, lambda_column(faces));
    for (std::size_t k = 0; k < faces.size(); ++k) result.forces.push_back(forces_of(problem.lp, faces[k], k, rows.weight_scale_N, formulation));
    result.mechanism = mechanism_of(problem.lp, model, rows, live);
    result.kinematics = interface_kinematics(model, faces, result.mechanism, options.friction == FrictionFlow::associative);
    return result;
}

}  // namespace blockdem
