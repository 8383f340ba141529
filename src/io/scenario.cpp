#include "io/scenario.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "contact/sub_contacts.hpp"
#include "geometry/outline.hpp"
#include "geometry/polygon.hpp"
#include "io/assembly_keys.hpp"
#include "io/geometry_keys.hpp"
#include "io/motion_sampling.hpp"
#include "io/outcome_keys.hpp"
#include "io/overrides.hpp"
#include "io/record_motion_keys.hpp"
#include "io/scenario_3d.hpp"
#include "io/scenario_folder.hpp"
#include "io/scenario_keys.hpp"
#include "io/series_motion_keys.hpp"
#include "io/time_series_csv.hpp"
#include "laws/material_stiffness.hpp"
#include "laws/restitution.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;

// gravity = g (a magnitude [m/s^2], acting in -y) or [gx, gy] [m/s^2]; tilt_deg turns it as a
// table tilted counter-clockwise (+x end raised) would, tilt_rate_deg_s from t = 0 on.
void read_gravity(TableReader& t, SimulationSettings& s) {
    double vector_tilt_rad = 0.0;
    if (t.has("gravity") && t.raw()["gravity"].is_array()) {
        const Vec2 g = *t.optional_vec2("gravity");
        s.gravity_m_s2 = length(g);
        if (!std::isfinite(s.gravity_m_s2)) t.fail("gravity", "the vector's magnitude overflows; give it in m/s^2");
        if (s.gravity_m_s2 > 0.0) vector_tilt_rad = std::atan2(-g.x, -g.y);
    } else {
        s.gravity_m_s2 = t.number_or("gravity", s.gravity_m_s2);
        if (s.gravity_m_s2 < 0.0)
            t.fail("gravity", "is a magnitude [m/s^2] acting in -y and must be >= 0 (or give a vector [gx, gy])");
    }
    const double tilt_deg = t.number_or("tilt_deg", 0.0);
    if (std::abs(tilt_deg) > 90.0) t.fail("tilt_deg", fmt::format("must lie in [-90, 90] degrees, got {}", tilt_deg));
    const double rate_deg_s = t.number_or("tilt_rate_deg_s", 0.0);
    const double end_deg = tilt_deg + rate_deg_s * s.duration_s;
    if (std::abs(end_deg) > 90.0)
        t.fail("tilt_rate_deg_s", fmt::format("takes the tilt from {} to {:.4g} degrees by the end of the run (duration {} s); "
                                              "it must stay within [-90, 90]",
                                              tilt_deg, end_deg, s.duration_s));
    s.tilt_rad = vector_tilt_rad + tilt_deg * pi / 180.0;
    s.tilt_rate_rad_s = rate_deg_s * pi / 180.0;
}

}  // namespace

// (Shared with the 3-D reader: io/scenario_keys.hpp.)
void read_run_keys(TableReader& t, SimulationSettings& s) {
    s.duration_s = t.positive("duration");
    s.dt_s = t.optional_positive("dt");
    s.dt_safety = t.optional_positive("dt_safety").value_or(s.dt_safety);
    if (s.dt_safety > 1.0) t.fail("dt_safety", fmt::format("must be <= 1 (a fraction of the stable limit), got {}", s.dt_safety));
    s.output_interval_s = t.optional_positive("output_interval").value_or(s.output_interval_s);
    s.max_energy_error = t.optional_positive("max_energy_error").value_or(s.max_energy_error);
    s.max_overlap_ratio = t.optional_positive("max_overlap").value_or(s.max_overlap_ratio);
    if (s.max_overlap_ratio > 1.0)
        t.fail("max_overlap", fmt::format("is a fraction of the thinner body's least width and must be <= 1, got {}",
                                          s.max_overlap_ratio));
}

