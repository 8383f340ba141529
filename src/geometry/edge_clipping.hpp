#pragma once
// The pieces of a face contact that the sharp (polygon_contact.cpp) and the rounded
// (rounded_contact.cpp) narrow phases share: the next corner, the incident edge facing a
// reference edge, and the clipping of that edge to the reference edge's extent.
// Inline: they run for every contact at every step.
#include <cstdint>
#include <limits>

#include "geometry/polygon_contact.hpp"

namespace blockdem::edge_clipping {

/// The corner after i (a branch, not the integer division of %: this runs for every contact).
inline std::uint32_t next_corner(std::uint32_t i, std::uint32_t count) { return i + 1 == count ? 0 : i + 1; }

/// The edge of a polygon whose outward normal points most against a reference normal, and by
/// how much it beats the runner-up (difference of the two dot products; 0 for a tie).
struct IncidentEdge {
    std::uint32_t edge = 0;
    double margin = 0.0;  ///< [-]
};

inline IncidentEdge incident_edge(const PolygonView& incident, Vec2 reference_normal) {
    IncidentEdge best;
    double most_against = std::numeric_limits<double>::infinity();
    double runner_up = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = 0; i < incident.count; ++i) {
        const double d = dot(incident.normals[i], reference_normal);
        if (d < most_against) {
            runner_up = most_against;
            most_against = d;
            best.edge = i;
        } else {
            runner_up = std::min(runner_up, d);
        }
    }
    best.margin = runner_up - most_against;
    return best;
}

/// A point of a clipped segment and the feature id it takes.
struct ClipPoint {
    Vec2 p;
    std::uint32_t feature;
};

/// Keeps the part of segment (in[0], in[1]) where dot(direction, x) <= offset. A point made by
/// the cut takes the feature id "cut", the corner of the reference edge that the plane passes.
/// Returns how many points out holds.
[[gnu::always_inline]] inline int clip_segment(const ClipPoint in[2], ClipPoint out[2], Vec2 direction, double offset,
                                               std::uint32_t cut) {
    int n = 0;
    const double d0 = dot(direction, in[0].p) - offset;
    const double d1 = dot(direction, in[1].p) - offset;
    if (d0 <= 0.0) out[n++] = in[0];
    if (d1 <= 0.0) out[n++] = in[1];
    if (d0 * d1 < 0.0) {
        const double f = d0 / (d0 - d1);
        out[n++] = {in[0].p + f * (in[1].p - in[0].p), cut};
    }
    return n;
}

}  // namespace blockdem::edge_clipping
