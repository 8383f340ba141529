#include "world/step.hpp"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "contact/contact_forces.hpp"
#include "contact/narrow_phase.hpp"
#include "geometry/polygon.hpp"
#include "geometry/rounded_contact.hpp"
#include "dynamics/central_difference.hpp"
#include "dynamics/critical_time_step.hpp"
#include "dynamics/highest_mode.hpp"
#include "world/parallel.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {

namespace {

// Corners first to first + count of a body at x turned by r, and their box. With rounded (a
// part, rounding_m > 0), each corner's core offset too (rounded_contact.hpp), from the normals
// as placed: once per body and step, not four times per pair in the narrow phase. (In one loop:
// a second pass over the normals cost as much as the offsets saved.)
// Each vector is held as the two lanes (x, y) of one register (GCC's vector extension, which
// Clang shares; any target). Left to itself GCC paired x and y with shuffles and reloads, and
// scalar code needs a register copy for nearly each operation: about 70 instructions a rounded
// corner either way. The operations are Rotation::apply's, dot's and rounded_corner_offset's,
// lane by lane, so the bits are the same: c x - s y is c x + (-s) y exactly, and
// (v < lo ? v : lo) is std::min(lo, v).
// fixed_count (0: any): the corner count known when compiled, so that the loop is unrolled
// (quadrilaterals, most blocks: no loop counter, no register copies between corners).
template <bool rounded, std::uint32_t fixed_count = 0>
[[gnu::always_inline]] inline Aabb place_corners(Bodies& b, std::uint32_t first, std::uint32_t any_count, Vec2 x,
                                                 const Rotation& r, double rounding_m = 0.0) {
    const std::uint32_t count = fixed_count != 0 ? fixed_count : any_count;
    using Lanes = double __attribute__((vector_size(16)));  // (x, y) of one vector
    const auto lanes = [](Vec2 v) { return Lanes{v.x, v.y}; };
    const auto vec = [](Lanes v) { return Vec2{v[0], v[1]}; };
    const Lanes turn_x{r.c, r.s};   // where the local x axis goes
    const Lanes turn_y{-r.s, r.c};  // where the local y axis goes
    const auto turn = [&](Vec2 v) { return v.x * turn_x + v.y * turn_y; };
    const Lanes position = lanes(x);
    Lanes lo{INFINITY, INFINITY};
    Lanes hi{-INFINITY, -INFINITY};
    Lanes before{};  // the normal of the edge before corner k (for the first corner, the last edge's)
    if constexpr (rounded) before = turn(b.local_normals[first + count - 1]);
    // (Unrolled, the last normal is the first one's before, not turned twice: the stores between
    // keep the compiler from seeing that itself.)
    const Lanes last_normal = before;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const Lanes v = position + turn(b.local_vertices_m[k]);
        b.world_vertices_m[k] = vec(v);
        const bool known = rounded && fixed_count != 0 && k == first + count - 1;
        const Lanes normal = known ? last_normal : turn(b.local_normals[k]);
        b.world_normals[k] = vec(normal);
        if constexpr (rounded) {
            const Lanes product = before * normal;
            b.world_corner_offsets_m[k] = vec((rounding_m / (1.0 + (product[0] + product[1]))) * (before + normal));
            before = normal;
        }
        lo = v < lo ? v : lo;
        hi = hi < v ? v : hi;
    }
    return {vec(lo), vec(hi)};
}

}  // namespace