namespace {

SimulationSettings read_settings(TableReader t) {
    SimulationSettings s;
    read_run_keys(t, s);
    read_gravity(t, s);
    s.domain = read_domain(t);
    t.allow({"initial_state"});  // a state file: read by load_scenario (io, not physics)
    t.reject_unknown_keys();
    return s;
}

// Contact parameters from t, starting from base (the defaults of [contact] for a pair).
// require: mu, and kn and ks when require_stiffness (the [contact] table without a material).
// Damping: h_n directly, or e with e_meaning = "paper" (default) or "rebound"; termination =
// "no_tension" (default) or "zero_overlap" (laws/contact_parameters.hpp).
// base_meaning: the e_meaning a pair inherits from [contact].
// The joint keys (laws/mohr_coulomb_joint.hpp): strengths per unit area of joint, so only
// with stiffness = "per_length"; a table that switches to per-point drops the inherited ones.
void read_joint_keys(TableReader& t, ContactParameters& p) {
    const char* keys[] = {"cohesion", "tensile_strength", "residual_mu", "dilation_deg", "dilation_zero_slip"};
    if (p.stiffness == StiffnessBasis::per_point) {
        p.cohesion_pa = p.tensile_strength_pa = 0.0;
        p.residual_mu = -1.0;
        p.tan_dilation = 0.0;
        p.dilation_zero_slip_m = 0.0;
        for (const char* key : keys)
            if (t.has(key))
                t.fail(key, fmt::format("is a joint property and needs per-length stiffness, but per-point is set here "
                                        "(kn, ks in N/m): set stiffness = \"per_length\" and give kn, ks in Pa/m "
                                        "(docs/scenario.md, [contact])"));
        return;
    }
    for (auto [key, field] : {std::pair{"cohesion", &p.cohesion_pa}, std::pair{"tensile_strength", &p.tensile_strength_pa}})
        if (auto value = t.optional_number(key)) {
            if (!(*value >= 0.0)) t.fail(key, fmt::format("is a strength [Pa] and must be >= 0, got {}", *value));
            *field = *value;
        }
    if (auto residual = t.optional_number("residual_mu")) {
        if (!(*residual >= 0.0)) t.fail("residual_mu", fmt::format("must be >= 0, got {}", *residual));
        p.residual_mu = *residual;
    }
    if (p.residual_mu > p.mu)
        t.fail(t.has("residual_mu") ? "residual_mu" : "mu",
               fmt::format("the residual friction residual_mu = {} is above the peak friction mu = {}: a joint cannot "
                           "be stronger once broken",
                           p.residual_mu, p.mu));
    if (auto dilation = t.optional_number("dilation_deg")) {
        if (!(*dilation >= 0.0 && *dilation < 45.0))
            t.fail("dilation_deg", fmt::format("is the joint's dilation angle and must lie in [0, 45) degrees, got {}",
                                               *dilation));
        p.tan_dilation = std::tan(*dilation * pi / 180.0);
    }
    if (auto zero_slip = t.optional_number("dilation_zero_slip")) {
        if (!(*zero_slip >= 0.0))
            t.fail("dilation_zero_slip", fmt::format("is the dilatant slip [m] after which a joint stops dilating and "
                                                     "must be >= 0 (0: no limit), got {}",
                                                     *zero_slip));
        p.dilation_zero_slip_m = *zero_slip;
    }
    // (The friction that bounds it is the one the sliding point has: the residual one once broken.)
    if (p.tan_dilation > residual_friction(p) * (1.0 + 1e-12))
        t.fail(t.has("dilation_deg") ? "dilation_deg" : "mu",
               fmt::format("the dilation angle {:.6g} deg is above the joint's friction angle {:.6g} deg: a joint "
                           "cannot dilate more than associative friction",
                           std::atan(p.tan_dilation) * 180.0 / pi, std::atan(residual_friction(p)) * 180.0 / pi));
}

}  // namespace

