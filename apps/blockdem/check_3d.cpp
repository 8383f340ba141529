// `blockdem check` on a 3-D scenario: what the 2-D check prints where it means something in 3-D
// (docs/3d.md, "Checking a scenario"). The world is the one `blockdem run` starts from
// (io/scenario_3d.hpp), its time step set and checked; the start's contacts and the stable bound
// come from the same probe as the run's (world/world_3d_start.hpp), so the bound printed here is
// the run's.
#include "apps/blockdem/check_3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "io/scenario.hpp"
#include "io/scenario_3d.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "laws/restitution.hpp"
#include "world/response_monitor_3d.hpp"
#include "world/world_3d_start.hpp"

namespace blockdem::cli {
namespace {

const char* kind_name(BodyKind3d k) {
    switch (k) {
        case BodyKind3d::dynamic: return "dynamic";
        case BodyKind3d::fixed: return "fixed";
        case BodyKind3d::driven: return "driven";
    }
    return "?";
}

std::string vec(Vec3 v) { return fmt::format("({:.4g}, {:.4g}, {:.4g})", v.x, v.y, v.z); }

void print_bodies(const World3d& w) {
    fmt::print("bodies ({}):\n", w.bodies.size());
    fmt::print("  {:<16} {:<8} {:>12} {:>36} {:>30}\n", "name", "kind", "mass [kg]", "principal moments [kg m^2]",
               "centroid [m]");
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const RigidBody3d& b = w.bodies[i];
        fmt::print("  {:<16} {:<8} {:>12.5g} {:>36} {:>30}\n", b.name, kind_name(w.kinds[i]), b.mass_kg,
                   vec(b.principal_moments_kg_m2), vec(b.position_m));
    }
}

void print_contact(const ContactParameters& p) {
    fmt::print("contact parameters (every pair of bodies):\n");
    fmt::print("  kn = {:.4g} N/m, ks = {:.4g} N/m per point, mu = {:.4g}, h_n = {:.4g} (paper e = {:.4g}, rebound e = "
               "{:.4g}), h_s = {:.4g}, termination = {}\n",
               p.kn_N_m, p.ks_N_m, p.mu, p.h_n, p.h_n < 1.0 ? restitution_paper(p.h_n) : 0.0,
               restitution_of(p.h_n, p.termination), p.h_s, to_string(p.termination));
}

// The dashpots as the 3-D step applies them (world/step_3d.cpp) for the pairs touching at the
// start: the points the stable bound is computed from. A point's springs are kn and ks times its
// stiffness share w (geometry/corner_share_3d.hpp) and its dashpots take the pair's reduced mass M
// in proportion to w, so C_i = w_i 2 h sqrt(M k / W) with W the pair's sum of shares, and the
// pair's dashpots add up to 2 h sqrt(M k W). The first `shown` pairs, then a count; then the
// dynamic bodies that touch nothing.
void print_start_contacts(const World3d& w, std::size_t shown = 20) {
    const std::vector<ContactPoint3d> points = start_contacts_3d(w);
    struct PairSums {
        std::size_t points = 0;
        double mass_kg = 0.0;  ///< [kg] the pair's reduced mass (the points' masses summed)
        double shares = 0.0;   ///< [-] W
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, PairSums> pairs_touching;  // sorted: deterministic
    std::vector<bool> touches(w.bodies.size(), false);
    const std::vector<double> dashpot_masses_kg = point_dashpot_masses_kg(w, points);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const ContactPoint3d& c = points[i];
        PairSums& p = pairs_touching[{c.key.body_a, c.key.body_b}];
        ++p.points;
        p.mass_kg += dashpot_masses_kg[i];
        p.shares += c.stiffness_share;
        touches[c.key.body_a] = touches[c.key.body_b] = true;
    }
    fmt::print("dashpots of the pairs touching at the start (C = 2 h sqrt(M k W) in all, M = the pair's reduced mass, "
               "W its points' stiffness shares summed, each point its share of C):\n");
    std::size_t pairs = 0;
    for (const auto& [pair, sums] : pairs_touching) {
        if (++pairs > shown) continue;
        const DashpotCoefficients c = dashpot_coefficients(w.contact, sums.mass_kg * sums.shares);
        fmt::print("  {} / {}: {} point{}, M = {:.4g} kg; C_n = {:.4g}, C_s = {:.4g} N s/m in all, W = {:.4g}\n",
                   w.bodies[pair.first].name, w.bodies[pair.second].name, sums.points, sums.points == 1 ? "" : "s",
                   sums.mass_kg, c.cn_N_s_m, c.cs_N_s_m, sums.shares);
    }
    if (pairs == 0) fmt::print("  none\n");
    if (pairs > shown) fmt::print("  ... and {} more pairs\n", pairs - shown);
    std::vector<std::string> free;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.kinds[i] == BodyKind3d::dynamic && !touches[i]) free.push_back(w.bodies[i].name);
    if (!free.empty()) {
        // The probe takes three short steps: a body resting on bodies that themselves rest on
        // others (a wall's upper courses) has no point yet, as it has none in the run's bound.
        fmt::print("  no point in the start probe (falling, or resting on bodies that rest on others):");
        for (std::size_t k = 0; k < std::min(free.size(), shown); ++k) fmt::print("{} {}", k == 0 ? "" : ",", free[k]);
        fmt::print("{}\n", free.size() > shown ? fmt::format(" and {} more", free.size() - shown) : "");
    }
}

