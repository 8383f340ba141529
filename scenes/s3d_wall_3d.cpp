#include "scenes/s3d_wall_3d.hpp"

#include <cmath>

#include <fmt/format.h>

#include "world/step_3d.hpp"

namespace blockdem::scenes {

std::vector<Vec3> s3d_brick_centres(const S3dWallDef& def, int& per_course) {
    const Vec3 b = def.brick_m;
    per_course = std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(def.bricks)))));
    const double pitch_m = b.x + def.gap_m;
    std::vector<Vec3> centres;
    centres.reserve(static_cast<std::size_t>(def.bricks));
    for (int course = 0; static_cast<int>(centres.size()) < def.bricks; ++course) {
        const bool odd = course % 2 == 1;
        const int count = odd ? per_course - 1 : per_course;
        const double first_x_m = odd ? pitch_m : 0.5 * pitch_m;
        for (int wythe = 0; wythe < 2; ++wythe) {
            const double y_m = (wythe == 0 ? -0.5 : 0.5) * (b.y + def.gap_m);
            for (int k = 0; k < count && static_cast<int>(centres.size()) < def.bricks; ++k)
                centres.push_back({first_x_m + pitch_m * k, y_m, 0.5 * b.z + b.z * course});
        }
    }
    return centres;
}

World3d s3d_wall_3d(const S3dWallDef& def) {
    World3d w;
    w.contact = def.contact;
    w.table.y = SineMotion{def.amplitude_m_s2, def.period_s, 0.0, def.settling_steps * def.dt_s, 0.0};
    w.dt_s = def.dt_s;
    int per_course = 0;
    const std::vector<Vec3> centres = s3d_brick_centres(def, per_course);
    // S3D's base: (C pitch + 1) x 2 x 0.5 m, top at z = 0, 0.5 m beyond the wall's ends.
    const double length_m = per_course * (def.brick_m.x + def.gap_m) + 1.0;
    add_body(w,
             make_rigid_body_3d("base", box_vertices({length_m, 2.0, 0.5}, {0.5 * (length_m - 1.0), 0.0, -0.25}),
                                def.density_kg_m3),
             BodyKind3d::driven);
    // One brick's hull, then moved: the bricks share its shape.
    const RigidBody3d brick = make_rigid_body_3d("brick", box_vertices(def.brick_m, {}), def.density_kg_m3);
    for (std::size_t i = 0; i < centres.size(); ++i) {
        RigidBody3d r = brick;
        r.name = fmt::format("brick_{}", i);
        r.position_m = centres[i];
        add_body(w, std::move(r), BodyKind3d::dynamic);
    }
    return w;
}

World3d settled_s3d_wall_3d(const S3dWallDef& def) {
    World3d w = s3d_wall_3d(def);
    for (int i = 0; i < def.settling_steps; ++i) step_3d(w);
    return w;
}

}  // namespace blockdem::scenes
