#include "geometry/box_face_clip_3d.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace blockdem {
namespace {

using FaceCorner = BoxClipCorner3d;
constexpr std::size_t most_corners = BoxFaceClip3d::most_corners;

// One side of the rectangle: a bound on u (axis 0) or v (axis 1). A corner's height over the side
// plane is sign (coordinate - bound); the general clip's is that times the side's length.
// No default values: each side is written once before it is read (RectangleInFrame's four were
// zeroed at every clip, for nothing).
struct RectangleSide {
    int axis;
    double sign;
    double bound_m;  ///< [m] the side's start corner's coordinate along axis
    double slack_m;  ///< [m] 1e-9 of the side's length: the general clip's 1e-9 |side|^2 over |side|
};

double coordinate(const FaceCorner& c, int axis) { return axis == 0 ? c.u_m : c.v_m; }

// The side from corner p0 to p1 (u, v), running along v (a bound on u) or along u. Its outward
// normal in the plane is (p1 - p0) x n, which in the right-handed frame (e_u, e_v, n) is (dv, -du):
// along u when the side runs along v.
RectangleSide rectangle_side(bool along_v, double u0, double v0, double u1, double v1) {
    const double du = u1 - u0, dv = v1 - v0;
    if (along_v) return {0, dv > 0.0 ? 1.0 : -1.0, u0, 1e-9 * std::abs(dv)};
    return {1, du < 0.0 ? 1.0 : -1.0, v0, 1e-9 * std::abs(du)};
}

// The reference rectangle in the frame: its corners (u, v) and its four sides, in its corner order.
struct RectangleInFrame {
    double corner_u_m[4];  ///< [m]
    double corner_v_m[4];  ///< [m]
    RectangleSide sides[4];
};

// The frame: origin at the reference face's corner 0, e_u one of the box's directions in the
// face's plane, e_v = n x e_u, so that (e_u, e_v, n) is right-handed as the general clip's sides
// assume.
[[gnu::always_inline]] inline void load_axes(const PosedPolyhedron& ref, std::uint32_t ref_face, BoxFaceClip3d& clip) {
    const Vec3 n = ref.face_normals[ref_face];
    const int normal_direction = ref.box->face_direction[ref_face];
    const Vec3 e_u = ref.directions[normal_direction == 0 ? 1 : 0];
    clip.e_u = e_u;
    clip.e_v = cross(n, e_u);
    clip.n = n;
    clip.origin_m = ref.vertices_m[ref.shape->faces[ref_face][0]];
}

// The rectangle's four sides from its corners.
[[gnu::always_inline]] inline void set_rectangle_sides(RectangleInFrame& rectangle) {
    // The sides run along v and u in turn (box edges, along e_v or e_u to round-off and to
    // box_frame's 1e-12 of the box's size): the first side's longer coordinate says which.
    const double* corner_u = rectangle.corner_u_m;
    const double* corner_v = rectangle.corner_v_m;
    const bool first_along_v = std::abs(corner_v[1] - corner_v[0]) >= std::abs(corner_u[1] - corner_u[0]);
    for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t k_next = (k + 1) % 4;
        rectangle.sides[k] = rectangle_side(first_along_v == (k % 2 == 0), corner_u[k], corner_v[k], corner_u[k_next],
                                            corner_v[k_next]);
    }
}

// The rectangle in the frame (the axes loaded).
[[gnu::always_inline]] inline void load_rectangle(const PosedPolyhedron& ref, std::uint32_t ref_face,
                                                  const BoxFaceClip3d& clip, RectangleInFrame& rectangle) {
    const auto& ref_corners = ref.shape->faces[ref_face];
    const Vec3 origin_m = clip.origin_m;
    const Vec3 e_u = clip.e_u;
    const Vec3 e_v = clip.e_v;
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 r = ref.vertices_m[ref_corners[k]] - origin_m;
        rectangle.corner_u_m[k] = dot(r, e_u);
        rectangle.corner_v_m[k] = dot(r, e_v);
    }
    set_rectangle_sides(rectangle);
}

