#include "study/rocking_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/polygon.hpp"
#include "world/model.hpp"
#include "world/step.hpp"
#include "world/world.hpp"

namespace blockdem {

double RockingBlock::alpha_rad() const { return std::atan(width_m / height_m); }

double housner_restitution(double alpha_rad) {
    const double s = std::sin(alpha_rad);
    return 1.0 - 1.5 * s * s;
}

RockingObstacle rocking_obstacle(const RockingBlock& block) {
    if (!(housner_restitution(block.alpha_rad()) > 0.0)) return RockingObstacle::too_squat;
    return RockingObstacle::none;
}

int first_energy_gaining_impact(const FreeRocking& run) {
    for (std::size_t k = 0; k < run.impact_restitution.size(); ++k)
        if (!(run.impact_restitution[k] < 1.0)) return static_cast<int>(k);
    return -1;
}

std::vector<double> restitution_from_peaks(double alpha_rad, const std::vector<double>& peaks_rad) {
    // Potential energy above the upright position at tilt theta, per m g R: cos(alpha - theta) - cos(alpha)
    // (the kinetic energy at the impact, I_O omega^2 / 2, equals it on either side of the impact).
    auto height_gain = [&](double theta) { return std::cos(alpha_rad - std::abs(theta)) - std::cos(alpha_rad); };
    std::vector<double> r;
    for (std::size_t k = 0; k + 1 < peaks_rad.size(); ++k)
        r.push_back(std::sqrt(std::max(0.0, height_gain(peaks_rad[k + 1])) / height_gain(peaks_rad[k])));
    return r;
}

double geometric_mean(const std::vector<double>& ratios) {
    if (ratios.empty()) return 0.0;
    double log_sum = 0.0;
    for (double r : ratios) {
        if (!(r > 0.0)) return 0.0;
        log_sum += std::log(r);
    }
    return std::exp(log_sum / static_cast<double>(ratios.size()));
}

namespace {

// A fixed table under the block, wide enough for any rocking short of toppling, and the block
// standing on its left corner, tilted counter-clockwise by the release tilt.
Model free_rocking_model(const RockingBlock& block) {
    const double b = 0.5 * block.width_m;
    const double h = 0.5 * block.height_m;
    const double table_width_m = 4.0 * (block.width_m + block.height_m);
    const double table_height_m = 0.25 * block.height_m;
    BodyDef table;
    table.name = "table";
    table.kind = BodyKind::fixed;
    table.vertices_m = rectangle_vertices(table_width_m, table_height_m, {0.0, -0.5 * table_height_m}, 0.0);
    table.thickness_m = block.thickness_m;
    const Vec2 pivot{-b, 0.0};
    const double tilt = block.release_tilt_rad;
    BodyDef rocker;
    rocker.name = "block";
    rocker.kind = BodyKind::dynamic;
    rocker.vertices_m = rectangle_vertices(block.width_m, block.height_m, pivot + Rotation::from_angle(tilt).apply(Vec2{b, h}), tilt);
    rocker.density_kg_m3 = block.density_kg_m3;
    rocker.thickness_m = block.thickness_m;
    Model m;
    m.bodies = {table, rocker};
    m.contact = MaterialPairs::uniform(block.contact);
    m.settings.dt_s = block.dt_s;
    m.settings.gravity_m_s2 = block.gravity_m_s2;
    m.settings.duration_s = 1.0;  // (unused: the loop below decides when to stop)
    return m;
}

}  // namespace

FreeRocking free_rocking(const RockingBlock& block) {
    World w = build_world(free_rocking_model(block));
    const std::uint32_t id = w.body_id("block");
    const double alpha = block.alpha_rad();
    const double tilt0 = block.release_tilt_rad;
    // Housner's frequency parameter p = sqrt(3 g / (4 R)); a half cycle from any tilt below
    // alpha lasts a few 1/p, so 60/p covers every impact asked for unless the block has stopped.
    const double p_rad_s = std::sqrt(3.0 * block.gravity_m_s2 / (2.0 * std::hypot(block.width_m, block.height_m)));
    const double end_s = 60.0 / p_rad_s + 10.0 * block.impacts / p_rad_s;
    // Below this amplitude the block has stopped rocking (the contact's own compliance, m g / kn
    // over the base, is far smaller for any stiffness that makes sense).
    const double at_rest_rad = 1e-4 * alpha;

    FreeRocking out;
    out.dt_s = w.dt_s;
    out.peaks_rad.push_back(tilt0);
    double side = 1.0;            // sign of theta in this half cycle
    double peak = tilt0;          // largest |theta| in this half cycle
    bool peak_final = true;       // the release is a peak
    while (static_cast<int>(out.peaks_rad.size()) <= block.impacts && w.time_s < end_s) {
        step(w);
        ++out.steps;
        const double theta = tilt0 + w.bodies.rotation_rad[id];
        if (std::abs(theta) > 0.5 * std::numbers::pi || std::abs(theta) > alpha + 0.5 * (0.5 * std::numbers::pi - alpha)) {
            out.overturned = true;
            break;
        }
        if (theta * side < 0.0) {  // passed upright: an impact; the last half cycle's peak is done
            if (!peak_final) out.peaks_rad.push_back(peak);
            side = -side;
            peak = std::abs(theta);
            peak_final = false;
            continue;
        }
        if (!peak_final) {
            peak = std::max(peak, std::abs(theta));
            // Falling back below half its peak, the block cannot rise again before the next impact.
            if (std::abs(theta) < 0.5 * peak && peak > at_rest_rad) {
                out.peaks_rad.push_back(peak);
                peak_final = true;
            }
        }
        if (peak_final && out.peaks_rad.back() < at_rest_rad) break;
    }
    out.impact_restitution = restitution_from_peaks(alpha, out.peaks_rad);
    out.restitution = out.overturned ? 0.0 : geometric_mean(out.impact_restitution);
    return out;
}

std::vector<double> scanned_damping_ratios(ContactTermination termination) {
    std::vector<double> h = {0.02, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9};
    if (termination == ContactTermination::zero_overlap) {
        h.push_back(0.99);
    } else {
        h.insert(h.end(), {1.2, 2.0, 3.0});
    }
    return h;
}

std::vector<double> scanned_stiffnesses(double kn_N_m) {
    std::vector<double> kn;
    for (double exponent = 1.0; exponent >= -3.0; exponent -= 0.5) kn.push_back(kn_N_m * std::pow(10.0, exponent));
    return kn;
}

namespace {

// The contact with the fitted parameter set to value (kn: ks follows in proportion).
ContactParameters with_value(ContactParameters c, CalibratedParameter parameter, double value) {
    if (parameter == CalibratedParameter::h_n) {
        c.h_n = value;
    } else {
        c.ks_N_m *= value / c.kn_N_m;
        c.kn_N_m = value;
    }
    return c;
}

}  // namespace

RockingFit calibrate_rocking(const RockingBlock& block, CalibratedParameter parameter, double target, double tolerance) {
    RockingFit fit;
    fit.parameter = parameter;
    fit.target_restitution = target;
    fit.reachable_min = std::numeric_limits<double>::infinity();
    fit.reachable_max = -std::numeric_limits<double>::infinity();
    double best_error = std::numeric_limits<double>::infinity();
    // The root is sought in u: h_n itself, or log10(kn) (kn spans decades).
    const bool logarithmic = parameter == CalibratedParameter::kn;
    auto value_of = [&](double u) { return logarithmic ? std::pow(10.0, u) : u; };
    auto measure = [&](double u) {
        RockingBlock trial = block;
        trial.contact = with_value(block.contact, parameter, value_of(u));
        FreeRocking run = free_rocking(trial);
        ++fit.dem_runs;
        const double r = run.restitution;
        fit.scan.emplace_back(value_of(u), r);
        if (r < fit.reachable_min) fit.reachable_min = r, fit.value_at_min = value_of(u);
        if (r > fit.reachable_max) fit.reachable_max = r, fit.value_at_max = value_of(u);
        if (std::abs(r - target) < best_error) {
            best_error = std::abs(r - target);
            fit.contact = trial.contact;
            fit.achieved_restitution = r;
            fit.residual = r - target;
            fit.run = run;
        }
        return r - target;
    };
    std::vector<double> grid = parameter == CalibratedParameter::h_n ? scanned_damping_ratios(block.contact.termination)
                                                                     : scanned_stiffnesses(block.contact.kn_N_m);
    if (logarithmic)
        for (double& g : grid) g = std::log10(g);
    // Scan for the first sign change of r - target.
    double lo = grid[0];
    double f_lo = measure(lo);
    bool bracketed = false;
    double hi = lo, f_hi = f_lo;
    for (std::size_t i = 1; i < grid.size() && best_error > tolerance; ++i) {
        hi = grid[i];
        f_hi = measure(hi);
        if ((f_lo < 0.0) != (f_hi < 0.0)) {
            bracketed = true;
            break;
        }
        lo = hi;
        f_lo = f_hi;
    }
    // Illinois: regula falsi that halves the weight of an end kept twice, so both ends move.
    int kept = 0;
    for (int iteration = 0; bracketed && iteration < 40 && best_error > tolerance && std::abs(hi - lo) > 1e-9; ++iteration) {
        const double u = hi - f_hi * (hi - lo) / (f_hi - f_lo);
        const double f = measure(u);
        if ((f < 0.0) == (f_hi < 0.0)) {
            hi = u;
            f_hi = f;
            if (kept == -1) f_lo *= 0.5;
            kept = -1;
        } else {
            lo = u;
            f_lo = f;
            if (kept == 1) f_hi *= 0.5;
            kept = 1;
        }
    }
    fit.found = best_error <= tolerance;
    return fit;
}

}  // namespace blockdem
