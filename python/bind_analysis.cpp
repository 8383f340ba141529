// The project's independent references and record tools, bound as they are (docs/python.md,
// "Analysis"): table motions (motion/table_motion), Housner's rocking block
// (analysis/housner_rocking), Newmark's rigid-plastic sliding block (analysis/
// rigid_plastic_sliding), response spectra and intensity measures (motion/response_spectrum,
// intensity_measures), reading and processing records (motion/records, record_processing).
// Nothing is computed here: arguments go in, the C++ results come out as numpy arrays and dicts.
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "analysis/housner_rocking.hpp"
#include "analysis/rigid_plastic_sliding.hpp"
#include "motion/intensity_measures.hpp"
#include "motion/record_processing.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/table_motion.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace blockdem::python {
namespace {

using Samples = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A 1-D array of finite samples, copied (the C++ functions take spans or vectors).
std::vector<double> finite_samples(const Samples& a, const char* name) {
    if (a.ndim() != 1) throw py::value_error(fmt::format("{}: a 1-D array is needed, this one has {} dimensions", name, a.ndim()));
    std::vector<double> v(a.data(), a.data() + a.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i])) throw py::value_error(fmt::format("{}: sample {} is not finite ({})", name, i, v[i]));
    return v;
}

double positive(double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value)) throw py::value_error(fmt::format("{} must be positive and finite, got {}", name, value));
    return value;
}

/// A motion's start [s]: finite and >= 0, as the scenario's `start` key (a motion starts at rest).
double start_time(double start_s) {
    if (!(start_s >= 0.0) || !std::isfinite(start_s))
        throw py::value_error(fmt::format("start must be >= 0 and finite [s], got {}: a motion starts at rest, and one "
                                          "that started before t = 0 would have the table already moving when the run "
                                          "begins", start_s));
    return start_s;
}

/// A motion's amplitude [m/s^2]: finite and within the scenario's bound (io/scenario_keys.hpp).
double amplitude(double amplitude_m_s2) {
    if (!(std::abs(amplitude_m_s2) <= max_table_acceleration_m_s2))
        throw py::value_error(fmt::format("amplitude {} m/s^2 is beyond the {:g} m/s^2 that any earthquake, shaking "
                                          "table or centrifuge model asks for: check the value and its unit",
                                          amplitude_m_s2, max_table_acceleration_m_s2));
    return amplitude_m_s2;
}

py::array_t<double> to_array(const std::vector<double>& v) { return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data()); }

/// A table motion of one component, as the scenario's [table_motion.*] types make them.
struct Motion {
    ComponentMotion motion;
};

Motion series_motion(const Samples& acceleration, double dt_s, double start_s) {
    positive(dt_s, "dt");
    start_time(start_s);
    std::vector<double> a = finite_samples(acceleration, "accelerations");
    for (const double a_m_s2 : a) amplitude(a_m_s2);
    std::vector<double> t(a.size());
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = start_s + static_cast<double>(k) * dt_s;
    return {make_acceleration_series(std::move(t), std::move(a), "numpy array")};
}