// The frame and the rectangle in it: what both clips start from.
[[gnu::always_inline]] inline void load_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, BoxFaceClip3d& clip,
                                              RectangleInFrame& rectangle) {
    load_axes(ref, ref_face, clip);
    load_rectangle(ref, ref_face, clip, rectangle);
}

// Corner k of the incident face as the polygon's first form holds it: at (u, v, w), the face's
// own corner, on the reference face, running along the face's edge k to the next corner.
[[gnu::always_inline]] inline FaceCorner incident_corner(const PosedPolyhedron& inc, std::uint32_t inc_face, std::uint32_t ref_face, std::size_t k,
                           double u_m, double v_m, double w_m) {
    return {u_m,
            v_m,
            w_m,
            feature_3d(FeatureKind3d::vertex, static_cast<std::uint32_t>(inc.shape->faces[inc_face][k])),
            feature_3d(FeatureKind3d::face, ref_face),
            feature_3d(FeatureKind3d::edge, inc.edges->face_edges[inc_face][k]),
            false};
}

// The polygon's first form, the incident face's corners in clip.buffers[0] (the frame loaded).
// Returns the incident face's corner count.
std::size_t load_incident_face(std::uint32_t ref_face, const PosedPolyhedron& inc, std::uint32_t inc_face,
                               BoxFaceClip3d& clip) {
    FaceCorner* polygon = clip.buffers[0].data();
    const auto& inc_corners = inc.shape->faces[inc_face];
    const std::size_t count = inc_corners.size();
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 r = inc.vertices_m[inc_corners[k]] - clip.origin_m;
        polygon[k] = incident_corner(inc, inc_face, ref_face, k, dot(r, clip.e_u), dot(r, clip.e_v), dot(r, clip.n));
    }
    return count;
}

// A box's face of 4 corners in the frame: their coordinates alone. Why: the one pass decides
// from the coordinates, and a corner's record (its keys) is written once, where the polygon it
// ends in is (docs/performance.md, "Branch face5"), not first in the first form and then copied.
struct FourCorners {
    double u_m[4];  ///< [m]
    double v_m[4];  ///< [m]
    double w_m[4];  ///< [m]
};

[[gnu::always_inline]] inline FourCorners load_four_corners(const PosedPolyhedron& inc, std::uint32_t inc_face, const BoxFaceClip3d& clip) {
    FourCorners face;
    const auto& inc_corners = inc.shape->faces[inc_face];
    const Vec3 origin_m = clip.origin_m, e_u = clip.e_u, e_v = clip.e_v, n = clip.n;
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 r = inc.vertices_m[inc_corners[k]] - origin_m;
        face.u_m[k] = dot(r, e_u);
        face.v_m[k] = dot(r, e_v);
        face.w_m[k] = dot(r, n);
    }
    return face;
}

// The first form of a face of 4 corners, for the passes.
void write_four_corners(const PosedPolyhedron& inc, std::uint32_t inc_face, std::uint32_t ref_face,
                        const FourCorners& face, BoxFaceClip3d& clip) {
    for (std::size_t k = 0; k < 4; ++k)
        clip.buffers[0][k] = incident_corner(inc, inc_face, ref_face, k, face.u_m[k], face.v_m[k], face.w_m[k]);
}

// The crossing of the polygon's side from here (u, v, w) to next with a side plane, here's height
// dh and next's dn on either side of the slack: one formula for both clips, so that they agree to
// the bit.
void set_crossing(double here_u_m, double here_v_m, double here_w_m, double next_u_m, double next_v_m,
                  double next_w_m, double dh, double dn, FaceCorner& c) {
    // On the plane itself: the slack decides in or out, not where the crossing is.
    const double t = std::clamp(dh / (dh - dn), 0.0, 1.0);
    c.u_m = here_u_m + t * (next_u_m - here_u_m);
    c.v_m = here_v_m + t * (next_v_m - here_v_m);
    c.w_m = here_w_m + t * (next_w_m - here_w_m);
}

