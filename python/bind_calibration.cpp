// blockdem.calibrate_rocking: the fit of `blockdem calibrate` (study/rocking_calibration.hpp),
// the contact's h_n (or kn) for which a free-rocking block rebounds with a target restitution r.
//   fit = blockdem.calibrate_rocking(width=0.2, height=0.6, kn=1e7, target_restitution=0.8)
//   fit["found"], fit["h_n"], fit["kn"], fit["achieved_restitution"], fit["scan"] (runs x 2)
// The DEM runs and the search are the C++ ones; this only fills RockingBlock and copies the fit.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings.hpp"
#include "study/rocking_calibration.hpp"

namespace py = pybind11;

namespace blockdem::python {
namespace {

py::dict calibrate(double width_m, double height_m, double kn, std::optional<double> ks, double mu, double h_n,
                   double h_s, const std::string& termination, double density, std::optional<double> release_tilt,
                   double target, double tolerance, const std::string& parameter, int impacts) {
    require_positive(width_m, "width");
    require_positive(height_m, "height");
    require_positive(kn, "kn");
    require_positive(density, "density");
    require_positive(tolerance, "tolerance");
    if (!(target > 0.0 && target < 1.0)) throw py::value_error(fmt::format("target_restitution must be in (0, 1), got {}", target));
    if (termination != "no_tension" && termination != "zero_overlap")
        throw py::value_error(fmt::format("termination must be \"no_tension\" or \"zero_overlap\", got \"{}\"", termination));
    if (parameter != "h_n" && parameter != "kn")
        throw py::value_error(fmt::format("parameter must be \"h_n\" or \"kn\", got \"{}\"", parameter));
    if (impacts < 1) throw py::value_error(fmt::format("impacts must be >= 1, got {}", impacts));
    RockingBlock b;
    b.width_m = width_m;
    b.height_m = height_m;
    b.density_kg_m3 = density;
    b.contact.kn_N_m = kn;
    b.contact.ks_N_m = ks.value_or(kn);
    b.contact.mu = mu;
    b.contact.h_n = h_n;
    b.contact.h_s = h_s;
    b.contact.termination = termination == "zero_overlap" ? ContactTermination::zero_overlap : ContactTermination::no_tension;
    b.impacts = impacts;
    // As the CLI without --tilt: half the critical angle.
    b.release_tilt_rad = release_tilt.value_or(0.5 * b.alpha_rad());
    if (!(b.release_tilt_rad > 0.0 && b.release_tilt_rad < b.alpha_rad()))
        throw py::value_error(fmt::format("release_tilt must be in (0, alpha = {:.6g} rad), got {}", b.alpha_rad(),
                                          b.release_tilt_rad));
    // As the CLI: a block that cannot rock is refused before any DEM run (study/rocking_calibration.hpp).
    switch (rocking_obstacle(b)) {
        case RockingObstacle::none: break;
        case RockingObstacle::too_squat:
            throw py::value_error(fmt::format("width / height = {:.4g} is at least sqrt(2): Housner's r <= 0, so the block "
                                              "does not rock on after its first impact and there is no restitution to fit",
                                              width_m / height_m));
    }
    RockingFit fit;
    {
        py::gil_scoped_release release;
        fit = calibrate_rocking(b, parameter == "kn" ? CalibratedParameter::kn : CalibratedParameter::h_n, target, tolerance);
    }
    // As the CLI: a fitted run that gained energy at an impact slid or bounced, and is no rocking.
    if (const int k = first_energy_gaining_impact(fit.run); k >= 0)
        throw std::runtime_error(fmt::format("the fitted run gained energy at impact {}: r = {:.6g} >= 1, so the block slid or "
                                             "bounced instead of rocking on its corners; raise mu or h_s, or lower "
                                             "release_tilt", k + 1, fit.run.impact_restitution[static_cast<std::size_t>(k)]));
    py::dict d;
    d["found"] = fit.found;
    d["target_restitution"] = fit.target_restitution;
    d["achieved_restitution"] = fit.achieved_restitution;
    d["residual"] = fit.residual;
    d["h_n"] = fit.contact.h_n;
    d["kn"] = fit.contact.kn_N_m;
    d["ks"] = fit.contact.ks_N_m;
    d["dem_runs"] = fit.dem_runs;
    d["reachable_min"] = fit.reachable_min;
    d["reachable_max"] = fit.reachable_max;
    d["alpha_rad"] = b.alpha_rad();
    d["housner_restitution"] = housner_restitution(b.alpha_rad());
    d["impact_restitution"] = py::array(py::cast(fit.run.impact_restitution));
    d["peaks_rad"] = py::array(py::cast(fit.run.peaks_rad));
    d["dt"] = fit.run.dt_s;
    std::vector<std::array<double, 2>> scan;
    for (const auto& [value, r] : fit.scan) scan.push_back({value, r});
    d["scan"] = py::array(py::cast(scan));
    return d;
}

}  // namespace

void bind_calibration(py::module_& m) {
    m.def("calibrate_rocking", &calibrate, py::kw_only(), py::arg("width"), py::arg("height"), py::arg("kn"),
          py::arg("ks") = py::none(), py::arg("mu") = 0.8, py::arg("h_n") = 0.0, py::arg("h_s") = 1.0,
          py::arg("termination") = "no_tension", py::arg("density") = 2400.0, py::arg("release_tilt") = py::none(),
          py::arg("target_restitution"), py::arg("tolerance") = 1e-3, py::arg("parameter") = "h_n",
          py::arg("impacts") = 3,
          "The fit of `blockdem calibrate`: the h_n (parameter=\"h_n\", at kn) or kn (and ks in proportion; "
          "parameter=\"kn\", at h_n) for which a width x height [m] block released at release_tilt [rad] "
          "(default alpha/2) rocks freely with the target restitution r. Returns a dict (found, h_n, kn, "
          "achieved_restitution, residual, dem_runs, reachable_min/max, housner_restitution, scan).");
}

}  // namespace blockdem::python