// (Shared with the 3-D reader: io/scenario_keys.hpp.)
ContactParameters read_contact_parameters(TableReader& t, const ContactParameters& base, bool require_mu,
                                          bool require_stiffness, const std::string& base_meaning) {
    ContactParameters p = base;
    const std::string basis = t.choice("stiffness", {"per_point", "per_length"}, to_string(base.stiffness));
    p.stiffness = basis == "per_length" ? StiffnessBasis::per_length : StiffnessBasis::per_point;
    // kn and ks in the table's own basis: a table that changes the basis it inherits must give
    // both (a number in N/m read as Pa/m, or the reverse, would be off by the joint's area).
    if (p.stiffness != base.stiffness && !require_stiffness && !(t.has("kn") && t.has("ks")))
        t.fail("stiffness", fmt::format("{} stiffness given where {} is set in [contact]: give this table's own kn and ks "
                                        "in {}",
                                        p.stiffness == StiffnessBasis::per_length ? "per-length" : "per-point",
                                        base.stiffness == StiffnessBasis::per_length ? "per-length" : "per-point",
                                        p.stiffness == StiffnessBasis::per_length ? "Pa/m" : "N/m"));
    auto stiffness = [&](const char* key, double fallback) {
        return require_stiffness ? t.positive(key) : t.optional_positive(key).value_or(fallback);
    };
    if (p.stiffness == StiffnessBasis::per_length) {
        p.kn_pa_m = stiffness("kn", base.kn_pa_m);
        p.ks_pa_m = stiffness("ks", base.ks_pa_m);
    } else {
        p.kn_N_m = stiffness("kn", base.kn_N_m);
        p.ks_N_m = stiffness("ks", base.ks_N_m);
    }
    const auto mu = t.optional_number("mu");
    const auto friction_deg = t.optional_number("friction_deg");
    if (mu && friction_deg) t.fail("friction_deg", "give either mu or friction_deg (mu = tan(friction_deg)), not both");
    if (mu) {
        if (*mu < 0.0) t.fail("mu", fmt::format("must be >= 0, got {}", *mu));
        p.mu = *mu;
    } else if (friction_deg) {
        if (!(*friction_deg >= 0.0 && *friction_deg < 90.0))
            t.fail("friction_deg", fmt::format("must lie in [0, 90) degrees, got {}", *friction_deg));
        p.mu = std::tan(*friction_deg * pi / 180.0);
    } else if (require_mu) {
        t.fail_missing("mu");
    }
    read_joint_keys(t, p);
    // (Read before e: the rebound meaning of e depends on when the contact ends.)
    const std::string termination = t.choice("termination", {"no_tension", "zero_overlap"}, to_string(base.termination));
    p.termination = termination == "zero_overlap" ? ContactTermination::zero_overlap : ContactTermination::no_tension;
    const auto e = t.optional_number("e");
    const auto h_n = t.optional_number("h_n");
    const std::string meaning = t.choice("e_meaning", {"paper", "rebound"}, base_meaning);
    if (e && h_n) t.fail("h_n", "give either e (coefficient of restitution) or h_n (damping ratio), not both");
    if (e) {
        if (!(*e > 0.0 && *e <= 1.0)) t.fail("e", fmt::format("must be in (0, 1], got {}", *e));
        p.h_n = damping_ratio_for(*e, meaning == "paper" ? RestitutionMeaning::paper : RestitutionMeaning::rebound,
                                  p.termination);
    } else if (h_n) {
        if (*h_n < 0.0 || (meaning == "paper" && *h_n >= 1.0)) t.fail("h_n", fmt::format("must be in [0, 1), got {}", *h_n));
        p.h_n = *h_n;
    }
    if (auto h_s = t.optional_number("h_s")) {
        if (*h_s < 0.0) t.fail("h_s", fmt::format("must be >= 0, got {}", *h_s));
        p.h_s = *h_s;
    }
    return p;
}