void set_crossing(const FaceCorner& here, const FaceCorner& next, double dh, double dn, FaceCorner& c) {
    set_crossing(here.u_m, here.v_m, here.w_m, next.u_m, next.v_m, next.w_m, dh, dn, c);
}

// The Sutherland-Hodgman clip of the loaded face (clip.buffers[0], count corners), side by side.
bool clip_by_passes(const PosedPolyhedron& ref, std::uint32_t ref_face, std::uint32_t inc_face,
                    const RectangleInFrame& rectangle, std::size_t count, BoxFaceClip3d& clip) {
    const auto& ref_corners = ref.shape->faces[ref_face];
    FaceCorner* here_polygon = clip.buffers[0].data();
    FaceCorner* next_polygon = clip.buffers[1].data();
    for (std::size_t k = 0; k < 4 && count > 0; ++k) {
        const std::size_t k_next = (k + 1) % 4;
        const RectangleSide& side = rectangle.sides[k];
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
            set_crossing(here, next, dh, dn, c);
            if (!here.line_is_reference) {  // an incident edge crossing this reference edge
                c.feature_incident = here.line_after;
                c.feature_reference = ref_edge;
            } else {  // two reference sides meet: a corner of the reference face inside the incident face
                const double* corner_u = rectangle.corner_u_m;
                const double* corner_v = rectangle.corner_v_m;
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

// The face as it is, every side skipping (the one pass's polygon, in buffers[0]).
void write_uncut(const PosedPolyhedron& inc, std::uint32_t inc_face, std::uint32_t ref_face, const FourCorners& face,
                 BoxFaceClip3d& clip) {
    FaceCorner* polygon = clip.buffers[0].data();
    for (std::size_t i = 0; i < 4; ++i)
        polygon[i] = incident_corner(inc, inc_face, ref_face, i, face.u_m[i], face.v_m[i], face.w_m[i]);
    clip.count = 4;
    clip.corners = polygon;
}

// The one pass's cut of the face's 4 corners by side k alone, written into buffers[1] with its
// keys: the passes' own cut (the same heights, the same formula), for a face that no other side cuts.
void cut_by_one_side(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                     std::uint32_t inc_face, const RectangleSide& side, std::size_t k, const FourCorners& face,
                     BoxFaceClip3d& clip) {
    constexpr std::size_t count = 4;
    // The incident face's corner and edge numbers read once (the polygon's stores could be read
    // as writes to the lists' entries, but not to where the lists are).
    const std::size_t* corner_ids = inc.shape->faces[inc_face].data();
    const std::uint32_t* edge_ids = inc.edges->face_edges[inc_face].data();
    const std::uint32_t on_reference_face = feature_3d(FeatureKind3d::face, ref_face);
    const double* along = side.axis == 0 ? face.u_m : face.v_m;
    double heights[count];
    for (std::size_t i = 0; i < count; ++i) heights[i] = side.sign * (along[i] - side.bound_m);
    // The one cut, as the passes make it on the face's own corners (none lies on a reference side).
    const std::uint32_t ref_edge = feature_3d(FeatureKind3d::edge, ref.edges->face_edges[ref_face][k]);
    FaceCorner* cut = clip.buffers[1].data();
    std::size_t clipped = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t i_next = i + 1 == count ? 0 : i + 1;
        const double dh = heights[i];
        const double dn = heights[i_next];
        const bool here_in = dh <= side.slack_m;
        const std::uint32_t incident_edge = feature_3d(FeatureKind3d::edge, edge_ids[i]);
        if (here_in)
            cut[clipped++] = {face.u_m[i], face.v_m[i], face.w_m[i],
                              feature_3d(FeatureKind3d::vertex, static_cast<std::uint32_t>(corner_ids[i])),
                              on_reference_face, incident_edge, false};
        if (here_in == (dn <= side.slack_m)) continue;
        FaceCorner& c = cut[clipped++];
        set_crossing(face.u_m[i], face.v_m[i], face.w_m[i], face.u_m[i_next], face.v_m[i_next], face.w_m[i_next], dh,
                     dn, c);
        // here's line: the incident face's edge i
        c.feature_incident = incident_edge;
        c.feature_reference = ref_edge;
        c.line_after = here_in ? ref_edge : incident_edge;
        c.line_is_reference = here_in;
    }
    clip.count = clipped;
    clip.corners = cut;
}

// The clip in one pass, where it gives the passes' polygon to the bit: when at most one side
// cuts the face (has a corner beyond its slack). The sides before it then skip, as the passes do
// (the same heights, the same test); the cut is the passes' own cut of the incident face's
// corners (the same formula on the same heights); the sides after it skip only if the cut's new
// corners are inside them, which is decided without computing their heights there: a new corner
// lies on a side of the face between two of its corners, to round-off (a few 1e-16 of the largest
// coordinate), so if every corner is inside those sides by half their slack and that half exceeds
// 1e-12 of the coordinates, so is every new corner. The polygon is written once, with its keys,
// where it ends: buffers[0] when no side cuts, buffers[1] when one does. Returns false, clip
// untouched but for its frame, when it cannot say: the passes then decide (a cut by two sides, a
// corner within half a slack of a side that does not cut).
bool clip_in_one_pass(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                      std::uint32_t inc_face, const RectangleInFrame& rectangle, const FourCorners& face,
                      BoxFaceClip3d& clip) {
    // A corner's height over a side, sign (coordinate - bound), rounds monotonically with the
    // coordinate, so the face's highest corner over a side is its least or greatest coordinate
    // along the side's axis, to the bit: one height a side says whether the side cuts.
    // Taken pairwise (two independent halves, then one): only the heights' comparisons read them,
    // which a zero's sign, all that the order could change, does not affect.
    const auto least = [](const double* x) { return std::min(std::min(x[0], x[1]), std::min(x[2], x[3])); };
    const auto greatest = [](const double* x) { return std::max(std::max(x[0], x[1]), std::max(x[2], x[3])); };
    const double least_m[2] = {least(face.u_m), least(face.v_m)};
    const double greatest_m[2] = {greatest(face.u_m), greatest(face.v_m)};
    double highest_m[4];  // [m] the highest corner's height over each side
    unsigned cutting_sides = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        const RectangleSide& side = rectangle.sides[k];
        const double extreme_m = side.sign > 0.0 ? greatest_m[side.axis] : least_m[side.axis];
        highest_m[k] = side.sign * (extreme_m - side.bound_m);
        cutting_sides |= static_cast<unsigned>(!(highest_m[k] <= side.slack_m)) << k;
    }
    if (cutting_sides == 0) {  // every side skips: the face as it is
        write_uncut(inc, inc_face, ref_face, face, clip);
        return true;
    }
    if ((cutting_sides & (cutting_sides - 1)) != 0) return false;  // two sides or more cut
    const std::size_t k = static_cast<std::size_t>(std::countr_zero(cutting_sides));
    const double reach_m = std::max(std::max(-least_m[0], greatest_m[0]), std::max(-least_m[1], greatest_m[1]));
    for (std::size_t j = k + 1; j < 4; ++j) {
        const double half_slack_m = 0.5 * rectangle.sides[j].slack_m;
        if (!(highest_m[j] <= half_slack_m && 1e-12 * (std::abs(reach_m) + std::abs(rectangle.sides[j].bound_m)) < half_slack_m))
            return false;
    }
    cut_by_one_side(ref, ref_face, inc, inc_face, rectangle.sides[k], k, face, clip);
    return true;
}

// A box's face of 4 corners, loaded: the one pass where it can decide, the passes otherwise.
[[gnu::always_inline]] inline bool clip_four_corners(const PosedPolyhedron& ref, std::uint32_t ref_face,
                                                     const PosedPolyhedron& inc, std::uint32_t inc_face,
                                                     const RectangleInFrame& rectangle, const FourCorners& face,
                                                     BoxFaceClip3d& clip) {
    if (clip_in_one_pass(ref, ref_face, inc, inc_face, rectangle, face, clip)) return true;
    write_four_corners(inc, inc_face, ref_face, face, clip);
    return clip_by_passes(ref, ref_face, inc_face, rectangle, 4, clip);
}

// Two boxes' face clip from their frames (clip_boxes_where_below). The incident corners are
// inc's centre +/- h_j d_j (BoxFrame3d::vertex_corner says which signs), so in the reference
// face's frame each is the centre's (u, v, w), three dots, plus sums of h_j times the pair's dots
// already taken. The rectangle, from its corner 0 along e_u and e_v, spans 0 to U = +/- 2 h_u
// and 0 to V = +/- 2 h_v (its corner 0's bits give the signs, its corner 1's which way its side
// 0 runs). What the vertices give (int11's loaders) differs from this by round-off and by
// box_frame's tolerances (a vertex 1e-12 of its box's size off its corner, directions square to
// 1e-12), bounded by error_m; every decision is taken only where the bound cannot turn it.
struct BoxesInFrame {
    FourCorners face;
    double span_m[2];          ///< [m] U and V: the rectangle spans 0 to span_m[axis] along axis
    double slack_m[2];         ///< [m] the slack of the sides bounding axis (1e-9 of their length)
    std::size_t side_at_0[2];  ///< the number of the side at 0 along axis
    std::size_t side_at_span[2];
    double error_m;  ///< [m] bound on any coordinate's difference from the vertices' (a height's: twice it)
    double size_m;   ///< [m] the sum of both boxes' edge lengths along their three directions
};

[[gnu::always_inline]] inline BoxesInFrame boxes_in_frame(const PosedPolyhedron& ref, std::uint32_t ref_face,
                                                          const PosedPolyhedron& inc, std::uint32_t inc_face,
                                                          const double (*dots)[3], bool ref_is_a,
                                                          const BoxFaceClip3d& clip) {
    BoxesInFrame f;
    const BoxFrame3d& ref_box = *ref.box;
    const BoxFrame3d& inc_box = *inc.box;
    const int i = ref_box.face_direction[ref_face];
    const int along_u = i == 0 ? 1 : 0;  // load_axes's e_u
    const int along_v = 3 - i - along_u;
    // e_v = n x e_u is +/- ref's third direction (to round-off and to the directions' squareness).
    const bool v_along = dot(clip.e_v, ref.directions[along_v]) > 0.0;
    const double sign_v = v_along ? 1.0 : -1.0;
    const double sign_n = ref_box.face_sign[ref_face];  // n = sign_n ref's direction i, to the bit
    const double ref_half_m[3] = {ref_box.half_lengths_m.x, ref_box.half_lengths_m.y, ref_box.half_lengths_m.z};
    const double inc_half_m[3] = {inc_box.half_lengths_m.x, inc_box.half_lengths_m.y, inc_box.half_lengths_m.z};
    // The rectangle: from corner 0 towards the other side of each direction.
    const std::size_t* ref_corners = ref.shape->faces[ref_face].data();
    const unsigned corner_0 = ref_box.vertex_corner[ref_corners[0]];
    const unsigned corner_1 = ref_box.vertex_corner[ref_corners[1]];
    const bool plus_u = ((corner_0 >> along_u) & 1u) == 0;  // corner 0 on the - side: U > 0
    const bool plus_v = (((corner_0 >> along_v) & 1u) == 0) == v_along;
    f.span_m[0] = plus_u ? 2.0 * ref_half_m[along_u] : -2.0 * ref_half_m[along_u];
    f.span_m[1] = plus_v ? 2.0 * ref_half_m[along_v] : -2.0 * ref_half_m[along_v];
    f.slack_m[0] = 1e-9 * 2.0 * ref_half_m[along_v];  // the sides bounding u run along v
    f.slack_m[1] = 1e-9 * 2.0 * ref_half_m[along_u];
    // Side 0 runs from corner 0 along v (a bound on u at 0) or along u (a bound on v at 0); the
    // sides go round: along v, along u, along v, along u, or the other way.
    const bool first_along_v = (((corner_0 ^ corner_1) >> along_v) & 1u) != 0;
    f.side_at_0[0] = first_along_v ? 0 : 3;
    f.side_at_span[0] = first_along_v ? 2 : 1;
    f.side_at_0[1] = first_along_v ? 3 : 0;
    f.side_at_span[1] = first_along_v ? 1 : 2;
    // The incident corners: h_j d_j in the frame from the dots (ref's direction k . inc's j).
    const Vec3 r = inc.centroid_m - clip.origin_m;
    const double centre_u_m = dot(r, clip.e_u), centre_v_m = dot(r, clip.e_v), centre_w_m = dot(r, clip.n);
    const double* row_u = dots[along_u];
    const double* row_v = dots[along_v];
    const double* row_n = dots[i];
    double half_u_m[3], half_v_m[3], half_w_m[3];
    for (int j = 0; j < 3; ++j) {
        const double d_u = ref_is_a ? row_u[j] : dots[j][along_u];
        const double d_v = ref_is_a ? row_v[j] : dots[j][along_v];
        const double d_n = ref_is_a ? row_n[j] : dots[j][i];
        half_u_m[j] = inc_half_m[j] * d_u;
        half_v_m[j] = sign_v * inc_half_m[j] * d_v;
        half_w_m[j] = sign_n * inc_half_m[j] * d_n;
    }
    // The face lies on one side of inc's direction j0 (its corners share that bit) and its
    // corners differ along the other two, j1 and j2: the four sums +/- a +/- b formed once a
    // coordinate, each corner picking its own by its two bits.
    const int j0 = inc_box.face_direction[inc_face];
    const int j1 = j0 == 2 ? 0 : j0 + 1;
    const int j2 = 3 - j0 - j1;
    const double sign_0 = inc_box.face_sign[inc_face];
    double sums_m[3][4];  // [u, v, w][bit j1 + 2 bit j2]
    const double centres_m[3] = {centre_u_m, centre_v_m, centre_w_m};
    const double* halves_m[3] = {half_u_m, half_v_m, half_w_m};
    for (int c = 0; c < 3; ++c) {
        const double base_m = centres_m[c] + sign_0 * halves_m[c][j0];
        const double a_m = halves_m[c][j1], b_m = halves_m[c][j2];
        const double minus_a_m = base_m - a_m, plus_a_m = base_m + a_m;
        sums_m[c][0] = minus_a_m - b_m;
        sums_m[c][1] = plus_a_m - b_m;
        sums_m[c][2] = minus_a_m + b_m;
        sums_m[c][3] = plus_a_m + b_m;
    }
    const std::size_t* inc_corners = inc.shape->faces[inc_face].data();
    for (std::size_t k = 0; k < 4; ++k) {
        const unsigned corner = inc_box.vertex_corner[inc_corners[k]];
        const unsigned pick = ((corner >> j1) & 1u) | (((corner >> j2) & 1u) << 1);
        f.face.u_m[k] = sums_m[0][pick];
        f.face.v_m[k] = sums_m[1][pick];
        f.face.w_m[k] = sums_m[2][pick];
    }
    // The bound: a few dozen roundings of the positions' size (the vertices are placed where the
    // world is, these from the offset between the boxes), and 1e-11 of the boxes' size for what
    // box_frame lets a box be off a true box (e_v then 3e-12 off ref's third direction).
    const auto l1 = [](Vec3 x) { return std::abs(x.x) + std::abs(x.y) + std::abs(x.z); };
    f.size_m = 2.0 * (ref_half_m[0] + ref_half_m[1] + ref_half_m[2] + inc_half_m[0] + inc_half_m[1] + inc_half_m[2]);
    constexpr double unit_round_off = 0.5 * std::numeric_limits<double>::epsilon();
    f.error_m = 64.0 * unit_round_off * (l1(inc.centroid_m) + l1(clip.origin_m) + f.size_m) + 1e-11 * (l1(r) + f.size_m);
    return f;
}

// clip_boxes_where_below's decisions on the frames' coordinates, where error_m cannot turn them;
// false where it could (the caller then takes the vertices). Each corner must be below the plane
// by more than the bound, or all above it (no point, as clip_box_face_where_below says); each
// side's highest corner (the face's extreme along its axis, as the one pass takes it) must
// differ from the slack by more than twice the bound, so that a side that does not cut has every
// corner, and every corner a cut makes between two of them, inside it by that margin in either
// clip; at most one side cuts. For that side, each corner's height must differ from the slack
// by the margin and exceed 1e-8 of the boxes' size: a cut's new side along an incident edge is
// at least as long as the height of its corner there (a coordinate changes along an edge by at
// most its length), so no side of the polygon is short (corner_shares_without_groups's 1e-9 of
// the longest, which is below the incident face's diagonal) in either clip. The face as it is,
// or the one pass's cut, is then the passes' polygon here and there: the same corners, keys and
// order, the positions to round-off.
bool decide_boxes_in_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                           std::uint32_t inc_face, const BoxesInFrame& f, BoxFaceClip3d& clip) {
    const double error_m = f.error_m;
    bool all_below = true, all_above = true;
    for (std::size_t k = 0; k < 4; ++k) {
        all_below &= f.face.w_m[k] < -error_m;
        all_above &= f.face.w_m[k] > error_m;
    }
    if (all_above) {
        clip.count = 0;
        clip.corners = clip.buffers[0].data();
        return true;
    }
    if (!all_below) return false;
    const auto least = [](const double* x) { return std::min(std::min(x[0], x[1]), std::min(x[2], x[3])); };
    const auto greatest = [](const double* x) { return std::max(std::max(x[0], x[1]), std::max(x[2], x[3])); };
    const double margin_m = 2.0 * error_m;
    // Per axis: the sides at 0 and at the span, one facing - and one facing +.
    RectangleSide sides[2][2];  // [axis][0: the side at the lesser bound, 1: at the greater]
    std::size_t side_numbers[2][2];
    unsigned cuts = 0;  // bit 2 axis + which
    bool decided = true;
    for (int axis = 0; axis < 2; ++axis) {
        const double* x = axis == 0 ? f.face.u_m : f.face.v_m;
        const double span_m = f.span_m[axis];
        const double lower_m = std::min(0.0, span_m), upper_m = std::max(0.0, span_m);
        const double slack_m = f.slack_m[axis];
        sides[axis][0] = {axis, -1.0, lower_m, slack_m};
        sides[axis][1] = {axis, 1.0, upper_m, slack_m};
        side_numbers[axis][0] = span_m > 0.0 ? f.side_at_0[axis] : f.side_at_span[axis];
        side_numbers[axis][1] = span_m > 0.0 ? f.side_at_span[axis] : f.side_at_0[axis];
        const double below_m = lower_m - least(x);     // the highest corner over the lesser side
        const double above_m = greatest(x) - upper_m;  // and over the greater
        decided &= std::abs(below_m - slack_m) > margin_m;
        decided &= std::abs(above_m - slack_m) > margin_m;
        cuts |= static_cast<unsigned>(below_m > slack_m) << (2 * axis);
        cuts |= static_cast<unsigned>(above_m > slack_m) << (2 * axis + 1);
    }
    if (!decided) return false;
    if (cuts == 0) {
        write_uncut(inc, inc_face, ref_face, f.face, clip);
        return true;
    }
    if ((cuts & (cuts - 1)) != 0) return false;  // two sides or more cut
    const unsigned cut = static_cast<unsigned>(std::countr_zero(cuts));
    const RectangleSide& side = sides[cut >> 1][cut & 1u];
    const double* along = side.axis == 0 ? f.face.u_m : f.face.v_m;
    const double shortest_piece_m = 1e-8 * f.size_m + margin_m;
    for (std::size_t c = 0; c < 4; ++c) {
        const double height_m = side.sign * (along[c] - side.bound_m);
        decided &= std::abs(height_m - side.slack_m) > margin_m;
        decided &= std::abs(height_m) > shortest_piece_m;
    }
    if (!decided) return false;
    cut_by_one_side(ref, ref_face, inc, inc_face, side, side_numbers[cut >> 1][cut & 1u], f.face, clip);
    return true;
}

}  // namespace

