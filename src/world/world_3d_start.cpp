#include "world/world_3d_start.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "dynamics/highest_mode.hpp"
#include "world/step_3d.hpp"
#include "world/world.hpp"

namespace blockdem {
namespace {

// [m] the largest distance of a body's vertex from its centroid.
double body_radius_m(const RigidBody3d& b) {
    double r = 0.0;
    for (const Vec3& v : b.shape.vertices_m) r = std::max(r, length(v));
    return r;
}

// The probe's step [s]: a tenth of the shortest single-point period among the dynamic bodies.
double probe_step_s(const World3d& w) {
    double dt = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.kinds[i] == BodyKind3d::dynamic) dt = std::min(dt, 0.1 * std::sqrt(w.bodies[i].mass_kg / w.contact.kn_N_m));
    return dt;
}

}  // namespace

void check_no_initial_overlap_3d(const World3d& w) {
    World3d probe = w;
    probe.dt_s = std::isfinite(probe_step_s(w)) ? probe_step_s(w) : 1e-6;
    step_3d(probe);  // its contacts are those of the positions at t = 0
    for (const ContactPoint3d& c : probe.contacts) {
        const RigidBody3d& a = w.bodies[c.key.body_a];
        const RigidBody3d& b = w.bodies[c.key.body_b];
        if (c.overlap_m > 1e-9 * std::min(body_radius_m(a), body_radius_m(b)))
            throw ModelError(fmt::format("bodies '{}' and '{}' overlap at the start by {:.3g} m at ({:.6g}, {:.6g}, "
                                         "{:.6g}) m",
                                         a.name, b.name, c.overlap_m, c.point_m.x, c.point_m.y, c.point_m.z));
    }
}

namespace {

// The probe's touch tolerance: its bodies are grown about their centroids (the body frame's
// origin) by this fraction, so that faces placed touching, to the placement's round-off, overlap by
// about 1e-9 of the bodies' size and carry their points from the first step. It is the start
// check's own tolerance (an overlap below 1e-9 of the size is accepted as touching, so a gap below
// it counts as touching too); a joint left open on purpose (S3D's 1 mm) stays open.
constexpr double touch_fraction = 1e-9;

void grow_by_touch_tolerance(World3d& w) {
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        for (Vec3& v : w.bodies[i].shape.vertices_m) v = (1.0 + touch_fraction) * v;
        w.box_frames[i].half_lengths_m = (1.0 + touch_fraction) * w.box_frames[i].half_lengths_m;
    }
}

// The world after the probe's three steps (none without a dynamic body), its bodies grown by the
// touch tolerance: without it a tall stack placed touching showed only the points its lowest
// courses had loaded in three steps (examples/3d/brick_wall.toml: 504 points and a bound 12 %
// above the settled wall's, docs/3d.md).
std::optional<World3d> probed(const World3d& w) {
    const double dt = probe_step_s(w);
    if (!std::isfinite(dt)) return std::nullopt;
    World3d probe = w;
    probe.dt_s = dt;
    grow_by_touch_tolerance(probe);
    for (int k = 0; k < 3; ++k) step_3d(probe);
    return probe;
}

}  // namespace