namespace {

// young_modulus and poisson_ratio of one table ([contact] or [contact.materials.NAME]), each
// falling back to base; nullopt when the table gives neither and there is no base.
std::optional<ElasticMaterial> read_elastic_material(TableReader& t, const std::optional<ElasticMaterial>& base) {
    const auto young = t.optional_number("young_modulus");
    const auto poisson = t.optional_number("poisson_ratio");
    if (!young && !base) {
        if (poisson) t.fail("poisson_ratio", "needs young_modulus [Pa]: it sets ks from the material's Young's modulus");
        return std::nullopt;
    }
    ElasticMaterial m = base.value_or(ElasticMaterial{});
    if (young) {
        if (!(*young > 0.0)) t.fail("young_modulus", fmt::format("must be > 0 [Pa], got {}", *young));
        m.young_modulus_pa = *young;
    }
    if (poisson) {
        if (!(*poisson > -1.0 && *poisson < 0.5))
            t.fail("poisson_ratio", fmt::format("must be in (-1, 0.5) (a stable isotropic material), got {}", *poisson));
        m.poisson_ratio = *poisson;
    }
    return m;
}

// [contact]'s stiffness: a material (young_modulus, the rule derives kn and ks) or explicit kn
// and ks, never both in one table (which would win is not obvious).
std::optional<ElasticMaterial> read_default_material(TableReader& t) {
    const auto material = read_elastic_material(t, std::nullopt);
    // One rule so far; the key lets a scenario name the rule it was made with.
    t.choice("stiffness_rule", {"block_deformability"}, "block_deformability");
    if (material) {
        for (const char* key : {"kn", "ks"})
            if (t.has(key))
                t.fail(key, fmt::format("give either young_modulus (kn and ks derived from the material and the block "
                                        "size, docs/physics.md) or explicit kn and ks, not both; to override the "
                                        "derived {} for one pair of materials, give it in [[contact.pairs]]", key));
    } else if (t.raw().contains("stiffness_rule")) {
        t.fail("stiffness_rule", "needs young_modulus [Pa]: the rule derives kn and ks from the material");
    } else if (!t.raw().contains("kn") && !t.raw().contains("ks")) {
        t.fail("", fmt::format("missing the contact stiffness: give '{0}.young_modulus' [Pa] (kn and ks derived from "
                               "the material) or '{0}.kn' and '{0}.ks' [N/m] per contact point", t.path()));
    }
    return material;
}

// The typical block of every material: the median over its dynamic bodies, or over its fixed and
// driven ones if it has no dynamic body; over all bodies for a material no body uses.
std::vector<BlockDimensions> typical_blocks(const MaterialPairs& pairs, const std::vector<BodyDef>& bodies) {
    std::vector<std::vector<BlockDimensions>> moving(pairs.materials.size()), still(pairs.materials.size());
    std::vector<BlockDimensions> all;
    for (const BodyDef& b : bodies) {
        const BlockDimensions d = block_dimensions(b.vertices_m, b.thickness_m);
        (b.kind == BodyKind::dynamic ? moving : still)[pairs.id(b.material)].push_back(d);
        all.push_back(d);
    }
    std::vector<BlockDimensions> typical;
    for (std::size_t m = 0; m < pairs.materials.size(); ++m)
        typical.push_back(typical_block(!moving[m].empty() ? moving[m] : !still[m].empty() ? still[m] : all));
    return typical;
}

// Every pair's kn and ks from the rule (laws/material_stiffness.hpp), with their origin.
// A material no body uses (the "default" of a scenario that names all its materials) never
// touches anything, but the stable time step bounds each body by every pair its material is in:
// its pair with a used material B copies B's own side, so it is never stiffer than B with B.
void derive_stiffness(MaterialPairs& pairs, const std::vector<ElasticMaterial>& materials,
                      const std::vector<BodyDef>& bodies) {
    const std::vector<BlockDimensions> blocks = typical_blocks(pairs, bodies);
    const std::size_t n = pairs.materials.size();
    std::vector<bool> used(n, false);
    for (const BodyDef& b : bodies) used[pairs.id(b.material)] = true;
    pairs.origins.assign(n * n, StiffnessOrigin{});
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
            StiffnessOrigin& origin = pairs.origins[i * n + j];
            const std::uint32_t side_a = used[i] || !used[j] ? i : j;
            const std::uint32_t side_b = used[j] || !used[i] ? j : i;
            origin.derived = true;
            origin.a = {materials[side_a], blocks[side_a]};
            origin.b = {materials[side_b], blocks[side_b]};
            origin.rule = block_joint_stiffness(origin.a, origin.b);
            pairs.parameters[i * n + j].kn_N_m = origin.rule.kn_N_m;
            pairs.parameters[i * n + j].ks_N_m = origin.rule.ks_N_m;
            // Per length, the rule's joint stiffness per unit area is kn and ks themselves.
            pairs.parameters[i * n + j].kn_pa_m = origin.rule.kn_per_area_pa_m;
            pairs.parameters[i * n + j].ks_pa_m = origin.rule.ks_per_area_pa_m;
        }
    }
}

// Each material's E and nu: [contact]'s, or its own [contact.materials.NAME].
std::vector<ElasticMaterial> read_materials(TableReader& t, const std::optional<ElasticMaterial>& base,
                                            const MaterialPairs& pairs) {
    std::vector<ElasticMaterial> out(pairs.materials.size(), base.value_or(ElasticMaterial{}));
    auto table = t.optional_table("materials");
    if (!table) return out;
    if (!base)
        t.fail("materials", "a material's young_modulus needs the stiffness rule: give [contact] young_modulus instead "
                            "of kn and ks");
    for (const auto& [key, node] : table->raw()) {
        const std::string name(key.str());
        TableReader m = table->table(name);
        std::uint32_t id = 0;
        try {
            id = pairs.id(name);
        } catch (const std::out_of_range&) {
            const std::string guess = nearest(name, pairs.materials);
            table->fail(name, fmt::format("no body uses material '{}'{}; materials in use: {}", name,
                                          guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess),
                                          fmt::join(pairs.materials, ", ")));
        }
        out[id] = *read_elastic_material(m, base);
        m.reject_unknown_keys();
    }
    return out;
}

