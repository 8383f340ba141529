#pragma once
// The limit of the highest contact mode of the central-difference scheme, one algorithm for 2-D
// and 3-D (dynamics/critical_time_step.hpp derives the condition): the scheme is stable while
// M - (dt/2) C - (dt^2/4) K stays positive definite, so the limit is the dt at which
// B(dt) = (dt^2/4) K~ + (dt/2) C~ (K~, C~ the mass-normalised stiffness and damping matrices)
// reaches an eigenvalue of 1. Power iteration finds B's top eigenvector at a trial dt; that
// mode's Rayleigh quotients q_k and q_c give the dt at which its own (dt^2/4) q_k + (dt/2) q_c is
// 1; the trial dt is updated and the iteration repeated until it settles.
//
// The Gershgorin row sums (the proven bound) add every coupling with the same sign, so for a
// brick in a wall with six neighbours they are 2 to 3 times below this limit in 2-D, 3.7 to 4 times
// in 3-D (docs/physics.md, docs/3d.md). A Rayleigh quotient
// is never above the top eigenvalue, so an unconverged estimate errs towards a larger dt: the
// result is an estimate, and the proven bound stays the guarantee.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace blockdem {

/// Power iterations per trial dt.
inline constexpr int power_iterations = 60;

struct HighestMode {
    bool found = false;        ///< false: K~ is zero along every direction tried (no estimate)
    double dt_s = 0.0;         ///< [s] the mode's limit
    double omega_rad_s = 0.0;  ///< [rad/s] sqrt(q_k) of the mode
    double h = 0.0;            ///< [-] q_c / (2 omega)
    std::vector<double> mode;  ///< unit vector over the degrees of freedom (mass-normalised)
};

namespace detail {
inline double dot_product(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
    return sum;
}
}  // namespace detail

/// apply(weight_k, weight_c, x, y) sets y = (weight_k K~ + weight_c C~) x over n degrees of
/// freedom; quotients(x) returns x^T K~ x and x^T C~ x (a std::pair); trial_dt_s is the first
/// trial (the proven bound). apply is called at one pair of weights power_iterations times in a
/// row, so that it may prepare for each new pair (dynamics/block_pencil.hpp).
template <class Apply, class Quotients>
HighestMode highest_mode(std::size_t n, double trial_dt_s, Apply&& apply, Quotients&& quotients) {
    HighestMode r;
    // A start vector with a share of every mode: a fixed pseudo-random pattern (the all-ones
    // vector would miss the alternating modes of a regular lattice, the highest ones).
    std::vector<double>& x = r.mode;
    x.resize(n);
    std::vector<double> y(n);
    std::uint64_t state = 0x9e3779b97f4a7c15ull;
    for (double& v : x) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        v = static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
    }
    double dt = trial_dt_s;
    for (int outer = 0; outer < 4; ++outer) {
        for (int k = 0; k < power_iterations; ++k) {
            apply(0.25 * dt * dt, 0.5 * dt, x, y);
            const double norm = std::sqrt(detail::dot_product(y, y));
            if (!(norm > 0.0)) return r;
            for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / norm;
        }
        const auto [qk, qc] = quotients(x);
        if (!(qk > 0.0)) return r;
        const double next = (std::sqrt(qc * qc + 4.0 * qk) - qc) / qk;
        const bool settled = std::abs(next - dt) < 1e-3 * dt;
        dt = next;
        if (settled) break;
    }
    const auto [qk, qc] = quotients(x);
    r.omega_rad_s = std::sqrt(qk);
    r.h = qc / (2.0 * r.omega_rad_s);
    r.dt_s = dt;
    r.found = true;
    return r;
}

/// The same with the quotients made by apply.
template <class Apply>
HighestMode highest_mode(std::size_t n, double trial_dt_s, Apply&& apply) {
    std::vector<double> y(n);
    return highest_mode(n, trial_dt_s, apply, [&](const std::vector<double>& x) {
        apply(1.0, 0.0, x, y);
        const double qk = detail::dot_product(x, y);
        apply(0.0, 1.0, x, y);
        return std::pair<double, double>{qk, detail::dot_product(x, y)};
    });
}

/// A body's own N x N blocks of K~ and C~ (N = 3 in 2-D, 6 in 3-D), the upper triangle row by
/// row: the stiffness and damping it sees with its partners held still. A principal block's top
/// eigenvalue is never above the whole matrix's (Cauchy's interlacing), so a body whose blocks are
/// unstable at dt makes dt unstable for certain in the watch's linear model (every point's springs
/// as if sticking, a joint's stiffness on its two end points), whatever the layout around it.
template <int N>
struct BodyBlocks {
    static constexpr int entries = N * (N + 1) / 2;
    double k[entries] = {};  ///< [1/s^2]
    double c[entries] = {};  ///< [1/s]

    /// Adds k g g^T and c g g^T, g the body's N entries of one direction's g.
    void add(const double* g, double stiffness, double damping) {
        int e = 0;
        for (int r = 0; r < N; ++r)
            for (int col = r; col < N; ++col, ++e) {
                k[e] += stiffness * g[r] * g[col];
                c[e] += damping * g[r] * g[col];
            }
    }