namespace {

// A dynamic body that touches nothing at the start (dropped, thrown) is taken as landing flat on
// its lowest face on a fixed body (a body falling without spin lands as it is turned): points at
// that face's corners, each an equal share of the 4 kn a face lying on another carries (the law's
// turn-angle shares, geometry/corner_share_3d.hpp, for a regular face), the pair's reduced mass the
// body's own. As 2-D's landing (dynamics/critical_time_step.hpp), so that the step for a model with
// falling bodies is one they can land with. It is a guess: a body that tumbles and lands on
// another face may need less (a 0.3 x 0.5 x 0.9 m box: 8.2e-4 s to 1.02e-3 s by face), which the
// live watch reports. None without a fixed or driven body. Returns the number of landing bodies.
std::uint32_t add_landings(const World3d& probe, std::vector<ContactPoint3d>& points) {
    // (points holds the probe's contacts: the bodies they touch do not land.)
    std::uint32_t ground = 0;
    while (ground < probe.bodies.size() && probe.kinds[ground] == BodyKind3d::dynamic) ++ground;
    if (ground == probe.bodies.size()) return 0;
    std::vector<bool> touches(probe.bodies.size(), false);
    for (const ContactPoint3d& c : points) touches[c.key.body_a] = touches[c.key.body_b] = true;
    std::uint32_t landing = 0;
    for (std::uint32_t i = 0; i < probe.bodies.size(); ++i) {
        if (probe.kinds[i] != BodyKind3d::dynamic || touches[i]) continue;
        ++landing;
        const RigidBody3d& b = probe.bodies[i];
        std::size_t lowest = 0;
        for (std::size_t f = 1; f < b.shape.faces.size(); ++f)
            if (rotate(b.orientation, b.shape.face_normals[f]).z < rotate(b.orientation, b.shape.face_normals[lowest]).z)
                lowest = f;
        const std::vector<std::size_t>& corners = b.shape.faces[lowest];
        const bool ground_first = ground < i;
        for (std::uint32_t k = 0; k < corners.size(); ++k) {
            ContactPoint3d c;
            c.key = {std::min(ground, i), std::max(ground, i), k, k};
            c.point_m = world_vertex(b, corners[k]);
            c.normal = ground_first ? Vec3{0, 0, 1} : Vec3{0, 0, -1};  // from a to b
            c.stiffness_share = 4.0 / static_cast<double>(corners.size());
            points.push_back(c);
        }
    }
    return landing;
}

}  // namespace

StartTimeStep3d start_time_step_3d(const World3d& w) {
    const std::optional<World3d> probe = probed(w);
    constexpr double none = std::numeric_limits<double>::infinity();
    if (!probe) return {.proven = {.dt_s = none}, .highest_mode = {.dt_s = none}};
    std::vector<ContactPoint3d> points = probe->contacts;
    StartTimeStep3d s;
    s.landing_bodies = add_landings(*probe, points);
    s.proven = stable_time_step_3d(*probe, points);
    s.highest_mode = highest_mode_time_step_3d(*probe, points, s.proven);
    return s;
}

std::vector<ContactPoint3d> start_contacts_3d(const World3d& w) {
    std::optional<World3d> probe = probed(w);
    return probe ? std::move(probe->contacts) : std::vector<ContactPoint3d>{};
}

void start_live_watch_3d(StabilityWatch3d& watch, const StartTimeStep3d& start) {
    watch.start_bound_s = start.proven.dt_s;
    watch.limit_ratio = start_limit_ratio(start.highest_mode.dt_s, start.proven.dt_s);
    watch.ratio_bound_s = watch.limit_ratio > 0.0 ? start.proven.dt_s : 0.0;
}

StartTimeStep3d set_time_step_3d(World3d& w, std::optional<double> dt_s, double dt_safety, double output_interval_s) {
    const StartTimeStep3d start = start_time_step_3d(w);
    start_live_watch_3d(w.stability, start);
    const CriticalTimeStep3d& limit = start.highest_mode;
    if (dt_s) {
        w.dt_s = *dt_s;
        if (w.dt_s > limit.dt_s)
            throw ModelError(fmt::format("time step dt = {:g} s is above the stable limit {:.4g} s of the highest contact "
                                         "mode at the start (mostly body '{}': frequency {:.4g} rad/s, damping ratio "
                                         "{:.3g}); use dt <= {:.3g} s (every dt <= {:.3g} s is proven stable)",
                                         w.dt_s, limit.dt_s, w.bodies[limit.body].name, limit.omega_rad_s, limit.h,
                                         default_dt_safety * limit.dt_s, start.proven.dt_s));
        return start;
    }
    if (!std::isfinite(limit.dt_s))
        throw ModelError("cannot derive the time step: no body rests on another at the start, and none can land on a "
                         "fixed or driven body; give simulation.dt");
    const double largest_s = dt_safety * limit.dt_s;
    const double steps = std::ceil(output_interval_s / largest_s);
    w.dt_s = steps <= 1e9 ? std::min(largest_s, output_interval_s / steps) : largest_s;
    return start;
}

}  // namespace blockdem
