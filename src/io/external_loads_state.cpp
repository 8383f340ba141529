#include "io/external_loads_state.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

// The two dimensions' loads differ only in the width of their quantities (a scalar torque in
// 2-D, a vector in 3-D), so one writer and one reader serve both, per quantity type.
template <class T>
constexpr std::size_t width = 1;
template <>
constexpr std::size_t width<Vec2> = 2;
template <>
constexpr std::size_t width<Vec3> = 3;

void append(std::vector<double>& out, double v) { out.push_back(v); }
void append(std::vector<double>& out, Vec2 v) { out.insert(out.end(), {v.x, v.y}); }
void append(std::vector<double>& out, Vec3 v) { out.insert(out.end(), {v.x, v.y, v.z}); }

void take(const double* p, double& v) { v = p[0]; }
void take(const double* p, Vec2& v) { v = {p[0], p[1]}; }
void take(const double* p, Vec3& v) { v = {p[0], p[1], p[2]}; }

// By bits, not by value: a -0.0 added to a force sum of -0.0 leaves -0.0, a +0.0 makes it +0.0.
bool carries(double v) { return v != 0.0 || std::signbit(v); }
bool carries(Vec2 v) { return carries(v.x) || carries(v.y); }
bool carries(Vec3 v) { return carries(v.x) || carries(v.y) || carries(v.z); }

template <class Loads>
std::vector<std::uint32_t> carrying_bodies(const Loads& l) {
    std::vector<std::uint32_t> rows;
    for (std::size_t i = 0; i < l.force_n.size(); ++i)
        if (l.held[i] != 0 || carries(l.force_n[i]) || carries(l.torque_n_m[i]) || carries(l.held_velocity_m_s[i]) ||
            carries(l.held_angular_velocity_rad_s[i]))
            rows.push_back(static_cast<std::uint32_t>(i));
    return rows;
}

template <class T>
void write_column(StateGroup& g, const std::string& name, const std::vector<T>& per_body, const std::vector<std::uint32_t>& rows) {
    std::vector<double> flat;
    flat.reserve(width<T> * rows.size());
    for (std::uint32_t i : rows) append(flat, per_body[i]);
    g.write(name, flat, width<T> > 1 ? width<T> : 0);
}

template <class Loads>
void write_loads(StateGroup g, const Loads& l) {
    const std::vector<std::uint32_t> rows = carrying_bodies(l);
    std::vector<std::uint8_t> held;
    for (std::uint32_t i : rows) held.push_back(l.held[i]);
    g.write("body", rows);
    write_column(g, "force_n", l.force_n, rows);
    write_column(g, "torque_n_m", l.torque_n_m, rows);
    g.write("held", held);
    write_column(g, "held_velocity_m_s", l.held_velocity_m_s, rows);
    write_column(g, "held_angular_velocity_rad_s", l.held_angular_velocity_rad_s, rows);
}

[[noreturn]] void refuse(const StateGroup& g, const std::string& name, const std::string& problem) {
    throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: {}/{}: {}", g.path(), name, problem));
}

template <class T>
void read_column(const StateGroup& g, const std::string& name, const std::vector<std::uint32_t>& rows, std::vector<T>& per_body) {
    const std::size_t w = width<T>;
    const std::vector<double> flat = g.doubles(name, static_cast<std::int64_t>(w * rows.size()), w > 1 ? w : 0);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        for (std::size_t c = 0; c < w; ++c)
            if (!std::isfinite(flat[w * k + c])) refuse(g, name, fmt::format("row {} (body {}) is not finite", k + 1, rows[k]));
        take(&flat[w * k], per_body[rows[k]]);
    }
}

template <class Loads>
Loads read_loads(const StateGroup& g, std::size_t body_count) {
    const std::vector<std::uint32_t> rows = g.indices("body");
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (rows[k] >= body_count)
            refuse(g, "body", fmt::format("row {}: body {}, but the state has {} bodies (indices from 0)", k + 1, rows[k],
                                          body_count));
        if (k > 0 && rows[k] <= rows[k - 1])
            refuse(g, "body", fmt::format("row {}: body {} after body {} (each body once, in increasing order)", k + 1, rows[k],
                                          rows[k - 1]));
    }
    // As world/external_loads*.cpp allocate them: every body, zero but the rows read.
    Loads l;
    l.force_n.resize(body_count);
    l.torque_n_m.resize(body_count);
    l.held.assign(body_count, 0);
    l.held_velocity_m_s.resize(body_count);
    l.held_angular_velocity_rad_s.resize(body_count);
    read_column(g, "force_n", rows, l.force_n);
    read_column(g, "torque_n_m", rows, l.torque_n_m);
    const std::vector<std::uint8_t> held = g.flags("held", static_cast<std::int64_t>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (held[k] > 1) refuse(g, "held", fmt::format("row {} (body {}) is {}, not 0 or 1", k + 1, rows[k], unsigned{held[k]}));
        l.held[rows[k]] = held[k];
    }
    read_column(g, "held_velocity_m_s", rows, l.held_velocity_m_s);
    read_column(g, "held_angular_velocity_rad_s", rows, l.held_angular_velocity_rad_s);
    return l;
}

}  // namespace

void write_external_loads(StateGroup group, const ExternalLoads& loads) { write_loads(std::move(group), loads); }
void write_external_loads(StateGroup group, const ExternalLoads3d& loads) { write_loads(std::move(group), loads); }

ExternalLoads read_external_loads(const StateGroup& group, std::size_t body_count) {
    return read_loads<ExternalLoads>(group, body_count);
}
ExternalLoads3d read_external_loads_3d(const StateGroup& group, std::size_t body_count) {
    return read_loads<ExternalLoads3d>(group, body_count);
}

}  // namespace blockdem