void update_body_geometry(World& w) {
    Bodies& b = w.bodies;
    const auto n = static_cast<std::ptrdiff_t>(b.size());
    const double rounding_m = w.contact.rounding_m;
    if (rounding_m > 0.0) b.world_corner_offsets_m.resize(b.world_normals.size());
    // Normals are turned with the body rather than recomputed from the corners: no square root.
    // (Rounded or not is decided once, not for every part.)
    const auto place_bodies = [&]<bool rounded>() {
        // (Inlined into the loop by force: with quadrilaterals unrolled, the compiler left it a
        // call per body, which cost as much as the unrolling saved.)
        parallel_for(n, [&](std::ptrdiff_t i) __attribute__((always_inline)) {
            const Rotation r = Rotation::from_angle(b.rotation_rad[i]);
            const Vec2 x = b.position_m[i];
            const std::uint32_t first_part = b.part_begin[i];
            const std::uint32_t parts = b.part_count[i];
            for (std::uint32_t j = first_part; j < first_part + parts; ++j) {
                const std::uint32_t first = b.part_vertex_begin[j];
                const std::uint32_t count = b.part_vertex_count[j];
                b.part_box_m[j] = count == 4 ? place_corners<rounded, 4>(b, first, count, x, r, rounding_m)
                                             : place_corners<rounded>(b, first, count, x, r, rounding_m);
            }
            // A concave body's outline is not one of its parts: placed too, for the outputs.
            if (parts > 1) place_corners<false>(b, b.vertex_begin[i], b.vertex_count[i], x, r);
        });
    };
    if (rounding_m > 0.0)
        place_bodies.operator()<true>();
    else
        place_bodies.operator()<false>();
    b.corner_offsets_rounding_m = rounding_m;
}

bool broad_phase_is_stale(const World& w) {
    const Bodies& b = w.bodies;
    if (b.position_at_rebuild_m.size() != b.size()) return true;
    const double allowed = 0.5 * w.broad_phase_margin_m;
    const auto n = static_cast<std::ptrdiff_t>(b.size());
    const double moved_too_far = deterministic_sum(n, [&](std::ptrdiff_t i) {
        // Largest motion of any point of the body since the rebuild: translation + r |rotation|.
        const Vec2 d = b.position_m[i] - b.position_at_rebuild_m[i];
        const double moved = std::sqrt(dot(d, d)) +
                             b.bounding_radius_m[i] * std::abs(b.rotation_rad[i] - b.rotation_at_rebuild_rad[i]);
        return moved > allowed ? 1.0 : 0.0;
    });
    return moved_too_far > 0.0;
}

void rebuild_candidate_pairs(World& w) {
    Bodies& b = w.bodies;
    const double pad = 0.5 * w.broad_phase_margin_m;
    const auto parts = static_cast<std::ptrdiff_t>(b.part_total());
    w.boxes.resize(b.part_total());
    parallel_for(parts, [&](std::ptrdiff_t j) {
        w.boxes[j] = {b.part_box_m[j].lo - Vec2{pad, pad}, b.part_box_m[j].hi + Vec2{pad, pad}};
    });
    // Part ids are body ids while every body is convex; else the parts of one body are never
    // a candidate pair (they move as one).
    const bool all_convex = b.part_total() == b.size();
    if (!all_convex) {
        w.part_is_static.resize(b.part_total());
        for (std::size_t j = 0; j < b.part_total(); ++j) w.part_is_static[j] = b.is_static[b.part_body[j]];
    }
    w.broad_phase.find_pairs(w.boxes, all_convex ? b.is_static : w.part_is_static, w.candidate_pairs);
    if (!all_convex)
        std::erase_if(w.candidate_pairs, [&](const BodyPair& p) { return b.part_body[p.first] == b.part_body[p.second]; });
    take_out_bodies_outside_domain(w);  // before the merge: a taken-out body's contacts are dropped
    merge_candidate_pairs(w.contacts, w.candidate_pairs, b.part_body, w.contacts_scratch);
    if (w.contact.sub_contacts > 2) {  // (the merge left the old table in contacts_scratch)
        w.sub_contacts_scratch.swap(w.sub_contacts);
        carry_sub_contacts(w.contacts_scratch, w.sub_contacts_scratch, w.contacts, w.sub_contacts);
    }
    index_pairs_by_body(w);
    b.position_at_rebuild_m = b.position_m;
    b.rotation_at_rebuild_rad = b.rotation_rad;
    ++w.broad_phase_rebuilds;
}