// Bonds carry cohesion and tension per unit area of joint: a bonded body's pairs within its
// group need per-length stiffness.
void check_bonds_have_joints(TableReader contact, const Model& model) {
    for (const BodyDef& a : model.bodies) {
        if (a.bond_group == 0) continue;
        const ContactParameters& p = model.contact.at(model.contact.id(a.material), model.contact.id(a.material));
        if (p.stiffness == StiffnessBasis::per_length) continue;
        contact.fail("stiffness", fmt::format("body '{}' is bonded (bonded = true{}) but per-point stiffness is set for "
                                              "material '{}': bonds need stiffness = \"per_length\" (kn, ks in Pa/m)",
                                              a.name, a.assembly.empty() ? "" : fmt::format(", assembly '{}'", a.assembly),
                                              a.material));
    }
}

MaterialPairs read_contact(TableReader t, const std::vector<BodyDef>& bodies) {
    ContactParameters defaults;
    defaults.h_s = 1.0;  // the paper's recommendation
    const std::optional<ElasticMaterial> material = read_default_material(t);
    defaults = read_contact_parameters(t, defaults, true, !material);
    const std::string default_meaning = t.choice("e_meaning", {"paper", "rebound"}, "paper");
    MaterialPairs pairs;
    pairs.materials.push_back("default");
    for (const BodyDef& b : bodies)
        if (std::find(pairs.materials.begin(), pairs.materials.end(), b.material) == pairs.materials.end())
            pairs.materials.push_back(b.material);
    pairs.parameters.assign(pairs.materials.size() * pairs.materials.size(), defaults);
    const std::vector<ElasticMaterial> elastic = read_materials(t, material, pairs);
    if (material) derive_stiffness(pairs, elastic, bodies);
    if (auto rounding = t.optional_number("rounding")) {
        if (!(*rounding >= 0.0)) t.fail("rounding", fmt::format("is a corner radius [m] and must be >= 0, got {}", *rounding));
        pairs.rounding_m = *rounding;
    }
    const std::optional<std::int64_t> sub_contacts = t.optional_whole_number("sub_contacts", 2, max_sub_contacts);
    if (sub_contacts) pairs.sub_contacts = static_cast<std::uint32_t>(*sub_contacts);
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (TableReader pair : t.table_array("pairs")) {
        const auto names = [&] {
            pair.has("materials");
            const auto* arr = pair.raw().get_as<toml::array>("materials");
            if (!arr || arr->size() != 2 || !(*arr)[0].is_string() || !(*arr)[1].is_string())
                pair.fail("materials", "must be a list of two material names, e.g. [\"stone\", \"table\"]");
            return std::pair{*(*arr)[0].value<std::string>(), *(*arr)[1].value<std::string>()};
        }();
        std::uint32_t ids[2];
        for (int k = 0; k < 2; ++k) {
            const std::string& m = k == 0 ? names.first : names.second;
            try {
                ids[k] = pairs.id(m);
            } catch (const std::out_of_range&) {
                const std::string guess = nearest(m, pairs.materials);
                pair.fail("materials", fmt::format("no body uses material '{}'{}; materials in use: {}", m,
                                                   guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess),
                                                   fmt::join(pairs.materials, ", ")));
            }
        }
        if (!seen.insert({std::min(ids[0], ids[1]), std::max(ids[0], ids[1])}).second)
            pair.fail("materials", fmt::format("the pair {} / {} is given twice", names.first, names.second));
        for (const char* key : {"young_modulus", "poisson_ratio", "stiffness_rule"})
            if (pair.has(key))
                pair.fail(key, fmt::format("is a property of one material, not of a pair: give it in "
                                           "[contact.materials.NAME] (or give this pair's kn and ks)"));
        const bool kn_given = pair.has("kn");
        const bool ks_given = pair.has("ks");
        pairs.set(ids[0], ids[1], read_contact_parameters(pair, pairs.at(ids[0], ids[1]), false, false, default_meaning));
        for (const auto& [i, j] : {std::pair{ids[0], ids[1]}, std::pair{ids[1], ids[0]}}) {
            if (pairs.origins.empty()) break;
            pairs.origins[i * pairs.materials.size() + j].kn_given = kn_given;
            pairs.origins[i * pairs.materials.size() + j].ks_given = ks_given;
        }
        pair.reject_unknown_keys();
    }
    // Sub-contacts split a joint's length: they need stiffness per unit length everywhere.
    if (sub_contacts)
        for (std::size_t i = 0; i < pairs.parameters.size(); ++i)
            if (pairs.parameters[i].stiffness == StiffnessBasis::per_point)
                t.fail("sub_contacts", fmt::format("splits a joint's length, so it needs stiffness = \"per_length\", but "
                                                   "the pair {} / {} has per-point stiffness",
                                                   pairs.materials[i / pairs.materials.size()],
                                                   pairs.materials[i % pairs.materials.size()]));
    pairs.refresh_any_dilation();
    t.reject_unknown_keys();
    return pairs;
}

}  // namespace

