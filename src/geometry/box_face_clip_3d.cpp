#include "geometry/box_face_clip_3d.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

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
    const Vec3 n = face_normal(ref, ref_face);
    const int normal_direction = ref.box->face_direction[ref_face];
    const Vec3 e_u = ref.directions[normal_direction == 0 ? 1 : 0];
    clip.e_u = e_u;
    clip.e_v = cross(n, e_u);
    clip.n = n;
    clip.origin_m = ref.vertices_m[ref.box->face_corners[ref_face][0]];
}

// The rectangle in the frame (the axes loaded).
[[gnu::always_inline]] inline void load_rectangle(const PosedPolyhedron& ref, std::uint32_t ref_face,
                                                  const BoxFaceClip3d& clip, RectangleInFrame& rectangle) {
    const auto& ref_corners = ref.box->face_corners[ref_face];
    const Vec3 origin_m = clip.origin_m;
    const Vec3 e_u = clip.e_u;
    const Vec3 e_v = clip.e_v;
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 r = ref.vertices_m[ref_corners[k]] - origin_m;
        rectangle.corner_u_m[k] = dot(r, e_u);
        rectangle.corner_v_m[k] = dot(r, e_v);
    }
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

// The frame and the rectangle in it: what both clips start from.
[[gnu::always_inline]] inline void load_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, BoxFaceClip3d& clip,
                                              RectangleInFrame& rectangle) {
    load_axes(ref, ref_face, clip);
    load_rectangle(ref, ref_face, clip, rectangle);
}

// The incident face's corner (vertex) and edge numbers, and how many: from the incident body's box
// frame where it is a box (BoxFrame3d::face_corners and face_edges, the shape's numbers), else from
// its shape and edges. Why: the frame is in cache, read by the box-box test just before, where the
// shape's face list and its vertex numbers are two heap blocks a face, reached through the body: on
// an Intel Xeon VM at the 1e4-brick wall the clip waited on them (a third of its time).
[[gnu::always_inline]] inline bool is_framed_box(const PosedPolyhedron& p) { return p.box != nullptr && p.box->is_box; }
[[gnu::always_inline]] inline std::size_t incident_corner_count(const PosedPolyhedron& inc, std::uint32_t inc_face) {
    return is_framed_box(inc) ? 4 : inc.shape->faces[inc_face].size();
}
[[gnu::always_inline]] inline std::uint32_t incident_vertex(const PosedPolyhedron& inc, std::uint32_t inc_face, std::size_t k) {
    return is_framed_box(inc) ? inc.box->face_corners[inc_face][k] : static_cast<std::uint32_t>(inc.shape->faces[inc_face][k]);
}
[[gnu::always_inline]] inline std::uint32_t incident_edge(const PosedPolyhedron& inc, std::uint32_t inc_face, std::size_t k) {
    return is_framed_box(inc) ? inc.box->face_edges[inc_face][k] : inc.edges->face_edges[inc_face][k];
}