namespace {

void watch_overlap(World& w, const ContactEnergy& contacts) {
    StabilityWatch& watch = w.stability;
    if (!(contacts.deepest_overlap_ratio > watch.max_overlap_ratio)) return;
    const PairContact& pair = w.contacts[contacts.deepest_pair];
    double deepest_m = 0.0;
    for (std::uint32_t k = 0; k < pair.count; ++k) deepest_m = std::max(deepest_m, pair.points[k].overlap_m);
    watch.max_overlap_ratio = contacts.deepest_overlap_ratio;
    watch.max_overlap_time_s = w.time_s;
    watch.max_overlap_pair_a = pair.a;
    watch.max_overlap_pair_b = pair.b;
    watch.max_overlap_m = deepest_m;
    // (A per-length joint's point stiffness, JKN L t, is what the overlap answers to.)
    const ContactParameters& p = w.contact.at(w.bodies.material[pair.a], w.bodies.material[pair.b]);
    watch.max_overlap_kn_N_m =
        p.stiffness == StiffnessBasis::per_length ? joint_point_of(w.bodies, pair, p, w.contact.rounding_m).kn_N_m : p.kn_N_m;
}

// Every this many steps the stable limit of the live contacts is evaluated (about 1% of a
// step's cost spread over them; a contact configuration lasts far longer than 32 steps).
constexpr std::int64_t live_limit_every = 32;
// Every this many looks the bodies' own blocks are tested too.
constexpr std::int64_t own_blocks_every = 4;

void watch_live_time_step(World& w) {
    if (w.step_index % live_limit_every != 0) return;
    const CriticalTimeStep bound = live_time_step(w, w.stability_rows);
    if (!std::isfinite(bound.dt_s)) return;  // (no dynamic body carries a point)
    StabilityWatch& watch = w.stability;
    // The Gershgorin bound times the ratio of the highest mode's limit to it (1.27 for a block on
    // its base, 2.07 for two blocks stacked, 2 to 3 for a brick in a wall), estimated again on a
    // new layout (dynamics/highest_mode.hpp, live_limit_s).
    double limit_s = live_limit_s({watch.limit_ratio, watch.ratio_bound_s, watch.estimates}, watch.first_exceeded_s >= 0.0,
                                  w.dt_s, bound.dt_s, [&] { return live_highest_mode_time_step(w, bound).dt_s; });
    std::string body = bound.body;
    // One ratio for the whole model can miss a body whose own layout has a smaller one; a body
    // whose own blocks are unstable at dt is above the limit for certain (as in 3-D,
    // world/run_checks_3d.cpp). Every fourth look: it costs about as much as the bound.
    if (w.step_index % (own_blocks_every * live_limit_every) == 0) {
        const CriticalTimeStep own = body_block_limit(w, w.dt_s);
        if (own.dt_s < limit_s) limit_s = own.dt_s, body = own.body;
    }
    if (limit_s < watch.least_limit_s) {
        watch.least_limit_s = limit_s;
        watch.least_limit_body = body;
        watch.least_limit_time_s = w.time_s;
    }
    if (w.dt_s > limit_s && watch.first_exceeded_s < 0.0) {
        watch.first_exceeded_s = w.time_s;
        watch.exceeded_body = body;
    }
}

}  // namespace

