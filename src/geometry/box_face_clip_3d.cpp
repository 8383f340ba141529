#include "geometry/box_face_clip_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace blockdem {
namespace {

using FaceCorner = BoxClipCorner3d;
constexpr std::size_t most_corners = BoxFaceClip3d::most_corners;

// One side of the rectangle: a bound on u (axis 0) or v (axis 1). A corner's height over the side
// plane is sign (coordinate - bound); the general clip's is that times the side's length.
struct RectangleSide {
    int axis = 0;
    double sign = 1.0;
    double bound_m = 0.0;  ///< [m] the side's start corner's coordinate along axis
    double slack_m = 0.0;  ///< [m] 1e-9 of the side's length: the general clip's 1e-9 |side|^2 over |side|
};

double coordinate(const FaceCorner& c, int axis) { return axis == 0 ? c.u_m : c.v_m; }

// The side from corner p0 to p1 (u, v). Its outward normal in the plane is (p1 - p0) x n, which in
// the right-handed frame (e_u, e_v, n) is (dv, -du): along u when the side runs along v.
RectangleSide rectangle_side(double u0, double v0, double u1, double v1) {
    const double du = u1 - u0, dv = v1 - v0;
    if (std::abs(dv) >= std::abs(du)) return {0, dv > 0.0 ? 1.0 : -1.0, u0, 1e-9 * std::abs(dv)};
    return {1, du < 0.0 ? 1.0 : -1.0, v0, 1e-9 * std::abs(du)};
}

}  // namespace

bool box_face_clip_applies(const PosedPolyhedron& ref, const PosedPolyhedron& inc, std::uint32_t inc_face) {
    return ref.box != nullptr && ref.box->is_box && inc.shape->faces[inc_face].size() <= box_clip_most_incident_corners;
}

bool clip_box_face_in_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                            std::uint32_t inc_face, BoxFaceClip3d& clip) {
    // The frame: origin at the face's corner 0, e_u one of the box's directions in the face's
    // plane, e_v = n x e_u, so that (e_u, e_v, n) is right-handed as the general clip's sides assume.
    const auto& ref_corners = ref.shape->faces[ref_face];
    const Vec3 n = ref.face_normals[ref_face];
    const int normal_direction = ref.box->face_direction[ref_face];
    const Vec3 e_u = ref.directions[normal_direction == 0 ? 1 : 0];
    const Vec3 e_v = cross(n, e_u);
    clip.e_u = e_u;
    clip.e_v = e_v;
    clip.n = n;
    const Vec3 origin_m = ref.vertices_m[ref_corners[0]];
    double corner_u[4], corner_v[4];
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 r = ref.vertices_m[ref_corners[k]] - origin_m;
        corner_u[k] = dot(r, e_u);
        corner_v[k] = dot(r, e_v);
    }
    clip.origin_m = origin_m;

    FaceCorner* here_polygon = clip.buffers[0].data();
    FaceCorner* next_polygon = clip.buffers[1].data();
    std::size_t count = 0;
    const auto& inc_corners = inc.shape->faces[inc_face];
    for (std::size_t k = 0; k < inc_corners.size(); ++k) {
        const Vec3 r = inc.vertices_m[inc_corners[k]] - origin_m;
        here_polygon[count++] = {dot(r, e_u),
                                 dot(r, e_v),
                                 dot(r, n),
                                 feature_3d(FeatureKind3d::vertex, static_cast<std::uint32_t>(inc_corners[k])),
                                 feature_3d(FeatureKind3d::face, ref_face),
                                 feature_3d(FeatureKind3d::edge, inc.edges->face_edges[inc_face][k]),
                                 false};
    }
    for (std::size_t k = 0; k < 4 && count > 0; ++k) {
        const std::size_t k_next = (k + 1) % 4;
        const RectangleSide side = rectangle_side(corner_u[k], corner_v[k], corner_u[k_next], corner_v[k_next]);
        const std::uint32_t ref_edge = feature_3d(FeatureKind3d::edge, ref.edges->face_edges[ref_face][k]);
        double heights_m[most_corners];
        bool all_in = true;
        for (std::size_t i = 0; i < count; ++i) {
            heights_m[i] = side.sign * (coordinate(here_polygon[i], side.axis) - side.bound_m);
            all_in = all_in && heights_m[i] <= side.slack_m;
        }
        if (all_in) continue;  // the side cuts nothing: the clip would copy the polygon as it is
        std::size_t clipped = 0;
        for (std::size_t i = 0; i < count; ++i) {
            // A convex polygon gains at most one corner a side; round-off that bent it more
            // than the array holds is left to the general clip.
            if (clipped + 2 > most_corners) return false;
            const std::size_t i_next = i + 1 == count ? 0 : i + 1;
            const FaceCorner& here = here_polygon[i];
            const FaceCorner& next = here_polygon[i_next];
            const double dh = heights_m[i];
            const double dn = heights_m[i_next];
            const bool here_in = dh <= side.slack_m;
            if (here_in) next_polygon[clipped++] = here;
            if (here_in == (dn <= side.slack_m)) continue;
            FaceCorner c;  // every field set below
            // On the plane itself: the slack decides in or out, not where the crossing is.
            const double t = std::clamp(dh / (dh - dn), 0.0, 1.0);
            c.u_m = here.u_m + t * (next.u_m - here.u_m);
            c.v_m = here.v_m + t * (next.v_m - here.v_m);
            c.w_m = here.w_m + t * (next.w_m - here.w_m);
            if (!here.line_is_reference) {  // an incident edge crossing this reference edge
                c.feature_incident = here.line_after;
                c.feature_reference = ref_edge;
            } else {  // two reference sides meet: a corner of the reference face inside the incident face
                const double to_u = (c.u_m - corner_u[k]) * (c.u_m - corner_u[k]) +
                                    (c.v_m - corner_v[k]) * (c.v_m - corner_v[k]);
                const double to_v = (c.u_m - corner_u[k_next]) * (c.u_m - corner_u[k_next]) +
                                    (c.v_m - corner_v[k_next]) * (c.v_m - corner_v[k_next]);
                const std::size_t corner = to_u <= to_v ? ref_corners[k] : ref_corners[k_next];
                c.feature_reference = feature_3d(FeatureKind3d::vertex, static_cast<std::uint32_t>(corner));
                c.feature_incident = feature_3d(FeatureKind3d::face, inc_face);
            }
            c.line_after = here_in ? ref_edge : here.line_after;
            c.line_is_reference = here_in ? true : here.line_is_reference;
            next_polygon[clipped++] = c;
        }
        std::swap(here_polygon, next_polygon);
        count = clipped;
    }
    clip.count = count;
    clip.corners = here_polygon;
    return true;
}

bool clip_by_box_face(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                      std::uint32_t inc_face, std::vector<ClipCorner3d>& polygon) {
    BoxFaceClip3d clip;
    if (!clip_box_face_in_frame(ref, ref_face, inc, inc_face, clip)) return false;
    // Each corner written into its slot: no capacity check a corner (the scratch keeps its size).
    polygon.resize(clip.count);
    for (std::size_t i = 0; i < clip.count; ++i) {
        const FaceCorner& c = clip.corners[i];
        polygon[i] = {clip.world_m(c.u_m, c.v_m, c.w_m), c.feature_incident, c.feature_reference, c.line_after,
                      c.line_is_reference};
    }
    return true;
}

}  // namespace blockdem