// (Shared with the 3-D reader: io/scenario_keys.hpp.)
std::optional<double> read_angle(TableReader& t, const std::string& base) {
    const auto rad = t.optional_number(base);
    const auto deg = t.optional_number(base + "_deg");
    if (rad && deg) t.fail(base + "_deg", fmt::format("give either {} [rad] or {}_deg [deg], not both", base, base));
    if (deg) return *deg * pi / 180.0;
    return rad;
}

namespace {

}  // namespace

// (Shared with the 3-D reader: io/scenario_keys.hpp.)
void check_some_body_moves(const std::string& file, std::size_t dynamic_bodies, std::size_t fixed_bodies,
                           std::size_t driven_bodies) {
    if (dynamic_bodies > 0) return;
    throw InputError({file, "", 0, 0},
                     fmt::format("the model has no dynamic body ({} fixed, {} driven), so nothing would move: give a "
                                 "body kind = \"dynamic\" (the default), or check an assembly's `fixed` key",
                                 fixed_bodies, driven_bodies));
}

void read_scenario_labels(TableReader& top) {
    top.optional_string("title");
    top.optional_string("description");
}

std::string read_body_name(TableReader& t) {
    const std::string name = t.string("name");
    // Names head CSV columns and are path segments of --set: keep them to one plain word.
    if (name.empty() || name.find_first_of(",.;\"' \t\r\n") != std::string::npos)
        t.fail("name", fmt::format("'{}' is not a valid body name: use letters, digits, '_' or '-' (no spaces, commas, "
                                   "dots or quotes)", name));
    return name;
}

namespace {

BodyDef read_body(TableReader t) {
    BodyDef b;
    b.name = read_body_name(t);
    const std::string kind = t.choice("kind", {"dynamic", "fixed", "driven"}, "dynamic");
    b.kind = kind == "dynamic" ? BodyKind::dynamic : kind == "fixed" ? BodyKind::fixed : BodyKind::driven;
    const std::string shape = t.choice("shape", {"rectangle", "polygon"}, "");
    const double rotation = read_angle(t, "rotation").value_or(0.0);
    if (shape == "rectangle") {
        const double width = t.positive("width");
        const double height = t.positive("height");
        const auto center = t.optional_vec2("center");
        if (!center) t.fail_missing("center", " ([x, y] in m)");
        b.vertices_m = rectangle_vertices(width, height, *center, rotation);
    } else {
        const std::vector<Vec2> listed = t.vec2_list("vertices");
        if (auto problem = listed_outline_problem(listed)) t.fail("vertices", *problem);
        b.vertices_m = counter_clockwise(listed);
        if (rotation != 0.0) {
            const Vec2 c = polygon_properties(b.vertices_m).centroid_m;
            const Rotation r = Rotation::from_angle(rotation);
            for (Vec2& v : b.vertices_m) v = c + r.apply(v - c);
        }
    }
    b.material = t.optional_string("material").value_or("default");
    b.thickness_m = t.optional_positive("thickness").value_or(1.0);
    b.mass_kg = t.optional_positive("mass");
    b.inertia_kg_m2 = t.optional_positive("inertia");
    const auto density = t.optional_positive("density");
    if (density && b.mass_kg) t.fail("mass", "give either density or mass, not both");
    if (density) b.density_kg_m3 = *density;
    if (b.kind == BodyKind::dynamic && !density && !b.mass_kg)
        t.fail("", fmt::format("body '{}' needs 'density' [kg/m^3] or 'mass' [kg]", b.name));
    b.velocity_m_s = t.optional_vec2("velocity").value_or(Vec2{});
    b.angular_velocity_rad_s = t.number_or("angular_velocity", 0.0);
    b.record = t.boolean_or("record", true);
    // Every [[bodies]] entry with bonded = true is bonded to the others where they touch at the
    // start (one group: contact/bonded_pairs.hpp).
    if (t.boolean_or("bonded", false)) b.bond_group = 1;
    t.reject_unknown_keys();
    return b;
}

double read_period(TableReader& t) {
    const auto period = t.optional_positive("period");
    const auto frequency = t.optional_positive("frequency");
    if (period && frequency) t.fail("frequency", "give either period [s] or frequency [Hz], not both");
    if (!period && !frequency) t.fail("", fmt::format("missing '{}.period' [s] or '{}.frequency' [Hz]", t.path(), t.path()));
    return period ? *period : 1.0 / *frequency;
}

// Every motion starts at rest (motion/table_motion.hpp): a start before t = 0 would have the
// table already moving, with a velocity and a displacement, when the run begins.
double read_start(TableReader& t) {
    const double start_s = t.number_or("start", 0.0);
    if (!(start_s >= 0.0))
        t.fail("start", fmt::format("must be >= 0 [s], got {}: a motion starts at rest, and one that started before t = 0 "
                                    "would have the table already moving when the run begins",
                                    start_s));
    return start_s;
}

ComponentMotion read_component_motion(TableReader& t, const std::filesystem::path& scenario_dir) {
    const std::string type =
        t.choice("type", {"sine", "one_sine", "one_cosine", "ricker", "csv", "series", "record", "synthetic", "none"}, "");
    ComponentMotion motion = RestMotion{};
    if (type == "record") return read_record_motion(t, scenario_dir);
    if (type == "synthetic") return read_synthetic_motion(t);
    if (type == "csv") return read_time_series_csv_keys(t, scenario_dir);
    if (type == "series") return read_series_motion_keys(t);
    if (type == "sine") {
        SineMotion m;
        m.amplitude_m_s2 = t.number("amplitude") * acceleration_unit_factor(t);
        m.period_s = read_period(t);
        m.phase_rad = read_angle(t, "phase").value_or(0.0);
        m.start_s = read_start(t);
        m.cycles = t.number_or("cycles", 0.0);
        if (m.cycles < 0.0) t.fail("cycles", "must be >= 0 (0: no end)");
        motion = m;
    } else if (type == "one_sine" || type == "one_cosine") {
        PulseMotion m;
        m.shape = type == "one_sine" ? PulseMotion::Shape::one_sine : PulseMotion::Shape::one_cosine;
        m.amplitude_m_s2 = t.number("amplitude") * acceleration_unit_factor(t);
        m.period_s = read_period(t);
        m.start_s = read_start(t);
        motion = m;
    } else if (type == "ricker") {
        RickerMotion m;
        m.amplitude_m_s2 = t.number("amplitude") * acceleration_unit_factor(t);
        m.peak_frequency_hz = t.positive("frequency");
        m.center_time_s = t.optional_number("center_time").value_or(1.5 / m.peak_frequency_hz);
        motion = m;
    }
    t.reject_unknown_keys();
    return motion;
}

// The key that sets a component's size, for a message about it.
std::string size_key(const TableReader& t) {
    for (const char* key : {"amplitude", "target_pga", "scale"})
        if (t.raw().contains(key)) return key;
    return "type";
}

}  // namespace

