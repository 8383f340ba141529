#include "io/sensor_keys.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

namespace blockdem {
namespace {

constexpr int max_filter_order = 8;

std::uint32_t body_named(TableReader& t, const std::string& key, const World& w) {
    const std::string name = t.string(key);
    const auto& names = w.bodies.name;
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) {
        const std::string near = nearest(name, names);
        t.fail(key, fmt::format("no body is named '{}'{}", name, near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near)));
    }
    return static_cast<std::uint32_t>(found - names.begin());
}

// The point must lie in the body (or on its outline, to a micrometre in a metre).
Vec2 point_in_body(TableReader& t, const std::string& key, const World& w, std::uint32_t body) {
    const auto p = t.optional_vec2(key);
    if (!p) t.fail_missing(key, " [m]: [x, y] in the body's own frame, from its centroid");
    const Bodies& b = w.bodies;
    const double tolerance_m = 1e-6 * b.bounding_radius_m[body];
    Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    bool inside = true;
    const std::uint32_t first = b.vertex_begin[body];
    const std::uint32_t count = b.vertex_count[body];
    for (std::uint32_t k = 0; k < count; ++k) {
        const Vec2 v = b.local_vertices_m[first + k];
        const Vec2 next = b.local_vertices_m[first + (k + 1) % count];
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
        // Counter-clockwise corners: the inside is to the left of every edge.
        if (cross(normalized(next - v), *p - v) < -tolerance_m) inside = false;
    }
    if (!inside)
        t.fail(key, fmt::format("[{:g}, {:g}] m lies outside body '{}'; the point is measured from the body's centroid in "
                                "its own frame, where the body spans x from {:.4g} to {:.4g} m and y from {:.4g} to {:.4g} m",
                                p->x, p->y, b.name[body], lo.x, hi.x, lo.y, hi.y));
    return *p;
}

void read_filter(TableReader& t, const World& w, SensorDef& s) {
    const auto cutoff = t.optional_positive("lowpass_hz");
    const auto order = t.optional_whole_number("order", 1, max_filter_order);
    if (order && !cutoff) t.fail("order", "is the order of the low-pass filter: give lowpass_hz [Hz] too");
    if (!cutoff) return;
    const double nyquist_hz = 0.5 / w.dt_s;
    if (*cutoff >= nyquist_hz)
        t.fail("lowpass_hz", fmt::format("{:g} Hz is at or above the Nyquist frequency of the time step, 1/(2 dt) = {:.6g} Hz "
                                         "(dt = {:.4g} s): the filter runs at every step and cannot pass more",
                                         *cutoff, nyquist_hz, w.dt_s));
    s.lowpass_hz = *cutoff;
    s.order = static_cast<int>(order.value_or(s.order));
}

SensorDef read_sensor(TableReader t, const World& w) {
    SensorDef s;
    s.name = t.string("name");
    if (s.name.empty() || s.name.find_first_of(",\"\n\r# ") != std::string::npos)
        t.fail("name", fmt::format("'{}' cannot be a column prefix in sensors.csv: use a name without spaces, commas, "
                                   "quotes or '#'", s.name));
    s.kind = t.choice("kind", {"point", "relative"}, "point") == "point" ? SensorKind::point : SensorKind::relative;
    s.body = body_named(t, "body", w);
    s.point_m = point_in_body(t, "point", w, s.body);
    if (s.kind == SensorKind::relative) {
        s.body2 = body_named(t, "body2", w);
        s.point2_m = point_in_body(t, "point2", w, s.body2);
    } else if (t.has("body2") || t.has("point2")) {
        t.fail(t.has("body2") ? "body2" : "point2", "belongs to a relative sensor: add kind = \"relative\"");
    }
    read_filter(t, w, s);
    t.reject_unknown_keys();
    return s;
}

InterfaceSelection read_interface_selection(TableReader& output, const World& w) {
    InterfaceSelection selection;
    const bool small = w.bodies.size() <= interfaces_auto_max_bodies;
    const toml::node* node = output.raw().get("interfaces");
    output.allow({"interfaces"});
    if (!node) {
        selection.all = small;
        return selection;
    }
    if (node->is_string()) {
        const std::string mode = output.choice("interfaces", {"auto", "all", "none"}, "auto");
        selection.all = mode == "all" || (mode == "auto" && small);
        return selection;
    }
    const toml::array* pairs = node->as_array();
    const std::string usage = "is \"auto\", \"all\", \"none\" or a list of body pairs, [[\"a\", \"b\"], ...]";
    if (!pairs) output.fail("interfaces", usage);
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (std::size_t i = 0; i < pairs->size(); ++i) {
        const toml::array* pair = (*pairs)[i].as_array();
        if (!pair || pair->size() != 2 || !(*pair)[0].is_string() || !(*pair)[1].is_string())
            output.fail("interfaces", fmt::format("entry {} {}", i + 1, usage));
        std::uint32_t ids[2];
        for (int k = 0; k < 2; ++k) {
            const std::string name = *(*pair)[static_cast<std::size_t>(k)].value<std::string>();
            const auto found = std::find(w.bodies.name.begin(), w.bodies.name.end(), name);
            if (found == w.bodies.name.end()) {
                const std::string near = nearest(name, w.bodies.name);
                output.fail("interfaces", fmt::format("entry {}: no body is named '{}'{}", i + 1, name,
                                                      near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near)));
            }
            ids[k] = static_cast<std::uint32_t>(found - w.bodies.name.begin());
        }
        if (ids[0] == ids[1]) output.fail("interfaces", fmt::format("entry {} names body '{}' twice", i + 1, w.bodies.name[ids[0]]));
        if (!seen.insert({std::min(ids[0], ids[1]), std::max(ids[0], ids[1])}).second)
            output.fail("interfaces", fmt::format("entry {} repeats the pair '{}', '{}'", i + 1, w.bodies.name[ids[0]],
                                                  w.bodies.name[ids[1]]));
        selection.named.emplace_back(ids[0], ids[1]);
    }
    return selection;
}

}  // namespace

MeasurementSettings read_measurement_keys(TableReader& root, const World& w) {
    MeasurementSettings m;
    std::set<std::string> names;
    for (const TableReader& t : root.table_array("sensors")) {
        m.sensors.push_back(read_sensor(t, w));
        if (!names.insert(m.sensors.back().name).second)
            t.fail("name", fmt::format("two sensors are named '{}'", m.sensors.back().name));
    }
    if (auto output = root.optional_table("output"))
        m.interfaces = read_interface_selection(*output, w);
    else
        m.interfaces.all = w.bodies.size() <= interfaces_auto_max_bodies;
    return m;
}

}  // namespace blockdem
