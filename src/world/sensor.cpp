#include "world/sensor.hpp"

#include <stdexcept>

namespace blockdem {

PointKinematics point_kinematics(const Bodies& b, std::uint32_t i, Vec2 r0_m) {
    const Vec2 r = Rotation::from_angle(b.rotation_rad[i]).apply(r0_m);
    const double omega = b.angular_velocity_at_t_rad_s[i];
    const double alpha = b.angular_acceleration_rad_s2[i];
    // Static bodies hold no angular state (0), and their acceleration is set only when driven;
    // a fixed body's arrays stay at zero.
    return {b.position_m[i] + r, b.velocity_at_t_m_s[i] + cross(omega, r),
            b.acceleration_m_s2[i] + cross(alpha, r) - (omega * omega) * r};
}

const std::vector<std::pair<const char*, const char*>>& sensor_columns(SensorKind kind) {
    static const std::vector<std::pair<const char*, const char*>> point = {
        {"ax", "m/s^2"}, {"ay", "m/s^2"}, {"vx", "m/s"}, {"vy", "m/s"}, {"x", "m"}, {"y", "m"}};
    static const std::vector<std::pair<const char*, const char*>> relative = {{"dx", "m"}, {"dy", "m"}};
    return kind == SensorKind::point ? point : relative;
}

std::size_t sensor_channel_count(SensorKind kind) { return sensor_columns(kind).size(); }

SensorBank::SensorBank(std::vector<SensorDef> sensors, double dt_s) : sensors_(std::move(sensors)) {
    std::size_t channels = 0;
    for (const SensorDef& s : sensors_) {
        first_channel_.push_back(channels);
        const std::size_t n = sensor_channel_count(s.kind);
        channels += n;
        if (s.lowpass_hz > 0.0) {
            designs_.push_back(design_butterworth_lowpass(s.lowpass_hz, s.order, 1.0 / dt_s));
            for (std::size_t c = 0; c < n; ++c) {
                filter_of_channel_.push_back(static_cast<std::int64_t>(filters_.size()));
                filters_.emplace_back(*designs_.back());
            }
        } else {
            designs_.emplace_back();
            filter_of_channel_.insert(filter_of_channel_.end(), n, -1);
        }
    }
    relative_start_m_.resize(sensors_.size());
    raw_.resize(channels);
    values_.resize(channels);
}

void SensorBank::observe(const World& w) {
    const Bodies& b = w.bodies;
    for (std::size_t s = 0; s < sensors_.size(); ++s) {
        const SensorDef& d = sensors_[s];
        double* out = raw_.data() + first_channel_[s];
        const PointKinematics p = point_kinematics(b, d.body, d.point_m);
        if (d.kind == SensorKind::point) {
            out[0] = p.acceleration_m_s2.x;
            out[1] = p.acceleration_m_s2.y;
            out[2] = p.velocity_m_s.x;
            out[3] = p.velocity_m_s.y;
            out[4] = p.position_m.x;
            out[5] = p.position_m.y;
            continue;
        }
        const Vec2 gap = p.position_m - point_kinematics(b, d.body2, d.point2_m).position_m;
        if (!started_) relative_start_m_[s] = gap;
        const Vec2 d_m = gap - relative_start_m_[s];
        out[0] = d_m.x;
        out[1] = d_m.y;
    }
    started_ = true;
    for (std::size_t c = 0; c < raw_.size(); ++c) {
        const std::int64_t f = filter_of_channel_[c];
        values_[c] = f < 0 ? raw_[c] : filters_[static_cast<std::size_t>(f)].filter(raw_[c]);
    }
}

SensorBankState SensorBank::state() const {
    SensorBankState s;
    for (const ButterworthChannel& f : filters_) {
        s.filter_state.insert(s.filter_state.end(), f.state().begin(), f.state().end());
        s.filter_started.push_back(f.started() ? 1 : 0);
    }
    s.relative_start_m = relative_start_m_;
    s.started = started_;
    return s;
}

void SensorBank::restore(const SensorBankState& s) {
    std::size_t values = 0;
    for (const ButterworthChannel& f : filters_) values += f.state().size();
    if (s.filter_state.size() != values || s.filter_started.size() != filters_.size() ||
        s.relative_start_m.size() != relative_start_m_.size())
        throw std::invalid_argument("the saved sensor state is for other sensors or filters");
    std::size_t at = 0;
    for (std::size_t i = 0; i < filters_.size(); ++i) {
        const std::size_t n = filters_[i].state().size();
        filters_[i].restore(std::vector<double>(s.filter_state.begin() + static_cast<std::ptrdiff_t>(at),
                                                s.filter_state.begin() + static_cast<std::ptrdiff_t>(at + n)),
                            s.filter_started[i] != 0);
        at += n;
    }
    relative_start_m_ = s.relative_start_m;
    started_ = s.started;
}

}  // namespace blockdem