void update_contacts_and_forces(World& w) {
    prepare_pair_forces(w);
    // Pair by pair, the narrow phase and then the law: a pair's data is read once per step
    // (the table is larger than the caches from about 1e5 blocks). Each pair writes only its
    // own entry and slot, and the ledger is summed in fixed chunks (parallel.hpp, rules 1, 3).
    const auto pairs = static_cast<std::ptrdiff_t>(w.contacts.size());
    ContactEnergy contacts;
    if (w.bodies.part_total() == w.bodies.size()) {
        // Every body convex: a pair's own points are its body pair's, known once its narrow
        // phase is done. (A world of joints only takes the joint law's own path: same results,
        // fewer instructions.)
        contacts = update_convex_contacts_and_forces(w);
    } else {
        // Concave bodies: the law needs the points of all the body pair's part pairs, so the
        // narrow phase runs over the whole table first, then the points are counted.
        w.opened_scratch.resize(w.contacts.size());
        parallel_for(pairs, [&](std::ptrdiff_t p) { w.opened_scratch[p] = update_pair_contact(w, static_cast<std::size_t>(p)); });
        count_body_pair_points(w);
        contacts = deterministic_sum(pairs, [&](std::ptrdiff_t p) {
            return apply_pair_law(w, static_cast<std::size_t>(p), w.body_pair_points[p], w.opened_scratch[p]);
        });
    }
    w.energy.normal_dashpot_j += contacts.normal_dashpot_j;
    w.energy.shear_dashpot_j += contacts.shear_dashpot_j;
    w.energy.friction_j += contacts.friction_j;
    w.energy.bond_breakage_j += contacts.bond_breakage_j;
    w.energy.elastic_j = contacts.elastic_j;
    watch_overlap(w, contacts);
}

namespace {

// The bodies' terms of the ledger, and how many bodies have a state that is not finite.
struct BodyEnergy {
    double kinetic_j = 0.0;        ///< [J]
    double gravitational_j = 0.0;  ///< [J]
    double non_finite = 0.0;       ///< bodies whose position, rotation or velocity is not finite
    Vec2 mass_moment_kg_m;         ///< [kg m] sum of m x: what a turning gravity works on
    Vec2 momentum_kg_m_s;          ///< [kg m/s] sum of m v at t
    BodyEnergy& operator+=(const BodyEnergy& o) {
        kinetic_j += o.kinetic_j;
        gravitational_j += o.gravitational_j;
        non_finite += o.non_finite;
        mass_moment_kg_m += o.mass_moment_kg_m;
        momentum_kg_m_s += o.momentum_kg_m_s;
        return *this;
    }
};

bool state_is_finite(const Bodies& b, std::size_t i) {
    return std::isfinite(b.position_m[i].x) && std::isfinite(b.position_m[i].y) && std::isfinite(b.rotation_rad[i]) &&
           std::isfinite(b.velocity_m_s[i].x) && std::isfinite(b.velocity_m_s[i].y);
}

// Body i's terms of the ledger at t (its velocity at t must be up to date).
// Gravitational energy is -m g . x (m g y for gravity in -y, written so that it is the same
// number to the last bit).
BodyEnergy body_energy_terms(const Bodies& b, std::size_t i, Vec2 g) {
    BodyEnergy e;
    e.non_finite = state_is_finite(b, i) ? 0.0 : 1.0;
    if (b.kind[i] != BodyKind::dynamic || b.is_static[i]) return e;  // (taken out: its energy is in removed_j)
    const Vec2 v = b.velocity_at_t_m_s[i];
    const double omega = b.angular_velocity_at_t_rad_s[i];
    e.kinetic_j = 0.5 * b.mass_kg[i] * dot(v, v) + 0.5 * b.inertia_kg_m2[i] * omega * omega;
    e.gravitational_j = -(b.mass_kg[i] * g.x) * b.position_m[i].x - (b.mass_kg[i] * g.y) * b.position_m[i].y;
    e.mass_moment_kg_m = b.mass_kg[i] * b.position_m[i];
    e.momentum_kg_m_s = b.mass_kg[i] * v;
    return e;
}

BodyEnergy body_energy(const World& w) {
    const Vec2 g = w.gravity_now_m_s2;
    return deterministic_sum(static_cast<std::ptrdiff_t>(w.bodies.size()), [&](std::ptrdiff_t i) {
        return body_energy_terms(w.bodies, static_cast<std::size_t>(i), g);
    });
}

// A gravity that turns (a tilting table) changes the potential -m g . x without moving a body:
// over the step that ends at t the field does the work -(g(t) - g(t - dt)) . sum(m x) on the
// bodies, with sum(m x) taken mid-step, sum(m x)(t) - dt/2 sum(m v)(t) (second order, as the
// scheme). Nothing before t = 0 counts: the ledger starts there.
void add_tilt_work(World& w, const BodyEnergy& bodies) {
    if (w.settings.tilt_rate_rad_s == 0.0 || w.step_index == 0) return;
    const Vec2 gravity_change = w.gravity_now_m_s2 - gravity_at(w.settings, w.time_s - w.dt_s);
    w.energy.tilt_work_j -= dot(gravity_change, bodies.mass_moment_kg_m - 0.5 * w.dt_s * bodies.momentum_kg_m_s);
}

void store_body_energy(World& w, const BodyEnergy& bodies) {
    w.energy.kinetic_j = bodies.kinetic_j;
    w.energy.gravitational_j = bodies.gravitational_j;
    w.energy.peak_scale_j = std::max(w.energy.peak_scale_j, w.energy.current_scale_j());
}

}  // namespace

