#include "geometry/polyhedron_edges_3d.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace blockdem {

PolyhedronEdges polyhedron_edges(const Polyhedron& p) {
    PolyhedronEdges r;
    std::map<std::pair<std::size_t, std::size_t>, std::uint32_t> number;  // once per shape: a map is fine
    r.face_edges.resize(p.faces.size());
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
        const auto& face = p.faces[f];
        for (std::size_t k = 0; k < face.size(); ++k) {
            const std::size_t u = face[k];
            const std::size_t v = face[(k + 1) % face.size()];
            const auto key = std::minmax(u, v);
            auto [it, added] = number.try_emplace(key, static_cast<std::uint32_t>(r.edges.size()));
            if (added)
                r.edges.push_back({static_cast<std::uint32_t>(key.first), static_cast<std::uint32_t>(key.second)});
            r.face_edges[f].push_back(it->second);
        }
    }
    for (const auto& e : r.edges) {
        const Vec3 d = normalized(p.vertices_m[e[1]] - p.vertices_m[e[0]]);
        std::uint32_t found = static_cast<std::uint32_t>(r.directions.size());
        for (std::uint32_t i = 0; i < r.directions.size(); ++i)
            if (length(cross(d, r.directions[i])) < 1e-9) found = i;
        if (found == r.directions.size()) r.directions.push_back(d);
        r.edge_direction.push_back(found);
    }
    return r;
}

}  // namespace blockdem