// Corner k of the incident face as the polygon's first form holds it: at (u, v, w), the face's
// own corner, on the reference face, running along the face's edge k to the next corner.
[[gnu::always_inline]] inline FaceCorner incident_corner(const PosedPolyhedron& inc, std::uint32_t inc_face, std::uint32_t ref_face, std::size_t k,
                           double u_m, double v_m, double w_m) {
    return {u_m,
            v_m,
            w_m,
            feature_3d(FeatureKind3d::vertex, incident_vertex(inc, inc_face, k)),
            feature_3d(FeatureKind3d::face, ref_face),
            feature_3d(FeatureKind3d::edge, incident_edge(inc, inc_face, k)),
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
    const Vec3 origin_m = clip.origin_m, e_u = clip.e_u, e_v = clip.e_v, n = clip.n;
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 r = inc.vertices_m[incident_vertex(inc, inc_face, k)] - origin_m;
        face.u_m[k] = dot(r, e_u);
        face.v_m[k] = dot(r, e_v);
        face.w_m[k] = dot(r, n);
    }
    return face;
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

// The Sutherland-Hodgman clip of the polygon in clip.buffers[from_buffer] (count corners), side by
// side from side first_side on: the whole clip of the loaded face from side 0 and buffer 0, or the
// rest of it after the one pass's cut (buffer 1, the sides after the cut's).
bool clip_by_passes(const PosedPolyhedron& ref, std::uint32_t ref_face, std::uint32_t inc_face,
                    const RectangleInFrame& rectangle, std::size_t count, BoxFaceClip3d& clip,
                    std::size_t first_side = 0, std::size_t from_buffer = 0) {
    const auto& ref_corners = ref.box->face_corners[ref_face];
    FaceCorner* here_polygon = clip.buffers[from_buffer].data();
    FaceCorner* next_polygon = clip.buffers[1 - from_buffer].data();
    for (std::size_t k = first_side; k < 4 && count > 0; ++k) {
        const std::size_t k_next = (k + 1) % 4;
        const RectangleSide& side = rectangle.sides[k];
        const std::uint32_t ref_edge = feature_3d(FeatureKind3d::edge, ref.box->face_edges[ref_face][k]);
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

// Which sides cut the face of 4 corners (have a corner beyond their slack), and the highest
// corner's height over each. A corner's height over a side, sign (coordinate - bound), rounds
// monotonically with the coordinate, so the face's highest corner over a side is its least or
// greatest coordinate along the side's axis, to the bit: one height a side says whether the side
// cuts, as the passes' test of every corner would.
struct SideCuts {
    double highest_m[4];  ///< [m] the highest corner's height over each side
    double reach_m;       ///< [m] the largest |u| or |v| of the face's corners
    unsigned cutting;     ///< bit k: side k cuts
};

SideCuts side_cuts(const RectangleInFrame& rectangle, const FourCorners& face) {
    // Taken pairwise (two independent halves, then one): only the heights' comparisons read them,
    // which a zero's sign, all that the order could change, does not affect.
    const auto least = [](const double* x) { return std::min(std::min(x[0], x[1]), std::min(x[2], x[3])); };
    const auto greatest = [](const double* x) { return std::max(std::max(x[0], x[1]), std::max(x[2], x[3])); };
    const double least_m[2] = {least(face.u_m), least(face.v_m)};
    const double greatest_m[2] = {greatest(face.u_m), greatest(face.v_m)};
    SideCuts cuts;
    cuts.cutting = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        const RectangleSide& side = rectangle.sides[k];
        const double extreme_m = side.sign > 0.0 ? greatest_m[side.axis] : least_m[side.axis];
        cuts.highest_m[k] = side.sign * (extreme_m - side.bound_m);
        cuts.cutting |= static_cast<unsigned>(!(cuts.highest_m[k] <= side.slack_m)) << k;
    }
    cuts.reach_m = std::max(std::max(-least_m[0], greatest_m[0]), std::max(-least_m[1], greatest_m[1]));
    return cuts;
}

// Whether the sides after side k skip once k has cut, decided without the cut corners' heights: a
// cut corner lies on a side of the face between two of its corners, to round-off (a few 1e-16 of
// the largest coordinate), so if every corner is inside those sides by half their slack and that
// half exceeds 1e-12 of the coordinates, so is every cut corner.
bool later_sides_skip(const RectangleInFrame& rectangle, const SideCuts& cuts, std::size_t k) {
    for (std::size_t j = k + 1; j < 4; ++j) {
        const double half_slack_m = 0.5 * rectangle.sides[j].slack_m;
        if (!(cuts.highest_m[j] <= half_slack_m &&
              1e-12 * (std::abs(cuts.reach_m) + std::abs(rectangle.sides[j].bound_m)) < half_slack_m))
            return false;
    }
    return true;
}

// The face as it is, no side cutting: its corners with their keys in buffers[0].
void keep_four_corners(const PosedPolyhedron& inc, std::uint32_t inc_face, std::uint32_t ref_face,
                       const FourCorners& face, BoxFaceClip3d& clip) {
    FaceCorner* polygon = clip.buffers[0].data();
    for (std::size_t i = 0; i < 4; ++i)
        polygon[i] = incident_corner(inc, inc_face, ref_face, i, face.u_m[i], face.v_m[i], face.w_m[i]);
    clip.count = 4;
    clip.corners = polygon;
}

// The face of 4 corners cut by side k alone, as the passes cut it when the sides before k skip (the
// same heights, the same formula, the same keys: none of the face's own corners lies on a reference
// side), written once with its keys into buffers[1].
void cut_four_corners(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                      std::uint32_t inc_face, const RectangleInFrame& rectangle, const FourCorners& face,
                      std::size_t k, BoxFaceClip3d& clip) {
    constexpr std::size_t count = 4;
    // The incident face's corner and edge numbers read once, into locals: the polygon's stores
    // could otherwise be taken for writes to the lists' entries, which would then be read again.
    std::uint32_t corner_ids[count], edge_ids[count];
    for (std::size_t i = 0; i < count; ++i) {
        corner_ids[i] = incident_vertex(inc, inc_face, i);
        edge_ids[i] = incident_edge(inc, inc_face, i);
    }
    const std::uint32_t on_reference_face = feature_3d(FeatureKind3d::face, ref_face);
    const RectangleSide& side = rectangle.sides[k];
    const double* along = side.axis == 0 ? face.u_m : face.v_m;
    double heights[count];
    for (std::size_t i = 0; i < count; ++i) heights[i] = side.sign * (along[i] - side.bound_m);
    const std::uint32_t ref_edge = feature_3d(FeatureKind3d::edge, ref.box->face_edges[ref_face][k]);
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
                              feature_3d(FeatureKind3d::vertex, corner_ids[i]),
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

// Where no side cuts the face: the face kept as it is (keep_four_corners), and true.
bool kept_uncut(const PosedPolyhedron& inc, std::uint32_t inc_face, std::uint32_t ref_face, const FourCorners& face,
                const SideCuts& cuts, BoxFaceClip3d& clip) {
    if (cuts.cutting != 0) return false;
    keep_four_corners(inc, inc_face, ref_face, face, clip);
    return true;
}

// Whether side k's cut is the whole clip: k is the only side that cuts and the sides after it skip
// (later_sides_skip).
bool cut_is_whole_clip(const RectangleInFrame& rectangle, const SideCuts& cuts, std::size_t k) {
    return (cuts.cutting & (cuts.cutting - 1)) == 0 && later_sides_skip(rectangle, cuts, k);
}

// The clip in one pass, where it gives the passes' polygon to the bit: when no side cuts the face,
// or side k's cut is the whole clip (cut_is_whole_clip). The sides before the cut skip as the
// passes do (side_cuts). The polygon is written once, with its keys, where it ends: buffers[0]
// when no side cuts, buffers[1] when one does. Returns false, clip untouched but for its frame,
// when it cannot say: two sides or more cut, or a later side holds a corner within half its slack
// or its half slack is within 1e-12 of the coordinates.
bool clip_in_one_pass(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                      std::uint32_t inc_face, const RectangleInFrame& rectangle, const FourCorners& face,
                      BoxFaceClip3d& clip) {
    const SideCuts cuts = side_cuts(rectangle, face);
    if (kept_uncut(inc, inc_face, ref_face, face, cuts, clip)) return true;
    const std::size_t k = static_cast<std::size_t>(std::countr_zero(cuts.cutting));
    if (!cut_is_whole_clip(rectangle, cuts, k)) return false;
    cut_four_corners(ref, ref_face, inc, inc_face, rectangle, face, k, clip);
    return true;
}

// A box's face of 4 corners, loaded: the one pass's cut by the first side that cuts, then, where
// that cut is not the whole clip, the passes from the next side on. The passes' polygon to the bit:
// their sides before the first cutting side skip and their cut by it is the one pass's. Why: on a
// shaken wall half the bed joints are cut by two sides (a brick shifted out of plane over the one
// below), and the passes started again from the face, making once more the cut the one pass had
// just decided.
[[gnu::always_inline]] inline bool clip_four_corners(const PosedPolyhedron& ref, std::uint32_t ref_face,
                                                     const PosedPolyhedron& inc, std::uint32_t inc_face,
                                                     const RectangleInFrame& rectangle, const FourCorners& face,
                                                     BoxFaceClip3d& clip) {
    const SideCuts cuts = side_cuts(rectangle, face);
    if (kept_uncut(inc, inc_face, ref_face, face, cuts, clip)) return true;
    const std::size_t k = static_cast<std::size_t>(std::countr_zero(cuts.cutting));
    cut_four_corners(ref, ref_face, inc, inc_face, rectangle, face, k, clip);
    if (cut_is_whole_clip(rectangle, cuts, k)) return true;
    return clip_by_passes(ref, ref_face, inc_face, rectangle, clip.count, clip, k + 1, 1);
}

}  // namespace

bool box_face_clip_applies(const PosedPolyhedron& ref, const PosedPolyhedron& inc, std::uint32_t inc_face) {
    return is_framed_box(ref) && incident_corner_count(inc, inc_face) <= box_clip_most_incident_corners;
}

bool clip_box_face_in_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                            std::uint32_t inc_face, BoxFaceClip3d& clip) {
    RectangleInFrame rectangle;
    load_frame(ref, ref_face, clip, rectangle);
    if (incident_corner_count(inc, inc_face) == 4)  // a box's face: the first cut in one pass
        return clip_four_corners(ref, ref_face, inc, inc_face, rectangle, load_four_corners(inc, inc_face, clip), clip);
    const std::size_t count = load_incident_face(ref_face, inc, inc_face, clip);
    return clip_by_passes(ref, ref_face, inc_face, rectangle, count, clip);
}

bool clip_box_face_where_below(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                               std::uint32_t inc_face, BoxFaceClip3d& clip) {
    if (incident_corner_count(inc, inc_face) != 4) return clip_box_face_in_frame(ref, ref_face, inc, inc_face, clip);
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
    if (incident_corner_count(inc, inc_face) != 4) return false;
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