// (Shared with the 3-D reader: io/scenario_keys.hpp.)
ComponentMotion read_component(TableReader t, const std::filesystem::path& scenario_dir) {
    ComponentMotion motion = read_component_motion(t, scenario_dir);
    const double peak_m_s2 = peak_acceleration(motion);
    if (!std::isfinite(peak_m_s2))
        t.fail(size_key(t), "gives a peak table acceleration beyond the range of a number in m/s^2: check the value "
                            "and its unit");
    if (peak_m_s2 > max_table_acceleration_m_s2)
        t.fail(size_key(t), fmt::format("gives a peak table acceleration of {:.4g} m/s^2 ({:.4g} g), beyond the {:g} "
                                        "m/s^2 that any earthquake, shaking table or centrifuge model asks for: "
                                        "check the value and its unit",
                                        peak_m_s2, peak_m_s2 / standard_gravity_m_s2, max_table_acceleration_m_s2));
    return motion;
}

namespace {

TableMotion read_table_motion(TableReader t, const std::filesystem::path& scenario_dir) {
    TableMotion m;
    if (auto h = t.optional_table("horizontal")) m.horizontal = read_component(*h, scenario_dir);
    if (auto v = t.optional_table("vertical")) m.vertical = read_component(*v, scenario_dir);
    t.reject_unknown_keys();
    return m;
}

}  // namespace

double acceleration_unit_factor(TableReader& keys, const std::string& key) {
    const std::string unit = keys.choice(key, {"m/s^2", "gal", "g"}, "m/s^2");
    if (unit == "gal") return 0.01;
    if (unit == "g") return standard_gravity_m_s2;
    return 1.0;
}

