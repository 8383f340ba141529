#include "io/bodies_json_writer.hpp"

#include "io/output_file.hpp"

namespace blockdem {

nlohmann::json bodies_json(const World& w) {
    const Bodies& b = w.bodies;
    nlohmann::json list = nlohmann::json::array();
    for (std::uint32_t i = 0; i < b.size(); ++i) {
        nlohmann::json corners = nlohmann::json::array();
        for (std::uint32_t k = 0; k < b.vertex_count[i]; ++k) {
            const Vec2 v = b.local_vertices_m[b.vertex_begin[i] + k];
            corners.push_back({v.x, v.y});
        }
        list.push_back({{"id", i},
                        {"name", b.name[i]},
                        {"kind", to_string(b.kind[i])},
                        {"assembly", b.assembly[i]},
                        {"material", w.contact.materials[b.material[i]]},
                        {"recorded", b.record[i] != 0},
                        {"initial_centroid_m", {b.initial_position_m[i].x, b.initial_position_m[i].y}},
                        {"corners_m", corners}});
    }
    return {{"bodies", list},
            {"gravity_m_s2", w.settings.gravity_m_s2},
            {"duration_s", w.settings.duration_s},
            {"corners_m", "relative to the centroid at rotation 0; counter-clockwise"}};
}

void write_bodies_json(const std::filesystem::path& file, const World& w) {
    write_output_file(file, bodies_json(w).dump(1) + '\n');
}

}  // namespace blockdem
