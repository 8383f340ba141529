#pragma once
// Calibrating the contact's normal damping to a measured rocking restitution (`blockdem
// calibrate`, docs/calibration.md).
//
// What is measured on a shake table: a block released from a tilt rocks freely, and every impact
// (the block passing upright, the pivot changing corner) multiplies its angular velocity by r.
// Between impacts the block turns rigidly about one corner, so each half cycle's energy fixes the
// angular velocity at the impact from the peak rotation on either side of it (Housner 1963):
//   r_k = sqrt((cos(alpha - theta_k+1) - cos alpha) / (cos(alpha - theta_k) - cos alpha)),
// alpha = atan(b / h). That is how r is read from a measured decay of amplitudes, and how it is
// read here from the DEM, so the two are the same quantity.
//
// The DEM run is the engine itself: a Model with a fixed table and the block tilted about one
// corner, built by build_world (the same dt rule as a run) and stepped by step(). The damping
// ratio h_n (or, on request, kn) is found by root-finding on r - r_target: a scan brackets the
// target, then the Illinois variant of regula falsi narrows the bracket until
// |r - r_target| <= tolerance.
#include <optional>
#include <vector>

#include "laws/contact_parameters.hpp"

namespace blockdem {

/// The free-rocking block and its contact with a rigid table.
struct RockingBlock {
    double width_m = 0.0;             ///< [m] 2b
    double height_m = 0.0;            ///< [m] 2h
    double density_kg_m3 = 2400.0;    ///< [kg/m^3]
    double thickness_m = 1.0;         ///< [m] out of plane
    double gravity_m_s2 = 9.81;       ///< [m/s^2]
    /// kn, ks, mu, h_n, h_s and the termination rule (the calibration varies h_n or kn).
    ContactParameters contact;
    double release_tilt_rad = 0.0;    ///< [rad] tilt at release, 0 < tilt < alpha
    std::optional<double> dt_s;       ///< [s] nullopt: dt_safety x the stable limit, as a run derives it
    int impacts = 3;                  ///< impacts measured per DEM run (r is their geometric mean)

    double alpha_rad() const;         ///< [rad] atan(b / h)
};

/// Housner's restitution 1 - 1.5 sin^2 alpha: a rigid block whose new pivot neither bounces nor slips.
double housner_restitution(double alpha_rad);

/// Why a block cannot rock freely on its corners as the calibration assumes.
enum class RockingObstacle {
    none,
    /// width / height >= sqrt 2: Housner's r = 1 - 1.5 sin^2 alpha <= 0, so a rigid block's first
    /// impact stops it (the angular momentum about the new corner is zero or reversed): it does
    /// not rock on, and no rocking restitution can be measured or fitted.
    too_squat,
};

/// The block's obstacle to rocking. Friction is not judged here: the static criterion mu >= b/h
/// refused blocks that rock cleanly (a free-rocking block needs less: about 0.6 to 0.75 b/h at
/// an impact), and a block that does slip shows it as an impact with r >= 1
/// (first_energy_gaining_impact), which the fit's callers refuse.
RockingObstacle rocking_obstacle(const RockingBlock& block);

/// r of each impact from successive peak rotations |theta_0|, |theta_1|, ... [rad] (the first
/// the release or an earlier peak), by the energy of rigid rocking between impacts.
std::vector<double> restitution_from_peaks(double alpha_rad, const std::vector<double>& peaks_rad);

/// The geometric mean of per-impact ratios (the ratio that gives the same total decay).
double geometric_mean(const std::vector<double>& ratios);

/// One DEM free-rocking run.
struct FreeRocking {
    std::vector<double> peaks_rad;        ///< [rad] |theta| at release and after each impact
    std::vector<double> impact_restitution;  ///< [-] r of each impact, from the peaks
    double restitution = 0.0;             ///< [-] their geometric mean; 0 if the block stopped rocking
    double dt_s = 0.0;                    ///< [s] the time step used
    long long steps = 0;                  ///< steps taken
    bool overturned = false;              ///< the block toppled (then no r is measured)
};

/// Index of the first impact whose r is >= 1 (an impact that gained energy: the block slid or
/// bounced, so its peaks are not those of rigid rocking), or -1.
int first_energy_gaining_impact(const FreeRocking& run);

/// Releases the block from its tilt with its contact (block.contact, h_n included) and measures
/// block.impacts impacts. Throws ModelError (world/world.hpp) for a block the engine refuses
/// (e.g. a given dt above the stable limit).
FreeRocking free_rocking(const RockingBlock& block);

/// Which contact parameter a calibration fits (the other ones stay as given).
enum class CalibratedParameter {
    h_n,  ///< the normal damping ratio, at the given kn
    kn,   ///< the normal stiffness (and ks in proportion), at the given h_n
};

/// The result of a calibration.
struct RockingFit {
    CalibratedParameter parameter = CalibratedParameter::h_n;
    bool found = false;              ///< |achieved - target| <= tolerance
    double target_restitution = 0.0; ///< [-]
    ContactParameters contact;       ///< the contact of the best run: the fitted h_n or kn (and ks) in it
    double achieved_restitution = 0.0;  ///< [-] r of the DEM with that contact
    double residual = 0.0;           ///< [-] achieved - target
    int dem_runs = 0;                ///< free-rocking runs made
    double reachable_min = 0.0;      ///< [-] least r seen over the scan
    double reachable_max = 0.0;      ///< [-] greatest r seen over the scan
    double value_at_min = 0.0;       ///< the fitted parameter's value where the least r was seen
    double value_at_max = 0.0;       ///< likewise for the greatest
    FreeRocking run;                 ///< the DEM run of the best contact
    std::vector<std::pair<double, double>> scan;  ///< (parameter value, r) of every run, in the order made
};

/// The h_n values scanned to bracket the target: from 0.02 (an undamped contact chatters and
/// its rocking has no steady r) to the largest damping the termination rule admits with a
/// coefficient of restitution (h_n < 1 for zero_overlap; up to 3 for no_tension, where e tends
/// to 0 only as h_n grows without bound).
std::vector<double> scanned_damping_ratios(ContactTermination termination);

/// The kn values scanned: the given kn times 10^(1, 0.5, 0, ..., -3). A softer contact makes the
/// impact last longer against the rocking period, and its dashpot takes more of the energy.
std::vector<double> scanned_stiffnesses(double kn_N_m);

/// Finds the parameter such that the DEM's free rocking gives target_restitution within
/// tolerance (both [-]); block.contact holds the starting kn, ks, h_n and the rest. kn is fitted
/// on a log scale with ks kept in proportion. When no scanned value brackets the target, found
/// is false and reachable_min/max say what this contact can give.
RockingFit calibrate_rocking(const RockingBlock& block, CalibratedParameter parameter, double target_restitution,
                             double tolerance);

}  // namespace blockdem