    /// The pivot at which the Cholesky factor of I - (dt^2/4) K - (dt/2) C fails (<= 0: the
    /// blocks are unstable at dt), or 1 when the factor exists.
    double failing_pivot(double dt_s) const {
        double m[N][N];
        int e = 0;
        for (int r = 0; r < N; ++r)
            for (int col = r; col < N; ++col, ++e)
                m[r][col] = m[col][r] = (r == col ? 1.0 : 0.0) - (0.25 * dt_s * dt_s * k[e] + 0.5 * dt_s * c[e]);
        for (int p = 0; p < N; ++p) {
            double pivot = m[p][p];
            for (int q = 0; q < p; ++q) pivot -= m[p][q] * m[p][q];
            if (pivot <= 0.0) return pivot;
            const double root = std::sqrt(pivot);
            m[p][p] = root;
            for (int r = p + 1; r < N; ++r) {
                double v = m[r][p];
                for (int q = 0; q < p; ++q) v -= m[r][q] * m[p][q];
                m[r][p] = v / root;
            }
        }
        return 1.0;
    }

    /// The blocks' own limit, from trial_dt_s.
    HighestMode mode(double trial_dt_s) const {
        return highest_mode(N, trial_dt_s, [&](double wk, double wc, const std::vector<double>& x, std::vector<double>& y) {
            std::fill(y.begin(), y.end(), 0.0);
            int e = 0;
            for (int r = 0; r < N; ++r)
                for (int col = r; col < N; ++col, ++e) {
                    const double v = wk * k[e] + wc * c[e];
                    y[r] += v * x[col];
                    if (col != r) y[col] += v * x[r];
                }
        });
    }
};

/// Of the bodies whose blocks are unstable at dt_s (a failing Cholesky pivot), the one with the
/// least own limit, and that limit: strictly below dt_s, since the failure is certain and the
/// power iteration's estimate errs upwards. found = false when every body's blocks are stable.
template <int N>
std::pair<std::size_t, HighestMode> most_unstable_body(const std::vector<BodyBlocks<N>>& blocks, double dt_s) {
    std::pair<std::size_t, HighestMode> least{0, HighestMode{}};
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        if (!(blocks[b].failing_pivot(dt_s) <= 0.0)) continue;
        HighestMode m = blocks[b].mode(dt_s);
        if (!m.found) continue;
        m.dt_s = std::min(m.dt_s, std::nextafter(dt_s, 0.0));
        if (!least.second.found || m.dt_s < least.second.dt_s) least = {b, std::move(m)};
    }
    return least;
}

/// The ratio of a highest-mode limit to the proven bound of the same points [-], the live watches'
/// scale at the start: 0 (none) where the bound is not finite and above 0 or the limit is not
/// finite (nothing touches, no dynamic body); at least 1 (the estimate never falls below the bound).
inline double start_limit_ratio(double highest_mode_s, double bound_s) {
    const bool known = std::isfinite(highest_mode_s) && std::isfinite(bound_s) && bound_s > 0.0;
    return known ? std::max(1.0, highest_mode_s / bound_s) : 0.0;
}

/// The ratio of the highest mode's limit to the proven bound, as a live watch keeps it (the 2-D and
/// 3-D watches: world/step.cpp, world/run_checks_3d.cpp): the live limit is the live bound times it.
struct LiveLimitRatio {
    double& ratio;            ///< [-] 0: none yet; else at least 1
    double& bound_s;          ///< [s] the proven bound of the contacts it was estimated on
    std::int64_t& estimates;  ///< estimates made on live contacts
};

/// The live limit [s] for the live contacts' proven bound bound_s: the bound times the ratio, which
/// depends on the layout (a block on its base, a stack, a brick among neighbours) much more than on
/// the stiffness. The ratio is estimated afresh on the live contacts (estimate_s: their highest
/// mode's limit) when none is known (3-D: nothing touched at the start) and when the scaled limit
/// falls below dt on a bound 5 % or more below the ratio's own: a body landing on another, a pile
/// forming, is a new layout. Each estimate lowers the ratio's bound by 5 % or more, so there are
/// few; none once dt has been reported above the limit (reported). A ratio from a stiffly coupled
/// layout is kept when the layout goes back to a less coupled one whose bound has not fallen (a
/// stack bouncing apart): the limit is then too high, and the per-body blocks and the energy
/// balance are the checks (docs/physics.md, "The stable time step").
template <class Estimate>
double live_limit_s(LiveLimitRatio r, bool reported, double dt_s, double bound_s, Estimate&& estimate_s) {
    constexpr double re_estimate_fall = 0.95;
    const bool needs_estimate =
        r.ratio == 0.0 || (!reported && dt_s > r.ratio * bound_s && bound_s < re_estimate_fall * r.bound_s);
    if (needs_estimate) {
        r.ratio = std::max(1.0, estimate_s() / bound_s);
        r.bound_s = bound_s;
        ++r.estimates;
    }
    return r.ratio * bound_s;
}

/// The body that moves most in a mode of dofs_per_body entries a body.
inline std::size_t body_moving_most(const std::vector<double>& mode, std::size_t dofs_per_body) {
    std::size_t body = 0;
    double most = -1.0;
    for (std::size_t i = 0; i * dofs_per_body < mode.size(); ++i) {
        double share = 0.0;
        for (std::size_t j = 0; j < dofs_per_body; ++j) share += mode[dofs_per_body * i + j] * mode[dofs_per_body * i + j];
        if (share > most) most = share, body = i;
    }
    return body;
}

}  // namespace blockdem
