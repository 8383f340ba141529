#pragma once
// Shared by the narrow-phase tests (test_polygon_contact.cpp, test_rounded_contact.cpp,
// test_rounded_bond_gap.cpp): a polygon that owns the vertices and edge normals a PolygonView
// only points to, so that a test makes a body in one line and hands collide_polygons or
// collide_rounded its view.
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/polygon_contact.hpp"

namespace blockdem::testing {

struct Poly {
    std::vector<Vec2> v, n;
    explicit Poly(std::vector<Vec2> vertices) : v(std::move(vertices)) {
        for (std::size_t i = 0; i < v.size(); ++i) n.push_back(edge_normal(v[i], v[(i + 1) % v.size()]));
    }
    PolygonView view() const { return {v.data(), n.data(), static_cast<std::uint32_t>(v.size())}; }
};

/// A w x h rectangle [m] centred at c, turned by rot [rad].
inline Poly box(double w, double h, Vec2 c, double rot = 0.0) { return Poly(rectangle_vertices(w, h, c, rot)); }

}  // namespace blockdem::testing