void bind_motion(py::module_& m) {
    py::class_<Motion>(m, "Motion", "A table motion of one component (docs/scenario.md, [table_motion]); SI units.")
        .def_static("rest", [] { return Motion{RestMotion{}}; })
        .def_static(
            "sine",
            [](double amplitude_m_s2, double period_s, double phase_rad, double start_s, double cycles) {
                if (!(cycles >= 0.0) || !std::isfinite(cycles))
                    throw py::value_error(fmt::format("cycles must be >= 0 and finite (0: no end), got {}", cycles));
                if (!std::isfinite(phase_rad)) throw py::value_error(fmt::format("phase must be finite, got {}", phase_rad));
                return Motion{SineMotion{amplitude(amplitude_m_s2), positive(period_s, "period"), phase_rad,
                                         start_time(start_s), cycles}};
            },
            py::arg("amplitude"), py::arg("period"), py::arg("phase") = 0.0, py::arg("start") = 0.0, py::arg("cycles") = 0.0,
            "a = amplitude sin(2 pi (t - start) / period + phase) [m/s^2, s, rad]; cycles = 0: no end")
        .def_static(
            "one_sine",
            [](double amplitude_m_s2, double period_s, double start_s) {
                return Motion{PulseMotion{PulseMotion::Shape::one_sine, amplitude(amplitude_m_s2), positive(period_s, "period"),
                                          start_time(start_s)}};
            },
            py::arg("amplitude"), py::arg("period"), py::arg("start") = 0.0, "One-sine pulse [m/s^2, s]")
        .def_static(
            "one_cosine",
            [](double amplitude_m_s2, double period_s, double start_s) {
                return Motion{PulseMotion{PulseMotion::Shape::one_cosine, amplitude(amplitude_m_s2), positive(period_s, "period"),
                                          start_time(start_s)}};
            },
            py::arg("amplitude"), py::arg("period"), py::arg("start") = 0.0, "One-cosine pulse [m/s^2, s]")
        .def_static(
            "ricker",
            [](double amplitude_m_s2, double peak_frequency_hz, double center_time_s) {
                if (!std::isfinite(center_time_s))
                    throw py::value_error(fmt::format("center_time must be finite [s], got {}", center_time_s));
                return Motion{RickerMotion{amplitude(amplitude_m_s2), positive(peak_frequency_hz, "peak_frequency"),
                                           center_time_s}};
            },
            py::arg("amplitude"), py::arg("peak_frequency"), py::arg("center_time") = 1.0, "Ricker wavelet [m/s^2, Hz, s]")
        .def_static("series", &series_motion, py::arg("accelerations"), py::arg("dt"), py::arg("start") = 0.0,
                    "Accelerations [m/s^2] at start + k dt, linear between samples, zero after the last")
        .def(
            "sample",
            [](const Motion& self, double t_s) {
                const MotionSample s = sample(self.motion, t_s);
                py::dict d;
                d["displacement"] = s.displacement_m;
                d["velocity"] = s.velocity_m_s;
                d["acceleration"] = s.acceleration_m_s2;
                return d;
            },
            py::arg("t"), "Displacement [m], velocity [m/s] and acceleration [m/s^2] at t [s]")
        .def_property_readonly("peak_acceleration", [](const Motion& self) { return peak_acceleration(self.motion); },
                               "[m/s^2]")
        .def("__repr__", [](const Motion& self) { return "<blockdem.Motion " + describe(self.motion) + ">"; });
}