toml::table load_toml_file(const std::filesystem::path& file) {
    if (std::filesystem::is_directory(file)) throw InputError({file.string(), "", 0, 0}, folder_not_scenario_message(file));
    std::ifstream in(file);
    if (!in) throw InputError({file.string(), "", 0, 0}, "cannot open the file (does it exist?)");
    std::stringstream text;
    text << in.rdbuf();
    try {
        return toml::parse(text.str(), file.string());
    } catch (const toml::parse_error& e) {
        throw InputError({file.string(), "", static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)},
                         fmt::format("TOML syntax error: {}", e.description()));
    }
}

Model read_model(const toml::table& root, const std::string& file, const std::filesystem::path& scenario_dir) {
    TableReader top(root, file, "");
    if (scenario_dimension(root, file) == 3)
        top.fail("dimension", "is 3: this command reads 2-D scenarios; a 3-D one runs with `blockdem run` (docs/3d.md)");
    Model model;
    model.settings = read_settings(top.table("simulation"));
    const std::vector<TableReader> body_tables = top.table_array("bodies");
    if (body_tables.empty() && !top.has("assemblies") && !top.has("geometry"))
        top.fail("", "the scenario has no [[bodies]], [[assemblies]] or [[geometry]]");
    std::set<std::string> names;
    for (const TableReader& bt : body_tables) {
        model.bodies.push_back(read_body(bt));
        if (!names.insert(model.bodies.back().name).second)
            bt.fail("name", fmt::format("two bodies are named '{}'", model.bodies.back().name));
    }
    read_assemblies(top, model);  // generated blocks and [settling] (io/assembly_keys.hpp)
    read_geometry(top, model, scenario_dir);  // drawn blocks (io/geometry_keys.hpp)
    check_domain_contains_bodies(top.table("simulation"), model);
    if (auto outcomes = top.optional_table("outcomes")) model.settings.outcomes = read_outcome_thresholds(*outcomes);
    model.contact = read_contact(top.table("contact"), model.bodies);
    check_bonds_have_joints(top.table("contact"), model);
    if (auto motion = top.optional_table("table_motion")) model.table_motion = read_table_motion(*motion, scenario_dir);
    read_scenario_labels(top);
    top.allow({"output", "sensors", "dimension"});  // read by load_scenario: not physics
    top.reject_unknown_keys();
    return model;
}

LoadedScenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides, bool settle,
                             const std::atomic<bool>* stop_requested) {
    return load_scenario(load_toml_file(file), file, overrides, settle, stop_requested);
}

LoadedScenario load_scenario(toml::table root, const std::filesystem::path& file, const std::vector<std::string>& overrides,
                             bool settle, const std::atomic<bool>* stop_requested) {
    LoadedScenario s;
    s.file = file;
    s.root = std::move(root);
    apply_overrides_to_scenario(s.root, overrides, file);
    s.model = read_model(s.root, file.string(), file.parent_path());
    TableReader top(s.root, file.string(), "");
    if (auto output = top.optional_table("output")) {
        output->allow({"interfaces"});  // read below, with the sensors
        s.output = read_output_settings(*output);
    }
    TableReader simulation = top.table("simulation");
    if (auto state = simulation.optional_string("initial_state")) {
        if (state->empty()) simulation.fail("initial_state", "is empty: give a state file (.h5)");
        if (s.model.settling)
            simulation.fail("initial_state", "starts from a state that is already settled: remove [settling] (or "
                                              "initial_state)");
        s.initial_state = std::filesystem::path(*state).is_absolute() ? std::filesystem::path(*state)
                                                                      : file.parent_path() / *state;
    }
    if (!settle) s.model.settling.reset();
    const auto count_kind = [&](BodyKind kind) {
        return static_cast<std::size_t>(std::count_if(s.model.bodies.begin(), s.model.bodies.end(),
                                                      [&](const BodyDef& b) { return b.kind == kind; }));
    };
    check_some_body_moves(file.string(), count_kind(BodyKind::dynamic), count_kind(BodyKind::fixed),
                          count_kind(BodyKind::driven));
    try {
        s.world = build_world(s.model, stop_requested);
    } catch (const ModelError& e) {
        throw InputError({file.string(), "", 0, 0}, e.what());
    }
    if (auto motion = top.optional_table("table_motion")) {  // dt is known from here on
        check_motion_sampling(*motion, "horizontal", s.model.table_motion.horizontal, s.world.dt_s);
        check_motion_sampling(*motion, "vertical", s.model.table_motion.vertical, s.world.dt_s);
    }
    s.measurements = read_measurement_keys(top, s.world);  // they name bodies and depend on dt
    return s;
}

}  // namespace blockdem
