#include "scenes/brick_wall_3d.hpp"

#include <fmt/format.h>

namespace blockdem::scenes {

std::vector<BrickPlacement3d> running_bond_3d(int courses, int bricks_per_course, int wythes, Vec3 b) {
    std::vector<BrickPlacement3d> bricks;
    for (int c = 0; c < courses; ++c) {
        const bool odd = c % 2 == 1;
        const double shift_m = odd ? 0.5 * b.x : 0.0;
        for (int y = 0; y < wythes; ++y)
            for (int k = 0; k < bricks_per_course - (odd ? 1 : 0); ++k)
                bricks.push_back({c, y, k, {(k + 0.5) * b.x + shift_m, (y + 0.5) * b.y, (c + 0.5) * b.z}});
    }
    return bricks;
}

World3d brick_wall_3d(const BrickWall3dDef& def) {
    World3d w;
    w.contact = def.contact;
    w.table.x = def.shaking;
    w.dt_s = def.dt_s;
    const Vec3 b = def.brick_m;
    const double length_m = (def.bricks_per_course + 1) * b.x;
    const double width_m = def.wythes * b.y + 2.0 * b.y;
    const Vec3 base_center_m{0.5 * length_m - b.x, 0.5 * def.wythes * b.y, -0.5 * b.z};
    add_body(w, make_rigid_body_3d("base", box_vertices({length_m, width_m, b.z}, base_center_m), def.density_kg_m3),
             BodyKind3d::driven);
    // Bricks of one shape: its hull once, then moved (the hull search is the costly part).
    const RigidBody3d brick = make_rigid_body_3d("brick", box_vertices(b, {}), def.density_kg_m3);
    for (const BrickPlacement3d& p : running_bond_3d(def.courses, def.bricks_per_course, def.wythes, b)) {
        RigidBody3d r = brick;
        r.name = fmt::format("brick_{}_{}_{}", p.course, p.wythe, p.index);
        r.position_m = p.centre_m;
        add_body(w, std::move(r), BodyKind3d::dynamic);
    }
    return w;
}

}  // namespace blockdem::scenes
