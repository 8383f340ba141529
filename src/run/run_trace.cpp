#include "run/run_trace.hpp"

namespace blockdem {

RunTrace::RunTrace(const World& w) {
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies.record[i]) bodies.push_back(i);
}

void RunTrace::record(const World& w) {
    const Bodies& b = w.bodies;
    time_s.push_back(w.time_s);
    for (std::uint32_t i : bodies) {
        x_m.push_back(b.position_m[i].x);
        y_m.push_back(b.position_m[i].y);
        rotation_rad.push_back(b.rotation_rad[i]);
        vx_m_s.push_back(b.velocity_at_t_m_s[i].x);
        vy_m_s.push_back(b.velocity_at_t_m_s[i].y);
        angular_velocity_rad_s.push_back(b.angular_velocity_at_t_rad_s[i]);
        ax_m_s2.push_back(b.acceleration_m_s2[i].x);
        ay_m_s2.push_back(b.acceleration_m_s2[i].y);
        angular_acceleration_rad_s2.push_back(b.angular_acceleration_rad_s2[i]);
    }
    energy.push_back(w.energy);
}

}  // namespace blockdem