bool clip_boxes_from_frames(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                            std::uint32_t inc_face, const double (*dots)[3], bool ref_is_a, BoxFaceClip3d& clip) {
    load_axes(ref, ref_face, clip);
    return decide_boxes_in_frame(ref, ref_face, inc, inc_face,
                                 boxes_in_frame(ref, ref_face, inc, inc_face, dots, ref_is_a, clip), clip);
}

bool clip_boxes_where_below(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                            std::uint32_t inc_face, const double (*dots)[3], bool ref_is_a, BoxFaceClip3d& clip) {
    return clip_boxes_from_frames(ref, ref_face, inc, inc_face, dots, ref_is_a, clip) ||
           clip_box_face_where_below(ref, ref_face, inc, inc_face, clip);
}

bool box_face_clip_applies(const PosedPolyhedron& ref, const PosedPolyhedron& inc, std::uint32_t inc_face) {
    return ref.box != nullptr && ref.box->is_box && inc.shape->faces[inc_face].size() <= box_clip_most_incident_corners;
}

bool clip_box_face_in_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                            std::uint32_t inc_face, BoxFaceClip3d& clip) {
    RectangleInFrame rectangle;
    load_frame(ref, ref_face, clip, rectangle);
    if (inc.shape->faces[inc_face].size() == 4)  // a box's face: the one pass tried on its coordinates
        return clip_four_corners(ref, ref_face, inc, inc_face, rectangle, load_four_corners(inc, inc_face, clip), clip);
    const std::size_t count = load_incident_face(ref_face, inc, inc_face, clip);
    return clip_by_passes(ref, ref_face, inc_face, rectangle, count, clip);
}