bool update_bodies(World& w) {
    set_driven_velocities(w);
    w.gravity_now_m_s2 = gravity_at(w.settings, w.time_s);
    const Vec2 g = w.gravity_now_m_s2;
    const bool starting = !w.velocities_staggered;
    const bool external = w.external_loads.any();
    // Body by body: its force sum, its velocity, its energy terms, while its data is at hand
    // (parallel.hpp, rules 1 to 3; the same arithmetic as the three separate passes).
    const BodyEnergy bodies = deterministic_sum(static_cast<std::ptrdiff_t>(w.bodies.size()), [&](std::ptrdiff_t p) {
        const auto i = static_cast<std::size_t>(p);
        sum_body_force(w, i);
        if (external) add_external_load(w, i);
        update_body_velocity(w.bodies, i, w.dt_s, starting);
        return body_energy_terms(w.bodies, i, g);
    });
    w.velocities_staggered = true;
    add_tilt_work(w, bodies);
    store_body_energy(w, bodies);
    return bodies.non_finite == 0.0;
}

void initialise_energy(World& w) {
    w.gravity_now_m_s2 = gravity_at(w.settings, w.time_s);
    w.energy.elastic_j = contact_elastic_energy(w);
    store_body_energy(w, body_energy(w));
    w.energy.initial_j = w.energy.stored_j();
    w.energy.initial_gravitational_j = w.energy.gravitational_j;
    w.energy.peak_scale_j = 0.0;
}

namespace {

// ", X s for the contacts of body B at t = T" when the live contacts' limit fell below dt.
std::string live_limit_note(const World& w) {
    const StabilityWatch& watch = w.stability;
    if (watch.first_exceeded_s < 0.0) return "";
    return fmt::format(", {:.4g} s for the contacts body '{}' had at t = {:.6g} s", watch.least_limit_s,
                       watch.least_limit_body, watch.least_limit_time_s);
}

}  // namespace

