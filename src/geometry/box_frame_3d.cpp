#include "geometry/box_frame_3d.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {

BoxFrame3d box_frame(const Polyhedron& p, const PolyhedronEdges& e) {
    BoxFrame3d box;
    if (p.vertices_m.size() != 8 || p.faces.size() != 6 || e.directions.size() != 3) return box;
    for (std::size_t f = 0; f < 6; ++f) {
        if (p.faces[f].size() != 4 || e.face_edges[f].size() != 4) return box;
        for (std::size_t k = 0; k < 4; ++k) {
            box.face_corners[f][k] = static_cast<std::uint16_t>(p.faces[f][k]);    // < 8
            box.face_edges[f][k] = static_cast<std::uint16_t>(e.face_edges[f][k]);  // < 12
        }
    }
    const auto& d = e.directions;
    constexpr double tolerance = 1e-12;
    if (std::abs(dot(d[0], d[1])) > tolerance || std::abs(dot(d[0], d[2])) > tolerance ||
        std::abs(dot(d[1], d[2])) > tolerance)
        return box;
    double half[3] = {0.0, 0.0, 0.0};
    for (const Vec3& v : p.vertices_m)
        for (int i = 0; i < 3; ++i) half[i] = std::max(half[i], std::abs(dot(v, d[i])));
    const double size_m = std::max({half[0], half[1], half[2]});
    for (const Vec3& v : p.vertices_m)
        for (int i = 0; i < 3; ++i)
            if (std::abs(std::abs(dot(v, d[i])) - half[i]) > tolerance * size_m) return box;
    for (std::size_t f = 0; f < 6; ++f) {
        const Vec3 n = p.face_normals[f];
        int along = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(dot(n, d[i])) > std::abs(dot(n, d[along]))) along = i;
        if (std::abs(std::abs(dot(n, d[along])) - 1.0) > tolerance) return box;
        box.face_direction[f] = static_cast<std::uint8_t>(along);
        box.face_sign[f] = dot(n, d[along]) > 0.0 ? 1.0 : -1.0;
        box.face_of[along][box.face_sign[f] > 0.0 ? 0 : 1] = static_cast<std::uint8_t>(f);
    }
    box.normals_are_directions = true;
    for (std::size_t f = 0; f < 6; ++f)
        if (!(p.face_normals[f] == box.face_sign[f] * d[box.face_direction[f]])) box.normals_are_directions = false;
    for (std::size_t k = 0; k < 8; ++k) {
        std::uint8_t corner = 0;
        for (int i = 0; i < 3; ++i)
            if (dot(p.vertices_m[k], d[i]) > 0.0) corner = static_cast<std::uint8_t>(corner | (1u << i));
        box.vertex_corner[k] = corner;
    }
    box.half_lengths_m = {half[0], half[1], half[2]};
    box.is_box = true;
    return box;
}

}  // namespace blockdem
