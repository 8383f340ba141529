#include "io/measurement_state_parts.hpp"

#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// A sensor as its state's layout and meaning depend on it: "top (filtered 50 Hz, order 4)".
std::vector<std::string> sensor_names(const SensorBank& bank) {
    std::vector<std::string> names;
    for (const SensorDef& d : bank.sensors())
        names.push_back(d.lowpass_hz > 0.0 ? fmt::format("{} (low-pass {:.17g} Hz, order {})", d.name, d.lowpass_hz, d.order)
                                           : fmt::format("{} (unfiltered)", d.name));
    return names;
}

// The numbers of an interface, one dataset each (the names are InterfaceState's fields).
struct NumberField {
    const char* name;
    double InterfaceState::*field;
};
constexpr NumberField number_fields[] = {
    {"normal_force_n", &InterfaceState::normal_force_n},
    {"shear_force_n", &InterfaceState::shear_force_n},
    {"opening_m", &InterfaceState::opening_m},
    {"slip_m", &InterfaceState::slip_m},
    {"peak_abs_slip_m", &InterfaceState::peak_abs_slip_m},
    {"peak_opening_m", &InterfaceState::peak_opening_m},
    {"first_touch_time_s", &InterfaceState::first_touch_time_s},
    {"first_break_time_s", &InterfaceState::first_break_time_s},
};

// Reads only the row count, before the writer (and so the part) exists.
class InterfaceRowsReader : public StatePart {
public:
    std::string state_group() const override { return "interfaces"; }
    void save_state(StateGroup&) const override {}
    void restore_state(const StateGroup& group) override { rows = group.integer("csv_rows"); }
    std::int64_t rows = 0;
};

}  // namespace

void SensorsStatePart::save_state(StateGroup& g) const {
    const SensorBankState s = writer_.bank().state();
    g.write("sensor", sensor_names(writer_.bank()));
    g.write("filter_state", s.filter_state);
    g.write("filter_started", s.filter_started);
    g.write("relative_start_m", s.relative_start_m);
    g.set("started", static_cast<std::int64_t>(s.started ? 1 : 0));
}

void SensorsStatePart::restore_state(const StateGroup& g) {
    SensorBank& bank = writer_.bank();
    const std::vector<std::string> names = sensor_names(bank);
    const std::vector<std::string> saved = g.strings("sensor");
    if (saved != names)
        throw InputError({g.file(), "", 0, 0},
                         fmt::format("the state's sensors ({}) are not the scenario's ([[sensors]]: {}): a restart keeps "
                                     "the sensors, as sensors.csv goes on",
                                     joined(saved), joined(names)));
    const SensorBankState now = bank.state();
    SensorBankState s;
    s.filter_state = g.doubles("filter_state", static_cast<std::int64_t>(now.filter_state.size()));
    s.filter_started = g.flags("filter_started", static_cast<std::int64_t>(now.filter_started.size()));
    s.relative_start_m = g.vectors("relative_start_m", static_cast<std::int64_t>(now.relative_start_m.size()));
    s.started = g.integer("started") != 0;
    bank.restore(s);
}

void InterfacesStatePart::save_state(StateGroup& g) const {
    const std::vector<InterfaceState>& list = writer_.monitor().interfaces();
    std::vector<std::uint32_t> body_a, body_b, points;
    std::vector<std::uint8_t> touching;
    for (const InterfaceState& s : list) {
        body_a.push_back(s.body_a);
        body_b.push_back(s.body_b);
        points.push_back(s.points);
        touching.push_back(s.touching ? 1 : 0);
    }
    g.write("body_a", body_a);
    g.write("body_b", body_b);
    g.write("points", points);
    g.write("touching", touching);
    for (const NumberField& f : number_fields) {
        std::vector<double> values;
        for (const InterfaceState& s : list) values.push_back(s.*f.field);
        g.write(f.name, values);
    }
    g.set("csv_rows", writer_.output_time_rows());
}

void InterfacesStatePart::restore_state(const StateGroup& g) {
    const std::vector<std::uint32_t> body_a = g.indices("body_a");
    const auto n = static_cast<std::int64_t>(body_a.size());
    const std::vector<std::uint32_t> body_b = g.indices("body_b", n);
    const std::vector<std::uint32_t> points = g.indices("points", n);
    const std::vector<std::uint8_t> touching = g.flags("touching", n);
    std::vector<InterfaceState> list(body_a.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
        if (body_a[k] >= world_.bodies.size() || body_b[k] >= world_.bodies.size() || body_a[k] == body_b[k])
            throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: /interfaces pair {} is "
                                                               "({}, {}), not two of the {} bodies",
                                                               k, body_a[k], body_b[k], world_.bodies.size()));
        list[k].body_a = body_a[k];
        list[k].body_b = body_b[k];
        list[k].points = points[k];
        list[k].touching = touching[k] != 0;
    }
    for (const NumberField& f : number_fields) {
        // (A state written before bonds existed has no first_break_time_s: nothing broke then.)
        if (!g.has(f.name) && f.field == &InterfaceState::first_break_time_s) continue;
        const std::vector<double> values = g.doubles(f.name, n);
        for (std::size_t k = 0; k < list.size(); ++k) list[k].*f.field = values[k];
    }
    try {
        writer_.restore(std::move(list), g.integer("csv_rows"));
    } catch (const std::invalid_argument& e) {
        throw InputError({g.file(), "", 0, 0}, fmt::format("{}: a restart keeps them, as interfaces.csv goes on", e.what()));
    }
}

std::int64_t interfaces_csv_rows(const StateFile& state) {
    InterfaceRowsReader reader;
    state.restore(reader);
    return reader.rows;
}

}  // namespace blockdem
