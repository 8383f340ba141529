// `blockdem calibrate`: the contact damping h_n for which a free-rocking block loses the
// measured energy per impact (docs/calibration.md). The user gives the block, the contact's
// stiffness and friction, and what was measured: the rocking restitution r (angular velocity
// after / before an impact), its square (the energy ratio), or a decay of peak rotations. The
// library (study/rocking_calibration.hpp) runs the engine's own free-rocking block and root-finds
// on h_n; this file checks the input, prints the fit and the scenario keys to paste.
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "laws/restitution.hpp"
#include "study/rocking_calibration.hpp"
#include "world/simulation_error.hpp"
#include "world/world.hpp"

namespace blockdem::cli {
namespace {

struct CalibrateOptions {
    double width_m = 0.0;
    double height_m = 0.0;
    double density_kg_m3 = 2400.0;
    double thickness_m = 1.0;
    double gravity_m_s2 = 9.81;
    double kn_N_m = 0.0;
    std::optional<double> ks_N_m;
    double mu = 0.8;
    double h_s = 1.0;
    std::optional<double> h_n;
    std::string fit = "h_n";
    std::string termination = "no_tension";
    std::string e_meaning = "paper";
    std::optional<double> restitution;
    std::optional<double> energy_ratio;
    std::vector<double> peaks;
    std::string peaks_unit = "rad";
    std::optional<double> tilt_rad;
    int impacts = 3;
    double tolerance = 1e-3;
    std::optional<double> dt_s;
    std::string toml_file;
};

[[noreturn]] void bad(const std::string& option, const std::string& problem) { throw InputError({"", option, 0, 0}, problem); }

void check_positive(const std::string& option, double value, const char* unit) {
    if (!(value > 0.0) || !std::isfinite(value)) bad(option, fmt::format("must be a number > 0 [{}], got {}", unit, value));
}

// What was measured, as the target r and the release tilt of the DEM runs.
struct Target {
    double restitution = 0.0;
    std::string source;
    std::vector<double> measured_impacts;  ///< per-impact r read from --peaks
    double tilt_rad = 0.0;
};

Target read_target(const CalibrateOptions& o, double alpha_rad) {
    const int given = (o.restitution ? 1 : 0) + (o.energy_ratio ? 1 : 0) + (o.peaks.empty() ? 0 : 1);
    if (given != 1)
        bad("--restitution", "give exactly one of --restitution (angular velocity ratio r), --energy-ratio (r^2) and --peaks "
                             "(successive peak rotations)");
    Target t;
    // The reachable bound: an impact cannot add energy (r < 1) and some rotation survives it (r > 0).
    auto check_ratio = [](const std::string& option, double r, const std::string& what) {
        if (!(r > 0.0 && r < 1.0))
            bad(option, fmt::format("{} must be in (0, 1): an impact loses some energy and the block rocks on; got {}", what, r));
    };
    if (o.restitution) {
        check_ratio("--restitution", *o.restitution, "the restitution r");
        t.restitution = *o.restitution;
        t.source = fmt::format("r = {:g} (angular velocity after / before an impact)", *o.restitution);
    } else if (o.energy_ratio) {
        check_ratio("--energy-ratio", *o.energy_ratio, "the energy ratio r^2");
        t.restitution = std::sqrt(*o.energy_ratio);
        t.source = fmt::format("r^2 = {:g} (kinetic energy after / before an impact), r = {:.6g}", *o.energy_ratio, t.restitution);
    } else {
        if (o.peaks.size() < 2) bad("--peaks", "needs at least two successive peak rotations (the release or a peak, then the next)");
        const double to_rad = o.peaks_unit == "deg" ? std::numbers::pi / 180.0 : 1.0;
        std::vector<double> peaks;
        for (std::size_t k = 0; k < o.peaks.size(); ++k) {
            const double p = std::abs(o.peaks[k]) * to_rad;
            if (!(p > 0.0) || !(p < alpha_rad))
                bad("--peaks", fmt::format("peak {} ({} {}) must be above 0 and below the block's slenderness angle alpha = "
                                           "atan(width / height) = {:.6g} rad ({:.4g} deg), or the block would topple",
                                           k + 1, o.peaks[k], o.peaks_unit, alpha_rad, alpha_rad * 180.0 / std::numbers::pi));
            if (k > 0 && !(p < peaks.back()))
                bad("--peaks", fmt::format("peak {} ({} {}) is not below peak {}: free rocking only decays", k + 1, o.peaks[k],
                                           o.peaks_unit, k));
            peaks.push_back(p);
        }
        t.measured_impacts = restitution_from_peaks(alpha_rad, peaks);
        t.restitution = geometric_mean(t.measured_impacts);
        t.tilt_rad = peaks.front();
        t.source = fmt::format("{} peaks, {} impacts: r per impact {:.4f}, geometric mean r = {:.6g}", peaks.size(),
                               t.measured_impacts.size(), fmt::join(t.measured_impacts, ", "), t.restitution);
    }
    return t;
}

RockingBlock read_block(const CalibrateOptions& o) {
    check_positive("--width", o.width_m, "m");
    check_positive("--height", o.height_m, "m");
    check_positive("--density", o.density_kg_m3, "kg/m^3");
    check_positive("--thickness", o.thickness_m, "m");
    check_positive("--gravity", o.gravity_m_s2, "m/s^2");
    check_positive("--kn", o.kn_N_m, "N/m");
    if (o.ks_N_m) check_positive("--ks", *o.ks_N_m, "N/m");
    if (!(o.mu >= 0.0)) bad("--mu", fmt::format("must be >= 0, got {}", o.mu));
    if (!(o.h_s >= 0.0)) bad("--h-s", fmt::format("must be >= 0, got {}", o.h_s));
    if (!(o.tolerance > 0.0 && o.tolerance < 0.1)) bad("--tolerance", fmt::format("must be in (0, 0.1) (on r), got {}", o.tolerance));
    if (o.impacts < 1 || o.impacts > 20) bad("--impacts", fmt::format("must be 1 to 20, got {}", o.impacts));
    if (o.dt_s) check_positive("--dt", *o.dt_s, "s");
    if (o.fit == "kn" && !o.h_n) bad("--h-n", "--fit kn needs the damping ratio to hold: give --h-n");
    if (o.fit == "h_n" && o.h_n) bad("--h-n", "is what --fit h_n (the default) finds: give it only with --fit kn");
    if (o.h_n && !(*o.h_n >= 0.0 && (*o.h_n < 1.0 || o.termination == "no_tension")))
        bad("--h-n", fmt::format("must be >= 0 (and < 1 with termination zero_overlap), got {}", *o.h_n));
    RockingBlock b;
    b.width_m = o.width_m;
    b.height_m = o.height_m;
    b.density_kg_m3 = o.density_kg_m3;
    b.thickness_m = o.thickness_m;
    b.gravity_m_s2 = o.gravity_m_s2;
    b.contact.kn_N_m = o.kn_N_m;
    b.contact.ks_N_m = o.ks_N_m.value_or(o.kn_N_m);
    b.contact.mu = o.mu;
    b.contact.h_s = o.h_s;
    b.contact.h_n = o.h_n.value_or(0.0);
    b.contact.termination = o.termination == "zero_overlap" ? ContactTermination::zero_overlap : ContactTermination::no_tension;
    b.impacts = o.impacts;
    b.dt_s = o.dt_s;
    return b;
}

// The scenario keys of the fit; h_n is given directly (e in both meanings as a comment).
std::string contact_keys(const RockingFit& fit, const std::string& e_meaning) {
    const ContactParameters& c = fit.contact;
    const double h = c.h_n;
    const double rebound = restitution_of(h, c.termination);
    std::string e_note;
    if (h < 1.0 && e_meaning == "paper")
        e_note = fmt::format("e = {:.6g} with e_meaning = \"paper\"; a head-on impact rebounds with {:.6g}", restitution_paper(h), rebound);
    else
        e_note = fmt::format("e = {:.6g} with e_meaning = \"rebound\" (a head-on impact's rebound)", rebound);
    std::string keys = "[contact]\n";
    const bool kn_fitted = fit.parameter == CalibratedParameter::kn;
    keys += fmt::format("kn = {:.6g}{}\n", c.kn_N_m, kn_fitted ? "              # [N/m] per contact point, fitted" : "");
    keys += fmt::format("ks = {:.6g}\n", c.ks_N_m);
    keys += fmt::format("mu = {:.6g}\n", c.mu);
    keys += fmt::format("h_s = {:.6g}\n", c.h_s);
    keys += fmt::format("h_n = {:.6f}              # {}{}\n", h, kn_fitted ? "" : "fitted: ", e_note);
    // (A scenario refuses h_n >= 1 in the default paper meaning, where e is undefined there.)
    if (h >= 1.0) keys += "e_meaning = \"rebound\"\n";
    keys += fmt::format("termination = \"{}\"\n", to_string(c.termination));
    return keys;
}

// The calibration fits a block that rocks on its corners: refused up front when it cannot (the
// DEM would run and fail with an unrelated remedy); a block that slips is found in the fitted run
// (check_fit_rocks).
void check_block_rocks(const RockingBlock& block) {
    const double aspect = block.width_m / block.height_m;  // [-] b/h = tan alpha
    switch (rocking_obstacle(block)) {
        case RockingObstacle::none: return;
        case RockingObstacle::too_squat:
            bad("--width", fmt::format("with --height {:g} m: width / height = {:.4g} is at least sqrt(2), so Housner's r = "
                                       "1 - 1.5 sin^2 alpha = {:.4g} <= 0: the block's first impact stops it and it does not "
                                       "rock on, so there is no rocking restitution to fit; calibrate on a block with "
                                       "width / height < 1.414 (--height above {:.4g} m)",
                                       block.height_m, aspect, housner_restitution(block.alpha_rad()),
                                       block.width_m / std::numbers::sqrt2));
    }
}

// An impact whose r is >= 1 gained energy: the block slid or bounced, and a fit through it is no
// rocking restitution (physics, exit 3).
void check_fit_rocks(const RockingFit& fit, const char* name) {
    const int k = first_energy_gaining_impact(fit.run);
    if (k < 0) return;
    throw SimulationError(fmt::format(
        "the fitted run ({} = {:.6g}) gained energy at impact {}: r = {:.6g} >= 1 (per impact {:.5f}), so the block slid or "
        "bounced instead of rocking on its corners and the fit is not a rocking restitution; raise --mu or --h-s, or lower "
        "--tilt (docs/calibration.md)",
        name, fit.parameter == CalibratedParameter::kn ? fit.contact.kn_N_m : fit.contact.h_n, k + 1,
        fit.run.impact_restitution[static_cast<std::size_t>(k)], fmt::join(fit.run.impact_restitution, ", ")));
}

void run_calibrate(const CalibrateOptions& o) {
    RockingBlock block = read_block(o);
    check_block_rocks(block);
    const double alpha = block.alpha_rad();
    const Target target = read_target(o, alpha);
    const double tilt = o.tilt_rad ? *o.tilt_rad : target.tilt_rad > 0.0 ? target.tilt_rad : 0.5 * alpha;
    if (!(tilt > 0.0 && tilt < alpha))
        bad("--tilt", fmt::format("the release tilt must be in (0, alpha) = (0, {:.6g}) rad, got {}", alpha, tilt));
    block.release_tilt_rad = tilt;
    const double housner = housner_restitution(alpha);

    fmt::print("block       {:g} x {:g} m (width x height), aspect {:.4g}, alpha = {:.6g} rad, density {:g} kg/m^3\n",
               block.width_m, block.height_m, block.height_m / block.width_m, alpha, block.density_kg_m3);
    fmt::print("contact     kn = {:.4g} N/m, ks = {:.4g} N/m, mu = {:g}, h_s = {:g}, termination = {}\n", block.contact.kn_N_m,
               block.contact.ks_N_m, block.contact.mu, block.contact.h_s, to_string(block.contact.termination));
    fmt::print("measured    {}\n", target.source);
    fmt::print("Housner     r = 1 - 1.5 sin^2 alpha = {:.6g} (target / Housner = {:.4f})\n", housner, target.restitution / housner);
    fmt::print("DEM runs    released from {:.6g} rad, {} impacts each, r from the peaks on either side of each impact\n", tilt,
               block.impacts);
    std::fflush(stdout);

    const CalibratedParameter parameter = o.fit == "kn" ? CalibratedParameter::kn : CalibratedParameter::h_n;
    RockingFit fit;
    try {
        fit = calibrate_rocking(block, parameter, target.restitution, o.tolerance);
    } catch (const ModelError& e) {
        throw InputError({"", "", 0, 0}, fmt::format("the free-rocking block cannot be run: {}", e.what()));
    }
    const char* name = parameter == CalibratedParameter::kn ? "kn" : "h_n";
    for (const auto& [value, r] : fit.scan) fmt::print("  {} = {:<12.6g} r = {:.6f}\n", name, value, r);
    if (!fit.found) {
        throw InputError(
            {"", o.restitution ? "--restitution" : o.energy_ratio ? "--energy-ratio" : "--peaks", 0, 0},
            fmt::format("r = {:.6g} is not reachable by fitting {} ({}): the free-rocking block gives r = {:.6g} ({} = {:.4g}) "
                        "to {:.6g} ({} = {:.4g}); Housner's r, the loss of a corner that neither bounces nor slips, is "
                        "{:.6g}. The nearest is r = {:.6g}, {:.3g} away (tolerance {:g}). {}",
                        target.restitution, name,
                        parameter == CalibratedParameter::kn ? fmt::format("h_n = {:g}", block.contact.h_n)
                                                             : fmt::format("kn = {:g} N/m", block.contact.kn_N_m),
                        fit.reachable_min, name, fit.value_at_min, fit.reachable_max, name, fit.value_at_max, housner,
                        fit.achieved_restitution, std::abs(fit.residual), o.tolerance,
                        target.restitution < fit.reachable_min
                            ? "Below Housner's r a stiff contact cannot go: try termination zero_overlap, a softer kn, or "
                              "--fit kn (docs/calibration.md)"
                            : "Above it the impact must give energy back: a lighter damping or a stiffer kn"));
    }
    check_fit_rocks(fit, name);
    const double static_overlap_m = block.gravity_m_s2 * block.density_kg_m3 * block.width_m * block.height_m * block.thickness_m /
                                    (2.0 * fit.contact.kn_N_m);
    fmt::print("fit         {} = {:.6g}: r = {:.6f} (per impact {:.5f}), residual {:+.2e}, {} DEM runs, dt = {:.4g} s\n", name,
               parameter == CalibratedParameter::kn ? fit.contact.kn_N_m : fit.contact.h_n, fit.achieved_restitution,
               fmt::join(fit.run.impact_restitution, ", "), fit.residual, fit.dem_runs, fit.run.dt_s);
    fmt::print("            static overlap at rest m g / (2 kn) = {:.3g} m ({:.3g} of the width)\n", static_overlap_m,
               static_overlap_m / block.width_m);
    const std::string keys = contact_keys(fit, o.e_meaning);
    fmt::print("\n# scenario keys (paste into the scenario):\n{}", keys);
    if (!o.toml_file.empty())
        write_output_file(o.toml_file, fmt::format("# blockdem calibrate: {}; fitted r = {:.6f} after {} DEM runs\n",
                                                   target.source, fit.achieved_restitution, fit.dem_runs) +
                                           keys);
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
    auto options = std::make_shared<CalibrateOptions>();
    CLI::App* cmd = app.add_subcommand("calibrate", "fit the contact damping h_n to a measured rocking restitution");
    cmd->add_option("--width", options->width_m, "[m] block width (2b)")->required();
    cmd->add_option("--height", options->height_m, "[m] block height (2h)")->required();
    cmd->add_option("--density", options->density_kg_m3, "[kg/m^3]")->capture_default_str();
    cmd->add_option("--thickness", options->thickness_m, "[m] out of plane")->capture_default_str();
    cmd->add_option("--gravity", options->gravity_m_s2, "[m/s^2]")->capture_default_str();
    cmd->add_option("--kn", options->kn_N_m, "[N/m] normal stiffness per contact point")->required();
    cmd->add_option("--ks", options->ks_N_m, "[N/m] shear stiffness (default: kn)");
    cmd->add_option("--mu", options->mu, "friction coefficient (high enough that the block rocks without sliding)")
        ->capture_default_str();
    cmd->add_option("--h-s", options->h_s, "shear damping ratio")->capture_default_str();
    cmd->add_option("--fit", options->fit, "what to fit: h_n (at the given kn) or kn (at the given --h-n)")
        ->capture_default_str()
        ->check(CLI::IsMember({"h_n", "kn"}));
    cmd->add_option("--h-n", options->h_n, "normal damping ratio to hold with --fit kn");
    cmd->add_option("--termination", options->termination, "when a contact ends: no_tension or zero_overlap")
        ->capture_default_str()
        ->check(CLI::IsMember({"no_tension", "zero_overlap"}));
    cmd->add_option("--e-meaning", options->e_meaning, "meaning of the e printed beside h_n: paper or rebound")
        ->capture_default_str()
        ->check(CLI::IsMember({"paper", "rebound"}));
    cmd->add_option("--restitution", options->restitution, "measured r: angular velocity after / before an impact");
    cmd->add_option("--energy-ratio", options->energy_ratio, "measured r^2: kinetic energy after / before an impact");
    cmd->add_option("--peaks", options->peaks, "measured successive peak rotations (comma-separated), first = release")
        ->delimiter(',');
    cmd->add_option("--peaks-unit", options->peaks_unit, "unit of --peaks: rad or deg")
        ->capture_default_str()
        ->check(CLI::IsMember({"rad", "deg"}));
    cmd->add_option("--tilt", options->tilt_rad, "[rad] release tilt of the DEM runs (default: the first peak, or alpha / 2)");
    cmd->add_option("--impacts", options->impacts, "impacts measured per DEM run")->capture_default_str();
    cmd->add_option("--tolerance", options->tolerance, "on r: |achieved - target| at most this")->capture_default_str();
    cmd->add_option("--dt", options->dt_s, "[s] time step of the DEM runs (default: dt_safety x the stable limit, as a run)");
    cmd->add_option("--toml", options->toml_file, "also write the scenario keys to this file")->check(output_file());
    cmd->callback([options] { run_calibrate(*options); });
}

}  // namespace blockdem::cli
