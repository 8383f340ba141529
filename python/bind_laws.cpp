// The small C++ functions the README's unit-level validation rows test, bound thinly so that
// Python can check them against its own references (docs/python.md, "Laws and filters"):
//   blockdem.restitution_no_tension(h_n), damping_ratio_rebound(e), damping_ratio_paper(e),
//   restitution_paper(h_n)                          laws/restitution.hpp
//   blockdem.contact_point_history(...)             laws/linear_spring_dashpot.hpp, one point
//   blockdem.joint_point_history(...)               laws/mohr_coulomb_joint.hpp, one dry point
//   blockdem.butterworth_magnitude(...), butterworth_filter(...)   signal/butterworth.hpp
// The histories drive one contact point through prescribed kinematics (one row per step) and
// return what the law gives at every step; the caller does the bookkeeping (work, balance).
// Nothing here is physics of its own: each function calls the law the time step calls.
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "laws/linear_spring_dashpot.hpp"
#include "laws/mohr_coulomb_joint.hpp"
#include "laws/restitution.hpp"
#include "python/bindings.hpp"
#include "signal/butterworth.hpp"

namespace py = pybind11;

namespace blockdem::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The prescribed kinematics, one entry per step, all of the same length.
struct KinematicsRows {
    std::vector<double> overlap_m, normal_speed_m_s, tangential_speed_m_s;
};

KinematicsRows kinematics_rows(const Array& overlap_m, const Array& normal_speed_m_s, const Array& tangential_speed_m_s) {
    const auto as_vector = [](const Array& a) { return std::vector<double>(a.data(), a.data() + a.size()); };
    KinematicsRows rows{as_vector(overlap_m), as_vector(normal_speed_m_s), as_vector(tangential_speed_m_s)};
    if (rows.normal_speed_m_s.size() != rows.overlap_m.size() || rows.tangential_speed_m_s.size() != rows.overlap_m.size())
        throw py::value_error(fmt::format("overlap, normal_speed and tangential_speed must have the same length "
                                          "({}, {}, {})", rows.overlap_m.size(), rows.normal_speed_m_s.size(),
                                          rows.tangential_speed_m_s.size()));
    return rows;
}

/// The law's output at every step, as numpy arrays keyed like ContactForce's fields.
struct ForceRows {
    std::vector<double> normal_n, shear_n, shear_spring_n, normal_dashpot_n, shear_dashpot_n;
    std::vector<double> normal_dashpot_work_j, shear_dashpot_work_j, friction_work_j, dilation_m;
    std::vector<bool> sliding;

    void add(const ContactForce& f, double dilation) {
        normal_n.push_back(f.normal_n);
        shear_n.push_back(f.shear_n);
        shear_spring_n.push_back(f.shear_spring_n);
        normal_dashpot_n.push_back(f.normal_dashpot_n);
        shear_dashpot_n.push_back(f.shear_dashpot_n);
        normal_dashpot_work_j.push_back(f.normal_dashpot_work_j);
        shear_dashpot_work_j.push_back(f.shear_dashpot_work_j);
        friction_work_j.push_back(f.friction_work_j);
        dilation_m.push_back(dilation);
        sliding.push_back(f.sliding);
    }

    py::dict to_dict() const {
        py::dict d;
        d["normal_N"] = py::array(py::cast(normal_n));
        d["shear_N"] = py::array(py::cast(shear_n));
        d["shear_spring_N"] = py::array(py::cast(shear_spring_n));
        d["normal_dashpot_N"] = py::array(py::cast(normal_dashpot_n));
        d["shear_dashpot_N"] = py::array(py::cast(shear_dashpot_n));
        d["normal_dashpot_work_J"] = py::array(py::cast(normal_dashpot_work_j));
        d["shear_dashpot_work_J"] = py::array(py::cast(shear_dashpot_work_j));
        d["friction_work_J"] = py::array(py::cast(friction_work_j));
        d["dilation_m"] = py::array(py::cast(dilation_m));
        d["sliding"] = py::array(py::cast(sliding));
        return d;
    }
};

py::dict contact_point_history(double kn, double ks, double mu, double cn, double cs, double dt,
                               const Array& overlap, const Array& normal_speed, const Array& tangential_speed,
                               bool zero_overlap) {
    require_positive(dt, "dt");
    const KinematicsRows rows = kinematics_rows(overlap, normal_speed, tangential_speed);
    ContactParameters p;
    p.kn_N_m = kn;
    p.ks_N_m = ks;
    p.mu = mu;
    p.termination = zero_overlap ? ContactTermination::zero_overlap : ContactTermination::no_tension;
    const DashpotCoefficients c{cn, cs};
    ForceRows out;
    ContactHistory history;
    for (std::size_t i = 0; i < rows.overlap_m.size(); ++i) {
        const ContactForce f = linear_spring_dashpot(
            p, c, {rows.overlap_m[i], rows.normal_speed_m_s[i], rows.tangential_speed_m_s[i]}, history, dt);
        out.add(f, 0.0);
        history = history_of(f);
    }
    return out.to_dict();
}