void bind_references(py::module_& m) {
    m.def(
        "housner_rocking",
        [](double half_width_m, double half_height_m, const Motion& base, double end_s, double dt_s, double theta0_rad,
           double omega0_rad_s, double restitution, double gravity_m_s2) {
            HousnerBlock block{positive(half_width_m, "half_width"), positive(half_height_m, "half_height"),
                               positive(gravity_m_s2, "gravity"), restitution};
            RockingResult r;
            {
                py::gil_scoped_release release;
                r = housner_rocking(block, base.motion, theta0_rad, omega0_rad_s, positive(end_s, "end"), positive(dt_s, "dt"));
            }
            std::vector<double> t, theta, omega;
            for (const auto& p : r.history) {
                t.push_back(p.time_s);
                theta.push_back(p.theta_rad);
                omega.push_back(p.omega_rad_s);
            }
            py::dict d;
            d["t"] = to_array(t);
            d["theta"] = to_array(theta);
            d["omega"] = to_array(omega);
            d["impact_times"] = to_array(r.impact_times_s);
            d["overturned"] = r.overturned;
            d["peak_theta"] = r.peak_abs_theta_rad;
            d["alpha"] = block.alpha_rad();
            d["p"] = block.p_rad_s();
            d["restitution"] = block.restitution < 0.0 ? block.housner_restitution() : block.restitution;
            return d;
        },
        py::arg("half_width"), py::arg("half_height"), py::arg("motion"), py::arg("end"), py::arg("dt") = 1.0e-4,
        py::arg("theta0") = 0.0, py::arg("omega0") = 0.0, py::arg("restitution") = -1.0, py::arg("gravity") = 9.81,
        "Housner's rocking block (half sizes b, h [m]) on a base moving by `motion`, RK4 to `end` [s]; "
        "restitution < 0: Housner's 1 - 1.5 sin^2 alpha. Returns t, theta [rad], omega [rad/s], impact_times, "
        "overturned, peak_theta, alpha, p [rad/s], restitution.");

    m.def(
        "rigid_plastic_sliding",
        [](const Motion& table, double mu, double end_s, double dt_s, double slope_rad, double gravity_m_s2) {
            positive(gravity_m_s2, "gravity");
            if (!(mu >= 0.0)) throw py::value_error(fmt::format("mu must be >= 0, got {}", mu));
            const SlidingSurface surface = incline_surface(mu, slope_rad, gravity_m_s2);
            std::vector<SlidingPoint> points;
            {
                py::gil_scoped_release release;
                points = rigid_plastic_sliding(table.motion, surface, positive(end_s, "end"), positive(dt_s, "dt"));
            }
            std::vector<double> t, u, v, a;
            for (const auto& p : points) {
                t.push_back(p.time_s);
                u.push_back(p.relative_displacement_m);
                v.push_back(p.relative_velocity_m_s);
                a.push_back(p.block_acceleration_m_s2);
            }
            py::dict d;
            d["t"] = to_array(t);
            d["displacement"] = to_array(u);
            d["velocity"] = to_array(v);
            d["block_acceleration"] = to_array(a);
            return d;
        },
        py::arg("motion"), py::arg("mu"), py::arg("end"), py::arg("dt") = 1.0e-4, py::arg("slope") = 0.0,
        py::arg("gravity") = 9.81,
        "Newmark's rigid-plastic block on a table moving along its surface (slope [rad], +s up the slope). "
        "Returns t, displacement [m] and velocity [m/s] relative to the table, block_acceleration [m/s^2].");
}

py::dict measures_dict(const IntensityMeasures& im) {
    py::dict d;
    d["pga"] = im.pga_m_s2;
    d["pga_signed"] = im.pga_signed_m_s2;
    d["pga_time"] = im.pga_time_s;
    d["pgv"] = im.pgv_m_s;
    d["pgv_time"] = im.pgv_time_s;
    d["pgd"] = im.pgd_m;
    d["pgd_time"] = im.pgd_time_s;
    d["final_velocity"] = im.final_velocity_m_s;
    d["final_displacement"] = im.final_displacement_m;
    d["arias"] = im.arias_m_s;
    d["t5"] = im.t5_s;
    d["t75"] = im.t75_s;
    d["t95"] = im.t95_s;
    d["d5_95"] = im.d5_95_s;
    d["d5_75"] = im.d5_75_s;
    d["bracketed_duration"] = im.bracketed_duration_s;
    return d;
}

