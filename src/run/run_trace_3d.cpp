#include "run/run_trace_3d.hpp"

namespace blockdem {

RunTrace3d::RunTrace3d(const World3d& w, const ResponseMonitor3d& monitor) : monitor_(monitor) {
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i)
        if (w.kinds[i] != BodyKind3d::fixed) bodies.push_back(i);
}

void RunTrace3d::record(const World3d& w) {
    time_s.push_back(w.time_s);
    for (std::uint32_t i : bodies) {
        const Vec3 p = position_now_m(w, i), v = velocity_now_m_s(w, i);
        const Vec3 omega = w.bodies[i].angular_velocity_at_t_rad_s;
        const Quaternion turn = turn_since_start(w, monitor_.bodies()[i], i);
        x_m.push_back(p.x);
        y_m.push_back(p.y);
        z_m.push_back(p.z);
        qw.push_back(turn.w);
        qx.push_back(turn.x);
        qy.push_back(turn.y);
        qz.push_back(turn.z);
        tilt_rad.push_back(blockdem::tilt_rad(turn));
        vx_m_s.push_back(v.x);
        vy_m_s.push_back(v.y);
        vz_m_s.push_back(v.z);
        wx_rad_s.push_back(omega.x);
        wy_rad_s.push_back(omega.y);
        wz_rad_s.push_back(omega.z);
    }
    energy.push_back(w.ledger);
}

}  // namespace blockdem
