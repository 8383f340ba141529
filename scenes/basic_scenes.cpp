#include "scenes/basic_scenes.hpp"

#include <numbers>

#include <fmt/format.h>

#include "geometry/polygon.hpp"
#include "laws/restitution.hpp"

namespace blockdem::scenes {

ContactParameters paper_contact() {
    return {.kn_N_m = 2.0e4, .ks_N_m = 2.0e4, .mu = 0.3, .h_n = damping_ratio_paper(0.4), .h_s = 1.0};
}

Model block_on_table(double width_m, double height_m, double mass_kg, const ContactParameters& contact,
                     double duration_s, double dt_s) {
    Model m;
    m.settings.duration_s = duration_s;
    m.settings.dt_s = dt_s;
    m.contact = MaterialPairs::uniform(contact);
    BodyDef table;
    table.name = "table";
    table.kind = BodyKind::driven;
    table.vertices_m = rectangle_vertices(20.0 * width_m, 0.2, {0.0, -0.1}, 0.0);
    table.density_kg_m3 = 1000.0;
    BodyDef block;
    block.name = "block";
    block.vertices_m = rectangle_vertices(width_m, height_m, {0.0, 0.5 * height_m}, 0.0);
    block.mass_kg = mass_kg;
    m.bodies = {table, block};
    return m;
}

Model paper_sliding(double h_s, double duration_s) {
    ContactParameters c = paper_contact();
    c.h_s = h_s;
    Model m = block_on_table(0.5, 0.2, 1.0, c, duration_s, 1.0e-4);
    m.table_motion.horizontal = SineMotion{3.5, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    return m;
}

Model block_stack(int n, double width_m, double height_m, double density_kg_m3, const ContactParameters& contact,
                  double duration_s) {
    Model m;
    m.settings.duration_s = duration_s;
    m.contact = MaterialPairs::uniform(contact);
    BodyDef base;
    base.name = "base";
    base.kind = BodyKind::fixed;
    base.vertices_m = rectangle_vertices(4.0 * width_m, 0.2, {0.0, -0.1}, 0.0);
    m.bodies.push_back(base);
    for (int i = 0; i < n; ++i) {
        BodyDef b;
        b.name = fmt::format("block{}", i);
        b.vertices_m = rectangle_vertices(width_m, height_m, {0.0, (i + 0.5) * height_m}, 0.0);
        b.density_kg_m3 = density_kg_m3;
        m.bodies.push_back(b);
    }
    return m;
}

}  // namespace blockdem::scenes