void bind_records(py::module_& m) {
    m.def(
        "response_spectrum",
        [](const Samples& acceleration, double dt_s, std::optional<std::vector<double>> periods_s, double damping_ratio,
           const std::string& method) {
            SpectrumOptions options;
            options.damping_ratio = damping_ratio;
            if (periods_s) options.periods_s = *periods_s;
            options.method = parse_spectrum_method(method);
            const std::vector<double> a = finite_samples(acceleration, "accelerations");
            std::vector<SpectrumOrdinate> ordinates;
            {
                py::gil_scoped_release release;
                ordinates = response_spectrum(a, positive(dt_s, "dt"), options);
            }
            std::vector<double> period, sd, psv, psa;
            for (const auto& o : ordinates) {
                period.push_back(o.period_s);
                sd.push_back(o.sd_m);
                psv.push_back(o.psv_m_s);
                psa.push_back(o.psa_m_s2);
            }
            py::dict d;
            d["period"] = to_array(period);
            d["sd"] = to_array(sd);
            d["psv"] = to_array(psv);
            d["psa"] = to_array(psa);
            return d;
        },
        py::arg("accelerations"), py::arg("dt"), py::arg("periods") = py::none(), py::arg("damping") = 0.05,
        py::arg("method") = "exact",
        "Elastic spectrum of accelerations [m/s^2] at dt [s]: period [s], sd [m], psv [m/s], psa [m/s^2]. "
        "periods None: 0.01 to 10 s; method \"exact\" or \"newmark\".");

    m.def(
        "intensity_measures",
        [](const Samples& acceleration, double dt_s) {
            return measures_dict(intensity_measures(finite_samples(acceleration, "accelerations"), positive(dt_s, "dt")));
        },
        py::arg("accelerations"), py::arg("dt"),
        "PGA [m/s^2], PGV [m/s], PGD [m], Arias [m/s], t5/t75/t95, d5_95, d5_75, bracketed_duration [s] (docs/records.md).");

    m.def(
        "integrate_record",
        [](const Samples& acceleration, double dt_s) {
            const RecordKinematics k = integrate_record(finite_samples(acceleration, "accelerations"), positive(dt_s, "dt"));
            py::dict d;
            d["velocity"] = to_array(k.velocity_m_s);
            d["displacement"] = to_array(k.displacement_m);
            return d;
        },
        py::arg("accelerations"), py::arg("dt"), "Velocity [m/s] and displacement [m] at the samples, from rest.");

    m.def(
        "process_record",
        [](const Samples& acceleration, double dt_s, double start_s, double duration_s, double taper_s, double pad_s,
           const std::string& baseline, int baseline_order, double scale, std::optional<double> target_pga_m_s2) {
            RecordProcessing steps;
            steps.start_s = start_s;
            steps.duration_s = duration_s;
            steps.taper_s = taper_s;
            steps.pad_s = pad_s;
            steps.baseline = {parse_baseline_method(baseline), baseline_order};
            steps.scale = scale;
            steps.target_pga_m_s2 = target_pga_m_s2;
            return to_array(process_record(finite_samples(acceleration, "accelerations"), positive(dt_s, "dt"), steps));
        },
        py::arg("accelerations"), py::arg("dt"), py::arg("start") = 0.0, py::arg("duration") = 0.0, py::arg("taper") = 0.0,
        py::arg("pad") = 0.0, py::arg("baseline") = "none", py::arg("baseline_order") = 3, py::arg("scale") = 1.0,
        py::arg("target_pga") = py::none(),
        "window -> taper -> pad -> baseline -> scale (docs/records.md); SI units; returns accelerations [m/s^2].");

    m.def(
        "read_record",
        [](const std::filesystem::path& file, const std::string& format, const std::string& units, double dt_s,
           const std::string& component) {
            RecordReadOptions options;
            options.format = parse_record_format(format);
            options.units = units;
            options.dt_s = dt_s;
            options.component = component;
            const GroundMotionRecord r = read_ground_motion_record(file, options);
            py::dict d;
            d["file"] = r.file;
            d["format"] = std::string(record_format_name(r.format));
            d["event"] = r.event;
            d["station"] = r.station;
            d["component"] = r.component;
            d["units_in_file"] = r.units_in_file;
            d["to_m_s2"] = r.to_m_s2;
            d["dt"] = r.dt_s;
            d["accelerations"] = to_array(r.acceleration_m_s2);
            d["notes"] = r.notes;
            return d;
        },
        py::arg("file"), py::arg("format") = "auto", py::arg("units") = "", py::arg("dt") = 0.0, py::arg("component") = "",
        "Reads a strong-motion record (PEER AT2, K-NET, COSMOS V2, JMA CSV, plain text): accelerations [m/s^2] at dt [s] "
        "and the header's facts. Bad files raise blockdem.InputError naming the file and line.");
}

}  // namespace

void bind_analysis(py::module_& m) {
    bind_motion(m);
    bind_references(m);
    bind_records(m);
}

}  // namespace blockdem::python