bool clip_box_face_where_below(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                               std::uint32_t inc_face, BoxFaceClip3d& clip) {
    const auto& inc_corners = inc.shape->faces[inc_face];
    if (inc_corners.size() != 4) return clip_box_face_in_frame(ref, ref_face, inc, inc_face, clip);
    // The corners first (the rectangle not yet): with none below the plane no corner of the
    // polygon is, since a crossing's height lies between its two ends' to the bit (w_h + t (w_n -
    // w_h) with t in [0, 1] rounds to a value at or above the lower end when both ends are at or
    // above 0), and a crossing of crossings likewise.
    load_axes(ref, ref_face, clip);
    const FourCorners face = load_four_corners(inc, inc_face, clip);
    if (!(face.w_m[0] < 0.0 || face.w_m[1] < 0.0 || face.w_m[2] < 0.0 || face.w_m[3] < 0.0)) {
        clip.count = 0;
        clip.corners = clip.buffers[0].data();
        return true;
    }
    RectangleInFrame rectangle;
    load_rectangle(ref, ref_face, clip, rectangle);
    return clip_four_corners(ref, ref_face, inc, inc_face, rectangle, face, clip);
}

bool clip_box_face_by_passes(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                             std::uint32_t inc_face, BoxFaceClip3d& clip) {
    RectangleInFrame rectangle;
    load_frame(ref, ref_face, clip, rectangle);
    const std::size_t count = load_incident_face(ref_face, inc, inc_face, clip);
    return clip_by_passes(ref, ref_face, inc_face, rectangle, count, clip);
}

bool clip_box_face_in_one_pass(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                               std::uint32_t inc_face, BoxFaceClip3d& clip) {
    RectangleInFrame rectangle;
    load_frame(ref, ref_face, clip, rectangle);
    if (inc.shape->faces[inc_face].size() != 4) return false;
    return clip_in_one_pass(ref, ref_face, inc, inc_face, rectangle, load_four_corners(inc, inc_face, clip), clip);
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
