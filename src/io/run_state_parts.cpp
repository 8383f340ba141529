#include "io/run_state_parts.hpp"

#include <cmath>

#include "io/input_error.hpp"
#include "world/simulation.hpp"

namespace blockdem {
namespace {

// The monitor's numbers per body, one dataset each (the names are BodyResponse's fields).
struct NumberField {
    const char* name;
    double BodyResponse::*field;
};
constexpr NumberField number_fields[] = {
    {"alpha_ccw_rad", &BodyResponse::alpha_ccw_rad},
    {"alpha_cw_rad", &BodyResponse::alpha_cw_rad},
    {"base_tilt_rad", &BodyResponse::base_tilt_rad},
    {"base_length_m", &BodyResponse::base_length_m},
    {"peak_abs_rotation_rad", &BodyResponse::peak_abs_rotation_rad},
    {"time_of_peak_rotation_s", &BodyResponse::time_of_peak_rotation_s},
    {"last_crossing_s", &BodyResponse::last_crossing_s},
    {"peak_abs_relative_displacement_m", &BodyResponse::peak_abs_relative_displacement_m},
    {"base_slip_m", &BodyResponse::base_slip_m},
    {"peak_abs_base_slip_m", &BodyResponse::peak_abs_base_slip_m},
    {"sliding_time_s", &BodyResponse::sliding_time_s},
    {"rocking_threshold_rad", &BodyResponse::rocking_threshold_rad},
    {"slip_threshold_m", &BodyResponse::slip_threshold_m},
    {"rocking_onset_s", &BodyResponse::rocking_onset_s},
    {"slip_onset_s", &BodyResponse::slip_onset_s},
    {"height_m", &BodyResponse::height_m},
    {"support_lost_time_s", &BodyResponse::support_lost_time_s},
    {"drop_time_s", &BodyResponse::drop_time_s},
    {"start_rotation_rad", &BodyResponse::start_rotation_rad},
    {"peak_abs_rotation_on_support_rad", &BodyResponse::peak_abs_rotation_on_support_rad},
    {"peak_elastic_shear_m", &BodyResponse::peak_elastic_shear_m},
};

struct VectorField {
    const char* name;
    Vec2 BodyResponse::*field;
};
constexpr VectorField vector_fields[] = {
    {"base_left_offset_m", &BodyResponse::base_left_offset_m},
    {"base_right_offset_m", &BodyResponse::base_right_offset_m},
    {"relative_displacement_m", &BodyResponse::relative_displacement_m},
};

struct FlagField {
    const char* name;
    bool BodyResponse::*field;
    bool absent_means_true = false;  ///< a flag that states from before it lack: taken as true
};
constexpr FlagField flag_fields[] = {
    {"beyond_alpha", &BodyResponse::beyond_alpha},
    {"touches_a_supporter", &BodyResponse::touches_a_supporter},
    {"at_rest", &BodyResponse::at_rest},
    {"touched_a_body", &BodyResponse::touched_a_body, true},
    {"rested_on_ground", &BodyResponse::rested_on_ground, true},
};

}  // namespace

void MonitorStatePart::save_state(StateGroup& g) const {
    const std::vector<BodyResponse>& r = monitor_.responses();
    for (const NumberField& f : number_fields) {
        std::vector<double> values;
        for (const BodyResponse& body : r) values.push_back(body.*f.field);
        g.write(f.name, values);
    }
    for (const VectorField& f : vector_fields) {
        std::vector<Vec2> values;
        for (const BodyResponse& body : r) values.push_back(body.*f.field);
        g.write(f.name, values);
    }
    for (const FlagField& f : flag_fields) {
        std::vector<std::uint8_t> values;
        for (const BodyResponse& body : r) values.push_back(body.*f.field ? 1 : 0);
        g.write(f.name, values);
    }
    // Each body's supporters: supporters[supporters_start[i] .. supporters_start[i + 1]).
    std::vector<std::uint32_t> start{0}, supporters;
    for (const BodyResponse& body : r) {
        supporters.insert(supporters.end(), body.supporters.begin(), body.supporters.end());
        start.push_back(static_cast<std::uint32_t>(supporters.size()));
    }
    g.write("supporters_start", start);
    g.write("supporters", supporters);
    std::vector<std::int64_t> support_body;
    for (const BodyResponse& body : r) support_body.push_back(body.support_body);
    g.write("support_body", support_body);
    g.set("start_level_rad", monitor_.start_level_rad());
}

void MonitorStatePart::restore_state(const StateGroup& g) {
    std::vector<BodyResponse> r = monitor_.responses();
    const auto n = static_cast<std::int64_t>(r.size());
    for (const NumberField& f : number_fields) {
        const std::vector<double> values = g.doubles(f.name, n);
        for (std::size_t i = 0; i < r.size(); ++i) r[i].*f.field = values[i];
    }
    for (const VectorField& f : vector_fields) {
        const std::vector<Vec2> values = g.vectors(f.name, n);
        for (std::size_t i = 0; i < r.size(); ++i) r[i].*f.field = values[i];
    }
    for (const FlagField& f : flag_fields) {
        const std::vector<std::uint8_t> values = f.absent_means_true && !g.has(f.name) ? std::vector<std::uint8_t>(n, 1) : g.flags(f.name, n);
        for (std::size_t i = 0; i < r.size(); ++i) r[i].*f.field = values[i] != 0;
    }
    const std::vector<std::uint32_t> start = g.indices("supporters_start", n + 1);
    const std::vector<std::uint32_t> supporters = g.indices("supporters", start.back());
    for (std::size_t i = 0; i < r.size(); ++i) {
        if (start[i] > start[i + 1])
            throw InputError({g.file(), "", 0, 0}, "not a readable blockdem state file: /monitor/supporters_start is not "
                                                   "increasing");
        r[i].supporters.assign(supporters.begin() + start[i], supporters.begin() + start[i + 1]);
    }
    const std::vector<std::int64_t> support_body = g.integers("support_body", n);
    for (std::size_t i = 0; i < r.size(); ++i) {
        if (support_body[i] < -1 || support_body[i] >= n)
            throw InputError({g.file(), "", 0, 0}, "not a readable blockdem state file: /monitor/support_body names no body");
        r[i].support_body = support_body[i];
    }
    monitor_.restore(std::move(r), g.number("start_level_rad"));
}

void VtkStatePart::save_state(StateGroup& g) const { g.write("frame_time_s", writer_.frame_times_s()); }

void VtkStatePart::restore_state(const StateGroup& g) {
    const std::int64_t every = steps_per_output(world_);
    std::vector<double> kept;
    for (double t_s : g.doubles("frame_time_s")) {
        const std::int64_t step = std::llround(t_s / world_.dt_s);
        if (step < world_.step_index && step % every == 0) kept.push_back(t_s);
    }
    writer_.resume(std::move(kept), world_.dt_s);
}

}  // namespace blockdem