py::dict joint_point_history(double kn, double ks, double mu, double tan_dilation, double cn, double cs, double dt,
                             const Array& overlap, const Array& normal_speed, const Array& tangential_speed) {
    require_positive(dt, "dt");
    if (!(tan_dilation >= 0.0)) throw py::value_error(fmt::format("tan_dilation must be >= 0, got {}", tan_dilation));
    const KinematicsRows rows = kinematics_rows(overlap, normal_speed, tangential_speed);
    ContactParameters p;
    p.mu = mu;
    p.tan_dilation = tan_dilation;
    const JointPoint point{kn, ks, 1.0};
    const DashpotCoefficients c{cn, cs};
    ForceRows out;
    ContactHistory history;
    DilationHistory dilation;
    for (std::size_t i = 0; i < rows.overlap_m.size(); ++i) {
        const JointForce j = mohr_coulomb_joint(
            p, point, c, {rows.overlap_m[i], rows.normal_speed_m_s[i], rows.tangential_speed_m_s[i]}, history,
            BondState::none, dt, dilation);
        out.add(j.force, j.dilation_m);
        history = history_of(j.force);
        dilation = {j.dilation_m, j.force.normal_n};
    }
    return out.to_dict();
}

ButterworthDesign design(double cutoff_hz, int order, double sample_rate_hz) {
    try {
        return design_butterworth_lowpass(cutoff_hz, order, sample_rate_hz);
    } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
    }
}

}  // namespace

void bind_laws(py::module_& m) {
    // The C++ functions assume their domain (their callers check the scenario): checked here.
    const auto restitution_in_domain = [](double e) {
        if (!(e > 0.0 && e <= 1.0)) throw py::value_error(fmt::format("e must be in (0, 1], got {}", e));
        return e;
    };
    m.def("restitution_no_tension",
          [](double h_n) {
              if (!(h_n >= 0.0)) throw py::value_error(fmt::format("h_n must be >= 0, got {}", h_n));
              return restitution_no_tension(h_n);
          },
          py::arg("h_n"), "The rebound ratio of a no-tension linear spring-dashpot with damping ratio h_n (Schwager and Poeschel).");
    m.def("damping_ratio_rebound", [=](double e) { return damping_ratio_rebound(restitution_in_domain(e)); }, py::arg("e"),
          "The damping ratio for which a no-tension contact rebounds with e, 0 < e <= 1.");
    m.def("damping_ratio_paper", [=](double e) { return damping_ratio_paper(restitution_in_domain(e)); }, py::arg("e"),
          "Ohmachi and Arai's h_n = -ln e / sqrt(pi^2 + ln^2 e), 0 < e <= 1.");
    m.def("restitution_paper",
          [](double h_n) {
              if (!(h_n >= 0.0 && h_n < 1.0)) throw py::value_error(fmt::format("h_n must be in [0, 1), got {}", h_n));
              return restitution_paper(h_n);
          },
          py::arg("h_n"), "exp(-pi h / sqrt(1 - h^2)), 0 <= h_n < 1.");
    m.def("contact_point_history", &contact_point_history, py::arg("kn"), py::arg("ks"), py::arg("mu"),
          py::arg("cn") = 0.0, py::arg("cs") = 0.0, py::arg("dt"), py::arg("overlap"), py::arg("normal_speed"),
          py::arg("tangential_speed"), py::arg("zero_overlap") = false,
          "One point of the linear spring-dashpot law driven through prescribed kinematics (one entry per "
          "step: overlap [m], normal and tangential speed [m/s]); kn, ks [N/m], cn, cs [N s/m], dt [s]. "
          "Returns a dict of arrays: the forces on b [N] and each step's dissipation [J].");
    m.def("joint_point_history", &joint_point_history, py::arg("kn"), py::arg("ks"), py::arg("mu"),
          py::arg("tan_dilation") = 0.0, py::arg("cn") = 0.0, py::arg("cs") = 0.0, py::arg("dt"), py::arg("overlap"),
          py::arg("normal_speed"), py::arg("tangential_speed"),
          "One dry (unbonded) point of the per-length joint law, dilating by tan_dilation per unit of slip, "
          "driven as contact_point_history; kn, ks are the point's [N/m]. Adds dilation_m, the point's u_d.");
    m.def("butterworth_magnitude",
          [](double cutoff_hz, int order, double sample_rate_hz, const Array& frequency_hz) {
              const ButterworthDesign d = design(cutoff_hz, order, sample_rate_hz);
              std::vector<double> out;
              for (py::ssize_t i = 0; i < frequency_hz.size(); ++i) out.push_back(magnitude_response(d, frequency_hz.data()[i]));
              return py::array(py::cast(out));
          },
          py::arg("cutoff_hz"), py::arg("order"), py::arg("sample_rate_hz"), py::arg("frequency_hz"),
          "|H(f)| of the digital Butterworth low-pass (the sensors' filter) at each frequency [Hz].");
    m.def("butterworth_filter",
          [](double cutoff_hz, int order, double sample_rate_hz, const Array& samples) {
              ButterworthChannel channel(design(cutoff_hz, order, sample_rate_hz));
              std::vector<double> out;
              for (py::ssize_t i = 0; i < samples.size(); ++i) out.push_back(channel.filter(samples.data()[i]));
              return py::array(py::cast(out));
          },
          py::arg("cutoff_hz"), py::arg("order"), py::arg("sample_rate_hz"), py::arg("samples"),
          "The samples (at sample_rate_hz) through one sensor channel's Butterworth low-pass.");
}

}  // namespace blockdem::python