void check_stability(const World& w, bool state_finite) {
    const Bodies& b = w.bodies;
    if (!state_finite) {
        std::size_t i = 0;
        while (i + 1 < b.size() && state_is_finite(b, i)) ++i;
        throw SimulationError(fmt::format("unstable: the state of body '{}' is not finite at t = {:.6g} s (step {}); "
                                          "reduce dt (now {:g} s; stable limit {:.4g} s at the start{})",
                                          b.name[i], w.time_s, w.step_index, w.dt_s, w.critical_dt_s, live_limit_note(w)));
    }
    const StabilityWatch& watch = w.stability;
    if (watch.max_overlap_ratio > w.settings.max_overlap_ratio) {
        // A linear spring's overlap falls as 1/kn under a steady load and as 1/sqrt(kn) in an
        // impact; the suggestion takes the impact rule, so it brings the overlap to 1% either way.
        const double ratio = watch.max_overlap_ratio;
        const double raise = (ratio / overlap_warning_ratio) * (ratio / overlap_warning_ratio);
        // (kn is read in the unit of the pair's stiffness basis: a joint's JKN in Pa/m, whose
        // point stiffness JKN L t the overlap answered to.)
        const ContactParameters& p =
            w.contact.at(b.material[watch.max_overlap_pair_a], b.material[watch.max_overlap_pair_b]);
        const std::string kn_advice =
            p.stiffness == StiffnessBasis::per_length
                ? fmt::format("raise kn (now {:.4g} Pa/m per unit joint area, {:.4g} N/m at this point) to about {:.3g} Pa/m",
                              p.kn_pa_m, watch.max_overlap_kn_N_m, p.kn_pa_m * raise)
                : fmt::format("raise kn (now {:.4g} N/m) to about {:.3g} N/m", watch.max_overlap_kn_N_m,
                              watch.max_overlap_kn_N_m * raise);
        throw SimulationError(fmt::format(
            "penetration: bodies '{}' and '{}' overlap by {:.4g} m at t = {:.6g} s (step {}), {:.3g} of the least width "
            "of the thinner body; the limit is {:g} (simulation.max_overlap). The contact is too soft for its load: "
            "{} for an overlap near 1%",
            b.name[watch.max_overlap_pair_a], b.name[watch.max_overlap_pair_b], watch.max_overlap_m, w.time_s,
            w.step_index, ratio, w.settings.max_overlap_ratio, kn_advice));
    }
    const double error = w.energy.balance_error();
    // (The first steps are skipped: every term is still near zero and their ratio means little.)
    // (Written so that a nan error, a ledger that took an infinite energy, stops the run too.)
    if (w.step_index > 10 && w.energy.scale_j() > 1e-9 && !(error <= w.settings.max_energy_error)) {
        const std::string culprit = unstable_body_clause(
            w.domain.left, b.size(), [&](std::size_t i) { return b.mass_kg[i]; }, [&](std::size_t i) { return b.name[i]; },
            [&](std::size_t i) { return length(b.velocity_m_s[i]); });
        throw SimulationError(fmt::format(
            "unstable: energy balance error {:.3g} (of the largest term, {:.4g} J) exceeds {:g} at t = {:.6g} s "
            "(step {}); {}; reduce dt (now {:g} s; stable limit {:.4g} s at the start{})",
            error, w.energy.scale_j(), w.settings.max_energy_error, w.time_s, w.step_index, culprit, w.dt_s,
            w.critical_dt_s, live_limit_note(w)));
    }
}

namespace {

// Adds the time since the last lap to one phase of w.timings; reads no clock when disabled.
class PhaseClock {
public:
    explicit PhaseClock(StepTimings& t) : timings_(t) {
        if (timings_.enabled) last_ = std::chrono::steady_clock::now();
    }
    void lap(double StepTimings::*phase) {
        if (!timings_.enabled) return;
        const auto now = std::chrono::steady_clock::now();
        timings_.*phase += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    StepTimings& timings_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace

void step_begin(World& w) {
    PhaseClock clock(w.timings);
    update_body_geometry(w);
    clock.lap(&StepTimings::geometry_s);
    if (broad_phase_is_stale(w)) rebuild_candidate_pairs(w);
    clock.lap(&StepTimings::broad_phase_s);
    update_contacts_and_forces(w);
    clock.lap(&StepTimings::contacts_s);
    const bool finite = update_bodies(w);
    watch_live_time_step(w);
    check_stability(w, finite);
    clock.lap(&StepTimings::bodies_s);
}

void step_end(World& w) {
    PhaseClock clock(w.timings);
    if (w.external_loads.any()) w.energy.external_work_j += external_load_work(w);
    w.energy.table_work_j += update_positions(w);
    w.time_s += w.dt_s;
    ++w.step_index;
    clock.lap(&StepTimings::positions_s);
}

}  // namespace blockdem
