#pragma once
// The edges of a convex polyhedron, numbered once, for the narrow phase (geometry/
// polyhedron_contact_3d.hpp): the separating-axis test needs the edge directions (parallel edges
// share one, so a box has 3, not 12), and the contact points are keyed by edge numbers so that a
// point's shear history survives from step to step.
#include <array>
#include <cstdint>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace blockdem {

struct PolyhedronEdges {
    std::vector<std::array<std::uint32_t, 2>> edges;   ///< vertex indices, each edge once
    std::vector<std::vector<std::uint32_t>> face_edges; ///< per face, edge k joins its corners k and k+1
    std::vector<Vec3> directions;                      ///< unit edge directions up to sign, each once (body frame)
    std::vector<std::uint32_t> edge_direction;         ///< per edge, its index in directions
};

/// The edges of p (built once per shape). Two directions are one when their cross product is
/// below 1e-9 (parallel to round-off).
PolyhedronEdges polyhedron_edges(const Polyhedron& p);

}  // namespace blockdem