// The corners of the face a body rests on: the face whose outward normal points most downward.
std::size_t resting_corners(const RigidBody3d& b) {
    std::size_t lowest = 0;
    for (std::size_t f = 1; f < b.shape.faces.size(); ++f)
        if (rotate(b.orientation, b.shape.face_normals[f]).z < rotate(b.orientation, b.shape.face_normals[lowest]).z)
            lowest = f;
    return b.shape.faces[lowest].size();
}

// Per dynamic body: the tilt it overturns at (over the face it rests on, as summary.json judges
// it: world/response_monitor_3d.hpp) and the overlap its own weight makes on that face, m g / (4 kn)
// (a face lying on another carries 4 kn in all, whatever its corners: geometry/corner_share_3d.hpp),
// against its height. The first `shown` bodies, then the extremes.
void print_derived(const World3d& w, std::size_t shown = 20) {
    fmt::print("per dynamic body: overturning tilt over its resting face; static overlap m g / (4 kn), the face's corners "
               "sharing 4 kn (its own weight: a body carrying others sinks more):\n");
    const ResponseMonitor3d monitor(w);
    std::size_t count = 0, least_angle_body = 0, largest_fraction_body = 0;
    double least_angle = INFINITY, largest_fraction = 0.0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        const RigidBody3d& b = w.bodies[i];
        double low = INFINITY, high = -INFINITY;
        for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
            low = std::min(low, world_vertex(b, k).z);
            high = std::max(high, world_vertex(b, k).z);
        }
        const double angle = monitor.bodies()[i].overturning_angle_rad;
        const std::size_t n = resting_corners(b);
        const double overlap_m = b.mass_kg * w.gravity_m_s2 / (4.0 * w.contact.kn_N_m);
        const double fraction = overlap_m / (high - low);
        if (angle < least_angle) {
            least_angle = angle;
            least_angle_body = i;
        }
        if (fraction > largest_fraction) {
            largest_fraction = fraction;
            largest_fraction_body = i;
        }
        if (++count > shown) continue;
        fmt::print("  {}: overturns at a tilt of {:.4g} rad ({:.3g} deg); static overlap {:.3g} m on {} corners = {:.3g} of "
                   "its height {:.4g} m\n",
                   b.name, angle, angle * 180.0 / std::numbers::pi, overlap_m, n, fraction, high - low);
    }
    if (count == 0) fmt::print("  none\n");
    if (count > shown)
        fmt::print("  ... and {} more; least overturning tilt {:.4g} rad ({}), largest overlap {:.3g} of the height ({})\n",
                   count - shown, least_angle, w.bodies[least_angle_body].name, largest_fraction,
                   w.bodies[largest_fraction_body].name);
}

void print_time_step(const LoadedScenario3d& s) {
    const World3d& w = s.world;
    const long long steps = std::llround(s.duration_s / w.dt_s);
    const StartTimeStep3d& start = s.start;
    if (!std::isfinite(s.critical_dt_s)) {
        fmt::print("time step: dt = {:.4g} s; no stable limit at the start: no body rests on another, none can land on a "
                   "fixed or driven body; {} steps\n",
                   w.dt_s, steps);
    } else {
        const CriticalTimeStep3d& limit = start.highest_mode;
        fmt::print("time step: dt = {:.4g} s; stable limit {:.6g} s (dt / limit = {:.3f}); {} steps\n", w.dt_s,
                   s.critical_dt_s, w.dt_s / s.critical_dt_s, steps);
        fmt::print("  (the limit of the highest contact mode at the start{}, mostly body '{}': frequency {:.4g} rad/s, "
                   "damping ratio {:.3g}; proven stable below {:.6g} s; dynamics/critical_time_step_3d.hpp)\n",
                   start.landing_bodies == 0 ? std::string()
                                             : fmt::format(" ({} bod{} touching nothing taken as landing flat on a fixed body)",
                                                           start.landing_bodies, start.landing_bodies == 1 ? "y" : "ies"),
                   w.bodies[limit.body].name, limit.omega_rad_s, limit.h, start.proven.dt_s);
    }
}

void print_motion(const World3d& w, double end_s) {
    auto line = [&](const char* name, const ComponentMotion& m) {
        const MotionSample last = sample(m, end_s);
        fmt::print("  {}: {}; peak {:.4g} m/s^2 ({:.4g} g); at t = {:g} s: velocity {:.4g} m/s, displacement {:.4g} m\n",
                   name, describe(m), peak_acceleration(m), peak_acceleration(m) / standard_gravity_m_s2, end_s,
                   last.velocity_m_s, last.displacement_m);
    };
    fmt::print("table motion:\n");
    line("x", w.table.x);
    line("y", w.table.y);
    line("z", w.table.z);
}

}  // namespace

void check_scenario_3d(toml::table root, const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    const LoadedScenario3d s = load_scenario_3d(std::move(root), file, overrides);
    const World3d& w = s.world;
    fmt::print("scenario {}: valid (3-D)\n", file.string());
    fmt::print("duration {:g} s, gravity {:g} m/s^2 along -z, output every {:g} s\n", s.duration_s, w.gravity_m_s2,
               s.output_interval_s);
    for (const std::string& note : s.assembly_notes) fmt::print("assembly: {}\n", note);
    print_bodies(w);
    print_contact(w.contact);
    print_start_contacts(w);
    print_derived(w);
    print_time_step(s);
    print_motion(w, s.duration_s);
}

}  // namespace blockdem::cli
