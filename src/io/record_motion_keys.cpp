// Scenario keys of a record-driven or synthetic table motion component. Keys, units and
// defaults: docs/records.md. Physical values leave here in SI; "g" means 9.80665 m/s^2.
#include "io/record_motion_keys.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "motion/intensity_measures.hpp"
#include "motion/record_processing.hpp"
#include "motion/records/acceleration_units.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/synthetic_motion.hpp"

namespace blockdem {
namespace {

const std::vector<std::string> unit_choices{"m/s^2", "gal", "g"};
const std::vector<std::string> baseline_choices{"none", "mean", "linear", "polynomial", "displacement_polynomial"};

double non_negative(TableReader& keys, const std::string& key, double fallback) {
    const double v = keys.number_or(key, fallback);
    if (v < 0.0) keys.fail(key, fmt::format("must be >= 0, got {}", v));
    return v;
}

// target_pga with target_pga_unit, in m/s^2.
std::optional<double> target_pga(TableReader& keys) {
    const auto value = keys.optional_positive("target_pga");
    const std::string unit = keys.choice("target_pga_unit", unit_choices, "m/s^2");
    if (!value) return std::nullopt;
    return *value * *acceleration_unit_factor(unit);
}

BaselineCorrection baseline(TableReader& keys, const std::string& fallback) {
    BaselineCorrection c;
    c.method = parse_baseline_method(keys.choice("baseline", baseline_choices, fallback));
    const int lowest = c.method == BaselineMethod::displacement_polynomial ? 3 : 2;
    c.order = static_cast<int>(keys.whole_number_or("baseline_order", std::max(3, lowest), lowest, 6));
    return c;
}

RecordReadOptions read_options(TableReader& keys) {
    RecordReadOptions o;
    o.format = parse_record_format(keys.choice("format", {"auto", "peer-at2", "knet", "cosmos-v2", "jma-csv", "plain"}, "auto"));
    if (auto units = keys.optional_string("unit")) {
        if (!acceleration_unit_factor(*units)) keys.fail("unit", fmt::format("unknown unit '{}'; use one of: {}", *units, acceleration_unit_names));
        o.units = *units;
    }
    o.dt_s = keys.optional_positive("dt").value_or(0.0);
    if (o.dt_s != 0.0 && !(o.dt_s >= min_record_dt_s && o.dt_s <= max_record_dt_s))
        keys.fail("dt", fmt::format("the sample interval {:g} s is outside the accepted {:g} s to {:g} s", o.dt_s, min_record_dt_s,
                                    max_record_dt_s));
    o.component = keys.optional_string("component").value_or("");
    return o;
}

RecordProcessing processing(TableReader& keys) {
    RecordProcessing p;
    p.start_s = non_negative(keys, "start", 0.0);
    p.duration_s = keys.optional_positive("duration").value_or(0.0);
    p.taper_s = non_negative(keys, "taper", 0.0);
    p.pad_s = non_negative(keys, "pad", 0.0);
    p.baseline = baseline(keys, "none");
    const auto scale = keys.optional_number("scale");
    p.target_pga_m_s2 = target_pga(keys);
    if (scale && p.target_pga_m_s2) keys.fail("target_pga", "give either scale or target_pga, not both");
    p.scale = scale.value_or(1.0);
    return p;
}

// The checks of synthetic_ground_motion() that depend on one key, made here to name the key.
void check_synthetic_sizes(TableReader& keys, const SyntheticMotionParameters& p) {
    const double samples = std::round(p.duration_s / p.dt_s) + 1.0;
    if (!(samples <= static_cast<double>(max_record_samples)))
        keys.fail(p.dt_s < 1e-5 ? "dt" : "duration",
                  fmt::format("duration {:g} s at dt = {:g} s is {:g} samples; a motion may have at most {}", p.duration_s, p.dt_s,
                              samples, max_record_samples));
    const double nyquist_hz = 0.5 / p.dt_s;
    if (!(p.ground_frequency_hz < nyquist_hz))
        keys.fail("ground_frequency", fmt::format("{:g} Hz must be below the Nyquist frequency 1 / (2 dt) = {:g} Hz",
                                                  p.ground_frequency_hz, nyquist_hz));
    if (!(p.highpass_frequency_hz < nyquist_hz))
        keys.fail("highpass_frequency", fmt::format("{:g} Hz must be below the Nyquist frequency 1 / (2 dt) = {:g} Hz",
                                                    p.highpass_frequency_hz, nyquist_hz));
}

// A delay so long that delay + k dt no longer resolves dt (1e19 s) would make equal sample times.
void check_delay(TableReader& keys, double delay_s, double dt_s) {
    constexpr double max_delay_samples = 1e12;  // t keeps dt to 1e-4 of itself
    if (delay_s > max_delay_samples * dt_s)
        keys.fail("delay", fmt::format("a delay of {:g} s is more than {:g} samples of {:g} s: the sample times would lose dt "
                                       "to rounding",
                                       delay_s, max_delay_samples, dt_s));
}

// A vertical component (UP, UD, HNZ, ...) under [table_motion.horizontal] is almost always the
// wrong file of a record's three: refused unless accept_vertical says it is meant.
void check_direction(TableReader& keys, const GroundMotionRecord& record, bool accept_vertical) {
    const bool horizontal = keys.path().ends_with("horizontal");
    if (!horizontal || accept_vertical || !is_vertical_component(record.component)) return;
    keys.fail("file", fmt::format("the record's component is '{}', a vertical one, but it would drive the table "
                                  "horizontally: give a horizontal component's file (or its column with `component`), move "
                                  "it to [table_motion.vertical], or set accept_vertical = true if this is meant",
                                  record.component));
}

AccelerationSeries to_series(const std::vector<double>& a, double dt, double delay, std::string source) {
    std::vector<double> t(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) t[k] = delay + static_cast<double>(k) * dt;
    return make_acceleration_series(std::move(t), a, std::move(source));
}

}  // namespace

AccelerationSeries read_record_motion(TableReader& keys, const std::filesystem::path& scenario_dir) {
    const std::filesystem::path file = scenario_dir / keys.string("file");
    const RecordReadOptions options = read_options(keys);
    const RecordProcessing steps = processing(keys);
    const double delay = non_negative(keys, "delay", 0.0);
    const bool accept_vertical = keys.boolean_or("accept_vertical", false);
    keys.reject_unknown_keys();
    if (std::filesystem::is_directory(file))
        keys.fail("file", fmt::format("'{}' is a folder, not a record file", file.string()));
    if (!std::filesystem::is_regular_file(file)) keys.fail("file", fmt::format("no record file '{}'", file.string()));
    const GroundMotionRecord record = read_ground_motion_record(file, options);
    check_direction(keys, record, accept_vertical);
    try {
        padding_samples(record.npts(), record.dt_s, steps.pad_s);
    } catch (const std::invalid_argument& e) {
        keys.fail("pad", e.what());
    }
    std::vector<double> a;
    try {
        a = process_record(record.acceleration_m_s2, record.dt_s, steps);
    } catch (const std::invalid_argument& e) {
        keys.fail(steps.duration_s > 0.0 ? "duration" : "start", e.what());
    }
    const std::string source = fmt::format("{} ({}{}, baseline {})", file.string(), record_format_name(record.format),
                                           record.component.empty() ? "" : ", component " + record.component,
                                           baseline_method_name(steps.baseline.method));
    check_delay(keys, delay, record.dt_s);
    try {
        return to_series(a, record.dt_s, delay, source);
    } catch (const std::invalid_argument& e) {  // a finite record that `scale` takes beyond the range of a number
        keys.fail(steps.scale != 1.0 ? "scale" : "file", fmt::format("{}: {}", file.string(), e.what()));
    }
}

AccelerationSeries read_synthetic_motion(TableReader& keys) {
    SyntheticMotionParameters p;
    p.seed = static_cast<std::uint64_t>(keys.whole_number_or("seed", 1, 0, 2'000'000'000));
    p.duration_s = keys.optional_positive("duration").value_or(p.duration_s);
    p.dt_s = keys.optional_positive("dt").value_or(p.dt_s);
    const auto pga = target_pga(keys);
    if (!pga) keys.fail("", "missing required key 'target_pga' (with target_pga_unit: m/s^2, gal or g)");
    p.target_pga_m_s2 = *pga;
    p.ground_frequency_hz = keys.optional_positive("ground_frequency").value_or(p.ground_frequency_hz);
    p.ground_damping = keys.optional_positive("ground_damping").value_or(p.ground_damping);
    p.highpass_frequency_hz = non_negative(keys, "highpass_frequency", p.highpass_frequency_hz);
    p.highpass_damping = keys.optional_positive("highpass_damping").value_or(p.highpass_damping);
    p.envelope = parse_envelope_shape(keys.choice("envelope", {"saragoni_hart", "trapezoidal"}, "saragoni_hart"));
    p.peak_time_fraction = keys.optional_positive("peak_time_fraction").value_or(p.peak_time_fraction);
    p.end_level = keys.optional_positive("end_level").value_or(p.end_level);
    p.rise_time_s = non_negative(keys, "rise_time", p.rise_time_s);
    p.strong_duration_s = non_negative(keys, "strong_duration", p.strong_duration_s);
    check_synthetic_sizes(keys, p);
    // Filtered noise drifts in velocity: by default the table is brought back to rest.
    const BaselineCorrection correction = baseline(keys, "polynomial");
    const double pad = non_negative(keys, "pad", 0.0);
    const double delay = non_negative(keys, "delay", 0.0);
    keys.reject_unknown_keys();
    std::vector<double> a;
    try {
        a = synthetic_ground_motion(p);
    } catch (const std::invalid_argument& e) {
        keys.fail("", e.what());
    }
    try {
        padding_samples(a.size(), p.dt_s, pad);
    } catch (const std::invalid_argument& e) {
        keys.fail("pad", e.what());
    }
    // Pad first so that the correction brings the table to rest at the very end of the series;
    // the correction changes the peak slightly: scale back to the asked-for PGA.
    pad_with_zeros(a, p.dt_s, pad);
    a = correct_baseline(a, p.dt_s, correction);
    const double factor = scale_factor_for_pga(a, p.target_pga_m_s2);
    for (double& x : a) x *= factor;
    check_delay(keys, delay, p.dt_s);
    return to_series(a, p.dt_s, delay, fmt::format("synthetic Kanai-Tajimi motion, seed {}, PGA {:g} m/s^2", p.seed, p.target_pga_m_s2));
}

}  // namespace blockdem
