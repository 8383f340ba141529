#include "geometry/polyhedron_contact_3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "geometry/box_face_clip_3d.hpp"
#include "geometry/corner_share_3d.hpp"
#include "laws/double_lanes.hpp"

namespace blockdem {
namespace {

struct Interval {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
};

Interval project(const PosedPolyhedron& p, Vec3 axis) {
    Interval r;
    const std::size_t n = p.shape->vertices_m.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double s = dot(axis, p.vertices_m[i]);
        r.lo = std::min(r.lo, s);
        r.hi = std::max(r.hi, s);
    }
    return r;
}

// The least overlap over the face normals of r: how far o's deepest vertex lies beyond each
// face's plane (negative: below it), the largest kept. Only the outward side of each face is
// tested: the faces of A, the faces of B turned over and the edge pairs' cross products are the
// normals of the Minkowski difference A - B, so if the bodies are apart one of these shows it
// (the edge axes are tested both ways). Sets apart when a face plane separates them.
struct FaceAxis {
    double separation_m = -std::numeric_limits<double>::infinity();
    std::uint32_t face = 0;
};

FaceAxis best_face_axis(const PosedPolyhedron& r, const PosedPolyhedron& o, bool& apart) {
    FaceAxis best;
    const std::size_t vertices = o.shape->vertices_m.size();
    for (std::uint32_t f = 0; f < r.shape->faces.size(); ++f) {
        const Vec3 n = face_normal(r, f);
        double deepest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < vertices; ++i) deepest = std::min(deepest, dot(n, o.vertices_m[i]));
        const double separation = deepest - dot(n, r.vertices_m[r.shape->faces[f][0]]);
        if (separation > 0.0) { apart = true; return best; }
        if (separation > best.separation_m) best = {separation, f};
    }
    return best;
}

struct EdgeAxis {
    double separation_m = -std::numeric_limits<double>::infinity();
    Vec3 axis;                      ///< from a to b
    std::uint32_t direction_a = 0;
    std::uint32_t direction_b = 0;
};

EdgeAxis best_edge_axis(const PosedPolyhedron& a, const PosedPolyhedron& b, bool& apart) {
    EdgeAxis best;
    for (std::uint32_t i = 0; i < a.edges->directions.size(); ++i) {
        for (std::uint32_t j = 0; j < b.edges->directions.size(); ++j) {
            Vec3 axis = cross(a.directions[i], b.directions[j]);
            const double l = length(axis);
            if (l < 1e-6) continue;  // parallel edges: their plane's normal is a face axis already tested
            axis = (1.0 / l) * axis;
            const Interval ai = project(a, axis);
            const Interval bi = project(b, axis);
            const double along = bi.lo - ai.hi;     // b beyond a along +axis
            const double against = ai.lo - bi.hi;   // b beyond a along -axis
            if (along > 0.0 || against > 0.0) { apart = true; return best; }
            const double separation = std::max(along, against);
            if (separation > best.separation_m) best = {separation, along >= against ? axis : -axis, i, j};
        }
    }
    return best;
}

// Two boxes: the same axes as best_face_axis and best_edge_axis, in a's frame (geometry/
// box_frame_3d.hpp). dots[i][j] = a's direction i . b's j, taken once; everything else is a sum of
// their products with the half lengths and the centres' offset along a's directions (along b's where
// b's faces are measured).
struct BoxPair {
    Vec3 offset_m;          ///< [m] b's centre minus a's, world frame
    double dots[3][3];      ///< a.directions[i] . b.directions[j]
    double abs_dots[3][3];  ///< their absolute values
    double offset_a_m[3];   ///< [m] offset_m along a's direction i
};

// |x| in each lane: the sign bit cleared, as std::abs does (andpd on x86-64).
inline DoubleLanes lanes_abs(DoubleLanes x) {
    constexpr LaneMask magnitude = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
    return reinterpret_cast<DoubleLanes>(reinterpret_cast<LaneMask>(x) & magnitude);
}

// The pair's dots two at a time, in the two lanes of a 16-byte vector (laws/double_lanes.hpp, the
// 3-D law's type: each lane rounds as the scalar expression written the same way, so the same
// bits as dot()): a's directions 0 and 1 in the lanes against each of b's, a's direction 2 against
// b's 0 and 1, and against b's 2 beside the offset along it. Why: the scalar dots, left to the
// compiler, took 12 dot products with a shuffle or a spill for about every product (165
// instructions a candidate pair at 1e4, a quarter of the box-box test). The lanes of a's first two
// directions are kept for a's faces (first_rows), read there without going through memory.
struct FirstRows {
    DoubleLanes abs_dots[3];  ///< {|dots[0][j]|, |dots[1][j]|} for j = 0, 1, 2
    DoubleLanes offset_a_m;   ///< [m] {offset_a_m[0], offset_a_m[1]}
    DoubleLanes abs_dots_2;   ///< {|dots[2][0]|, |dots[2][1]|}
};

[[gnu::always_inline]] inline BoxPair box_pair(const PosedPolyhedron& a, const PosedPolyhedron& b,
                                               FirstRows& first_rows) {
    BoxPair p;
    p.offset_m = *b.centroid_m - *a.centroid_m;
    const Vec3* ad = a.directions;
    const Vec3* bd = b.directions;
    const Vec3 o = p.offset_m;
    const DoubleLanes ax = {ad[0].x, ad[1].x}, ay = {ad[0].y, ad[1].y}, az = {ad[0].z, ad[1].z};
    for (int j = 0; j < 3; ++j) {
        // a.x * b.x + a.y * b.y + a.z * b.z in each lane, as dot() rounds it.
        const DoubleLanes column = ax * lanes(bd[j].x) + ay * lanes(bd[j].y) + az * lanes(bd[j].z);
        p.dots[0][j] = column[0];
        p.dots[1][j] = column[1];
        first_rows.abs_dots[j] = lanes_abs(column);
        p.abs_dots[0][j] = first_rows.abs_dots[j][0];
        p.abs_dots[1][j] = first_rows.abs_dots[j][1];
    }
    first_rows.offset_a_m = ax * lanes(o.x) + ay * lanes(o.y) + az * lanes(o.z);
    p.offset_a_m[0] = first_rows.offset_a_m[0];
    p.offset_a_m[1] = first_rows.offset_a_m[1];
    const DoubleLanes a2x = lanes(ad[2].x), a2y = lanes(ad[2].y), a2z = lanes(ad[2].z);
    const DoubleLanes row_2 = a2x * DoubleLanes{bd[0].x, bd[1].x} + a2y * DoubleLanes{bd[0].y, bd[1].y} +
                              a2z * DoubleLanes{bd[0].z, bd[1].z};
    const DoubleLanes last = a2x * DoubleLanes{bd[2].x, o.x} + a2y * DoubleLanes{bd[2].y, o.y} +
                             a2z * DoubleLanes{bd[2].z, o.z};
    p.dots[2][0] = row_2[0];
    p.dots[2][1] = row_2[1];
    p.dots[2][2] = last[0];
    p.offset_a_m[2] = last[1];
    first_rows.abs_dots_2 = lanes_abs(row_2);
    p.abs_dots[2][0] = first_rows.abs_dots_2[0];
    p.abs_dots[2][1] = first_rows.abs_dots_2[1];
    p.abs_dots[2][2] = std::abs(last[0]);
    return p;
}

// The best face along one of r's directions: separation_m[i] for i = 0, 1, 2 and the centre's
// offset along each (its sign picks the face), the first of the best (the lower face on an exact
// tie, as a loop over the faces in order keeping the first of equals would choose). Sets apart
// when a face plane separates them.
[[gnu::always_inline]] inline FaceAxis best_box_face(const BoxFrame3d& r, const double separation_m[3],
                                                     const double centre_m[3], bool& apart) {
    // The face along direction i facing the other box's centre; on centre_m = 0 both faces along i
    // separate as much: the lower number, as in a face loop.
    const auto facing = [&](int i, double c_m) -> std::uint32_t {
        return c_m > 0.0   ? r.face_of[i][0]
               : c_m < 0.0 ? r.face_of[i][1]
                           : std::min(r.face_of[i][0], r.face_of[i][1]);
    };
    // The best direction is kept, its face looked up once at the end; only an exact tie between two
    // directions needs both faces.
    double best_separation_m = -std::numeric_limits<double>::infinity();
    int best_direction = -1;
    for (int i = 0; i < 3; ++i) {
        if (separation_m[i] > best_separation_m ||
            (separation_m[i] == best_separation_m && best_direction >= 0 &&
             facing(i, centre_m[i]) < facing(best_direction, centre_m[best_direction]))) {
            best_separation_m = separation_m[i];
            best_direction = i;
        }
    }
    if (best_separation_m > 0.0) apart = true;
    return {best_separation_m, best_direction < 0 ? 0u : facing(best_direction, centre_m[best_direction])};
}

// a's faces against the box b. b's deepest point below the plane of a's face along +/- a's
// direction i is b's centre's projection less reach_i = sum_j h_j |a_i . b_j|, and the plane is
// a's centre's plus h_i, so that of the two faces along i the one facing b's centre (the sign of
// centre_i) separates more: separation_i = |centre_i| - reach_i - h_i. Directions 0 and 1 in the
// two lanes of first_rows (each lane as the scalar sum), direction 2 alone.
[[gnu::always_inline]] inline FaceAxis box_face_axis_of_a(const PosedPolyhedron& a, const PosedPolyhedron& b,
                                                          const BoxPair& pair, const FirstRows& first_rows,
                                                          bool& apart) {
    const Vec3 ha = a.box->half_lengths_m;
    const Vec3 hb = b.box->half_lengths_m;
    const DoubleLanes reach_01_m = lanes(hb.x) * first_rows.abs_dots[0] + lanes(hb.y) * first_rows.abs_dots[1] +
                                   lanes(hb.z) * first_rows.abs_dots[2];
    const DoubleLanes separation_01_m =
        lanes_abs(first_rows.offset_a_m) - reach_01_m - DoubleLanes{ha.x, ha.y};
    const double reach_2_m = hb.x * first_rows.abs_dots_2[0] + hb.y * first_rows.abs_dots_2[1] + hb.z * pair.abs_dots[2][2];
    const double separation_m[3] = {separation_01_m[0], separation_01_m[1],
                                    std::abs(pair.offset_a_m[2]) - reach_2_m - ha.z};
    return best_box_face(*a.box, separation_m, pair.offset_a_m, apart);
}

// The faces of b against the box a, the same sums with the roles swapped: a's reach along b's
// direction i is sum_j h_j |a_j . b_i| (the column i of the dots), and the centre is a's minus b's.
// Both face functions are inlined by force: left to itself the compiler called the one function
// they replace (a call and its frame cost more a pair than the face lookups saved in best_box_face).
[[gnu::always_inline]] inline FaceAxis box_face_axis_of_b(const PosedPolyhedron& a, const PosedPolyhedron& b,
                                                          const BoxPair& pair, bool& apart) {
    const Vec3 ha = a.box->half_lengths_m;
    const Vec3 hb = b.box->half_lengths_m;
    const double half_b[3] = {hb.x, hb.y, hb.z};
    double separation_m[3];
    double centre_m[3];
    for (int i = 0; i < 3; ++i) {
        const double reach_a_m = ha.x * pair.abs_dots[0][i] + ha.y * pair.abs_dots[1][i] + ha.z * pair.abs_dots[2][i];
        // a's centre minus b's; along b's directions only here (b's faces are skipped for most pairs
        // on a wall, aligned_beyond_round_off).
        centre_m[i] = -dot(b.directions[i], pair.offset_m);
        separation_m[i] = std::abs(centre_m[i]) - reach_a_m - half_b[i];
    }
    return best_box_face(*b.box, separation_m, centre_m, apart);
}

// The edge axes a_i x b_j. In a's frame b_j is the column j of the dots, so with (i, i1, i2) a
// cyclic order the axis is (a_i1 (-dots[i2][j]) + a_i2 dots[i1][j]), of length l = sqrt(dots[i1][j]^2
// + dots[i2][j]^2): its projections of the offset and of both boxes' half widths, times l, are
// sums of the dots already taken, and the separation is their difference over l. Only the axis that
// can be taken needs l: an edge axis replaces a face of overlap F only when its overlap is below
// `clearly` (0.95) times F, and since l <= 1 an axis whose separation times l is already at or
// below -0.95 F cannot (its root is not taken). Apart is decided for every axis, from the sign of
// the separation times l.
struct EdgeSearch {
    const BoxPair& pair;
    double half_a[3];
    double half_b[3];
    double least_separation_m;  ///< [m] -clearly F: an axis at or below it cannot be taken
    EdgeAxis best;

    // Axis (I, J), its indices known when compiled so that the dots are read from fixed places.
    // Returns true when it separates the boxes.
    template <std::uint32_t I, std::uint32_t J>
    bool apart_along() {
        constexpr std::uint32_t I1 = (I + 1) % 3, I2 = (I + 2) % 3, J1 = (J + 1) % 3, J2 = (J + 2) % 3;
        const double length2 = pair.dots[I1][J] * pair.dots[I1][J] + pair.dots[I2][J] * pair.dots[I2][J];
        if (length2 < 1e-12) return false;  // parallel edges (|a_i x b_j| < 1e-6): a face axis already tested
        // a's direction k . (a_i x b_j) = b_j . (a_k x a_i) = +/- a_m . b_j, m the third index, and
        // likewise for b: the dots already taken.
        const double reach_a_m = half_a[I1] * pair.abs_dots[I2][J] + half_a[I2] * pair.abs_dots[I1][J];
        const double reach_b_m = half_b[J1] * pair.abs_dots[I][J2] + half_b[J2] * pair.abs_dots[I][J1];
        const double centre_m = pair.offset_a_m[I2] * pair.dots[I1][J] - pair.offset_a_m[I1] * pair.dots[I2][J];
        const double separation_times_l = std::abs(centre_m) - reach_a_m - reach_b_m;
        if (separation_times_l > 0.0) return true;
        if (separation_times_l <= least_separation_m) return false;  // cannot be taken (l <= 1)
        const double separation_m = separation_times_l / std::sqrt(length2);
        if (separation_m > best.separation_m) best = {separation_m, Vec3{}, I, J};
        return false;
    }
};

// Whether, from a's faces and the dots alone, neither b's face axes nor the six crossed edge axes
// a_i x b_j (i != j) can separate the boxes or be taken (b's face needs an overlap below clearly
// times a's, an edge axis below clearly times the face's), so that b's faces are not measured and
// only the three edge axes a_i x b_i are. It holds where b's directions lie close to a's in the
// same order (a wall's bricks: the dots' diagonal within 1e-11 of 1) and the faces overlap by more
// than round-off; elsewhere everything is measured as before.
//
// Why. For a unit axis L with components L_k = a_k . L, b_j . L = sum_k dots[k][j] L_k, so
// |b_j . L| >= |dots[j][j]| |L_j| - sum_{k != j} |dots[k][j]| |L_k|, and b's half width along L,
// sum_j hb_j |b_j . L|, is at least sum_k |L_k| (hb_k |dots[k][k]| - e_k), e_k = sum_{j != k} hb_j
// |dots[k][j]|. With |centre . L| <= sum_k |centre_k| |L_k| and a's half width sum_k ha_k |L_k|,
// L's separation is at most sum_k |L_k| (s_k + 2 e_k), s_k a's face separation along k (its
// facing face's: |centre_k| - ha_k - b's reach). Every s_k is at most a's best, face_a_m = -F_a,
// and every e_k at most E = sum_j hb_j sum_{k != j} |dots[k][j]|, so when T = face_a_m + 2 E < 0 no
// axis separates by more than T (sum_k |L_k| >= 1). b's face axes are unit: each separates by at
// most T. The search compares an edge axis's separation times its length l, and a_i x b_j (i != j)
// has l >= |dots[j][j]| >= d, the diagonal's least |dot|: it separates by at most T l. So when
// (T + clearly F_a) d <= -2 slack, no b face is apart or overlaps below clearly F_a (b is not the
// reference, the face overlap is F_a) and no crossed edge axis is apart or above -clearly F_a l.
// The slack, 4e-12 of the boxes' summed half lengths (their centres' offset is below twice that
// where no face of a separates), covers the round-off of both sides' sums and the directions'
// distance from orthonormal (each about 1e-16 relative) a thousand times over; it sends a pair
// whose faces touch to round-off (F_a near 1e-16 m, where the axes' own round-off decides) to the
// full test, which chooses there as before.
//
// Where it holds, the three a_i x b_i are often parallel edges too, which apart_along skips
// (length2 = dots[i1][i]^2 + dots[i2][i]^2 < 1e-12): every off-diagonal |dots[k][j]| is at most
// E / hb_j (all of E's terms are >= 0), so when E < 5e-7 hb_min each is below 5e-7 (5.000001e-7
// with E's round-off) and each length2 below 5.1e-13, under 1e-12 by far: edges_parallel, and no edge
// axis is measured, as apart_along would measure none. A wall's bricks: off-diagonal dots 1e-21
// to 1e-11.
enum class Alignment : std::uint8_t {
    none,            ///< everything measured
    crossed_lose,    ///< b's faces and the crossed edge axes shown to lose: the three a_i x b_i measured
    edges_parallel,  ///< as crossed_lose, and the three a_i x b_i parallel edges: no edge axis measured
};

Alignment aligned_beyond_round_off(const BoxPair& pair, const Vec3& ha, const Vec3& hb, double face_a_m,
                                   double clearly) {
    const double slack_m = 4e-12 * (ha.x + ha.y + ha.z + hb.x + hb.y + hb.z);
    const double least_separation_m = clearly * face_a_m;  // -clearly F_a
    // T + clearly F_a <= (1 - clearly) face_a_m first: most pairs that fail, fail here (faces
    // touching to round-off).
    if (face_a_m - least_separation_m > -2.0 * slack_m) return Alignment::none;
    const auto& d = pair.abs_dots;
    const double crossed_m = hb.x * (d[1][0] + d[2][0]) + hb.y * (d[0][1] + d[2][1]) + hb.z * (d[0][2] + d[1][2]);  // E
    const double least_diagonal = std::min(std::min(d[0][0], d[1][1]), d[2][2]);
    if (!((face_a_m + 2.0 * crossed_m - least_separation_m) * least_diagonal <= -2.0 * slack_m)) return Alignment::none;
    return crossed_m < 5e-7 * std::min(std::min(hb.x, hb.y), hb.z) ? Alignment::edges_parallel
                                                                   : Alignment::crossed_lose;
}

EdgeAxis box_edge_axis(const PosedPolyhedron& a, const PosedPolyhedron& b, const BoxPair& pair, Alignment aligned,
                       double least_separation_m, bool& apart) {
    if (aligned == Alignment::edges_parallel) return EdgeAxis{};  // apart_along would measure none
    const Vec3 ha = a.box->half_lengths_m;
    const Vec3 hb = b.box->half_lengths_m;
    EdgeSearch search{pair, {ha.x, ha.y, ha.z}, {hb.x, hb.y, hb.z}, least_separation_m, EdgeAxis{}};
    // In the order (0,0), (0,1), ... (2,2), the first separating axis ending the search; only the
    // diagonal's three, in the same order, where the crossed ones are shown to lose (aligned_beyond_
    // round_off): the same choice, as an axis that neither separates nor can be taken never decides it.
    if (aligned == Alignment::crossed_lose)
        apart = search.apart_along<0, 0>() || search.apart_along<1, 1>() || search.apart_along<2, 2>();
    else
        apart = search.apart_along<0, 0>() || search.apart_along<0, 1>() || search.apart_along<0, 2>() ||
                search.apart_along<1, 0>() || search.apart_along<1, 1>() || search.apart_along<1, 2>() ||
                search.apart_along<2, 0>() || search.apart_along<2, 1>() || search.apart_along<2, 2>();
    EdgeAxis best = search.best;
    if (!apart && best.separation_m > -std::numeric_limits<double>::infinity()) {
        // The world axis, only for the one kept, turned towards b by the world offset. Not by the
        // sign of centre_m: that is the offset along a_i x b_j only when a's directions are
        // right-handed, which a box whose corners are listed in another order is not (its edge
        // directions run from the lower vertex number to the higher); |centre_m| is the same
        // either way. As the general test: b beyond a along +axis when centre >= 0.
        Vec3 axis = cross(a.directions[best.direction_a], b.directions[best.direction_b]);
        axis = (1.0 / length(axis)) * axis;
        best.axis = dot(axis, pair.offset_m) >= 0.0 ? axis : -axis;
    }
    return best;
}

// The edge of p along direction d whose middle reaches furthest along axis (sign +1) or least (-1).
std::uint32_t supporting_edge(const PosedPolyhedron& p, std::uint32_t direction, Vec3 axis, double sign) {
    std::uint32_t best = 0;
    double reach = -std::numeric_limits<double>::infinity();
    for (std::uint32_t e = 0; e < p.edges->edges.size(); ++e) {
        if (p.edges->edge_direction[e] != direction) continue;
        const auto [u, v] = p.edges->edges[e];
        const double s = sign * dot(axis, p.vertices_m[u] + p.vertices_m[v]);
        if (s > reach) { reach = s; best = e; }
    }
    return best;
}

// Edge on edge: one point midway between the closest points of the two supporting edges. Returns
// false when those closest points are not inside both edges (the axis is then not where the
// edges cross, and a face axis makes the points instead).
bool edge_contact(const PosedPolyhedron& a, const PosedPolyhedron& b, const EdgeAxis& e,
                  std::vector<ContactGeometry3d>& out) {
    const std::uint32_t ea = supporting_edge(a, e.direction_a, e.axis, 1.0);
    const std::uint32_t eb = supporting_edge(b, e.direction_b, e.axis, -1.0);
    const Vec3 p1 = a.vertices_m[a.edges->edges[ea][0]];
    const Vec3 d1 = a.vertices_m[a.edges->edges[ea][1]] - p1;
    const Vec3 p2 = b.vertices_m[b.edges->edges[eb][0]];
    const Vec3 d2 = b.vertices_m[b.edges->edges[eb][1]] - p2;
    const Vec3 r = p1 - p2;
    const double aa = dot(d1, d1), bb = dot(d1, d2), ee = dot(d2, d2), c = dot(d1, r), f = dot(d2, r);
    const double denominator = aa * ee - bb * bb;
    if (!(denominator > 1e-12 * aa * ee)) return false;
    const double s = (bb * f - c * ee) / denominator;
    const double t = (aa * f - bb * c) / denominator;
    constexpr double slack = 1e-9;
    if (s < -slack || s > 1.0 + slack || t < -slack || t > 1.0 + slack) return false;
    const Vec3 on_a = p1 + s * d1;
    const Vec3 on_b = p2 + t * d2;
    const double overlap_m = dot(e.axis, on_a - on_b);
    if (overlap_m > 0.0)
        out.push_back({0.5 * (on_a + on_b), e.axis, overlap_m, feature_3d(FeatureKind3d::edge, ea),
                       feature_3d(FeatureKind3d::edge, eb)});
    return true;
}


// The incident face: of inc's faces at its deepest vertex along the reference normal n (the least
// n . v, the first of equals), the one most opposed to n (the least n . normal, the first of equals
// in face order). Why not the most opposed of all faces: on a polyhedron that is not a box, the
// face whose normal lies nearest -n need not hold the deepest vertex. In the Gauss map a vertex
// is the spherical polygon of its faces' normals; -n lies in the deepest vertex's polygon, and
// where that polygon is long and thin another face's normal, across one of its sides, can lie
// nearer -n than any of its corners. That face's clip then misses the deepest point: two hulls of
// the random packing example overlapped by 1.6 cm with no contact point for hundreds of steps,
// until the choice flipped and the whole overlap sprang at once (docs/3d.md, "The incident face
// of a hull"). A box's or a prism's face most opposed to n always holds the deepest vertex (for
// a box the three faces at a vertex are the corners of its octant), so they keep their choice.
// Also gives the incident body's extent along n: its deepest vertex's n . v and its highest's.
struct IncidentExtent {
    double least_m = std::numeric_limits<double>::infinity();      ///< [m] the deepest vertex's n . v
    double greatest_m = -std::numeric_limits<double>::infinity();  ///< [m] the highest vertex's
};

std::uint32_t incident_face_at_deepest_vertex(const PosedPolyhedron& inc, Vec3 n, IncidentExtent& extent) {
    std::size_t deepest = 0;
    const std::size_t vertices = inc.shape->vertices_m.size();
    for (std::size_t i = 0; i < vertices; ++i) {
        const double s = dot(n, inc.vertices_m[i]);
        if (s < extent.least_m) {
            extent.least_m = s;
            deepest = i;
        }
        extent.greatest_m = std::max(extent.greatest_m, s);
    }
    std::uint32_t inc_face = 0;
    double most_opposed = std::numeric_limits<double>::infinity();
    for (std::uint32_t f = 0; f < inc.shape->faces.size(); ++f) {
        const auto& corners = inc.shape->faces[f];
        if (std::find(corners.begin(), corners.end(), deepest) == corners.end()) continue;
        const double c = dot(face_normal(inc, f), n);
        if (c < most_opposed) { most_opposed = c; inc_face = f; }
    }
    return inc_face;
}

// The same face for two boxes whose normals are their directions to the bit (BoxFrame3d::
// normals_are_directions), from the pair's dots: the normal of inc's face along +/- its direction
// j dotted with n is +/- the dot of the two directions, exactly (a product's rounding is symmetric
// in sign and order), so along each j the face against the sign of that dot gives -|dot|, and the
// least of the three, the lower face number on a tie, is the loop's choice.
std::uint32_t most_opposed_box_face(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                                    const BoxPair& pair, bool ref_is_a) {
    const int i = ref.box->face_direction[ref_face];
    const double ref_sign = ref.box->face_sign[ref_face];
    // Boxes turned alike (a wall's, the same shape) have inc's direction i along ref's: a |dot|
    // above sqrt(1/2) is the least -|dot| outright, since the three squares sum to 1 (to
    // round-off), so the others are below it and no tie can arise (the loop's choice, for the
    // test of one direction instead of three).
    const double c_i = ref_sign * pair.dots[i][i];  // n . inc's direction i, either way round
    if (std::abs(c_i) > 0.7072) return c_i > 0.0 ? inc.box->face_of[i][1] : inc.box->face_of[i][0];
    std::uint32_t inc_face = 0;
    double most_opposed = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 3; ++j) {
        const double c = ref_sign * (ref_is_a ? pair.dots[i][j] : pair.dots[j][i]);  // n . inc's direction j
        const std::uint32_t face = c > 0.0   ? inc.box->face_of[j][1]
                                   : c < 0.0 ? inc.box->face_of[j][0]
                                             : std::min(inc.box->face_of[j][0], inc.box->face_of[j][1]);
        const double opposed = -std::abs(c);
        if (opposed < most_opposed || (opposed == most_opposed && face < inc_face)) {
            most_opposed = opposed;
            inc_face = face;
        }
    }
    return inc_face;
}

// The contact points of a box face's rectangle clip, read in the face's frame: a corner's depth is
// -w, its point the world point halfway up, lifted only when it is below the plane; the shares
// are the turns of the polygon in that frame, which a rotation keeps to round-off (the polygon
// lies in the incident face, tilted or not, and its turns are measured in 3-D there as in the world).
// The shares are read from the clip's own corners (corner_shares_without_groups), not from a copy;
// only a polygon with a short side, which groups its corners, is copied for corner_shares_3d.
void box_face_points(const BoxFaceClip3d& clip, bool ref_is_a, bool incident_is_box,
                     std::vector<ContactGeometry3d>& out) {
    const std::size_t count = clip.count;
    const BoxClipCorner3d* polygon = clip.corners;
    struct ClipCorners {
        const BoxClipCorner3d* polygon;
        bool incident_is_box;
        Vec3 at(std::size_t i) const { return {polygon[i].u_m, polygon[i].v_m, polygon[i].w_m}; }
        bool known(std::size_t i) const {
            return incident_is_box && feature_kind(polygon[i].feature_incident) == FeatureKind3d::vertex;
        }
    };
    double shares[BoxFaceClip3d::most_corners];
    const ClipCorners corners{polygon, incident_is_box};
    // A box face cut by one side has 4 corners (cut across) or 5 (a corner cut off): loops of a
    // length known when compiled, unrolled.
    const bool ungrouped = count == 4   ? corner_shares_without_groups(corners, std::integral_constant<std::size_t, 4>{}, shares)
                           : count == 5 ? corner_shares_without_groups(corners, std::integral_constant<std::size_t, 5>{}, shares)
                                        : corner_shares_without_groups(corners, count, shares);
    if (!ungrouped) {
        Vec3 corners_m[BoxFaceClip3d::most_corners];
        for (std::size_t i = 0; i < count; ++i) corners_m[i] = {polygon[i].u_m, polygon[i].v_m, polygon[i].w_m};
        corner_shares_3d(corners_m, count, shares);
    }
    const Vec3 normal = ref_is_a ? clip.n : -clip.n;
    // The world point clip.world_m(u, v, w / 2) with x and y in the two lanes of a 16-byte vector
    // (laws/double_lanes.hpp: each lane rounds as the scalar expression written the same way, the
    // same sums in the same order, so the same bits), z alone. Why: the compiler formed the three
    // coordinates one by one, 18 operations a point where 12 do it.
    const DoubleLanes origin_xy = {clip.origin_m.x, clip.origin_m.y};
    const DoubleLanes e_u_xy = {clip.e_u.x, clip.e_u.y}, e_v_xy = {clip.e_v.x, clip.e_v.y}, n_xy = {clip.n.x, clip.n.y};
    for (std::size_t i = 0; i < count; ++i) {
        const BoxClipCorner3d& c = polygon[i];
        if (c.w_m >= 0.0) continue;  // depth -w <= 0
        const double half_w_m = 0.5 * c.w_m;
        const DoubleLanes xy = origin_xy + lanes(c.u_m) * e_u_xy + lanes(c.v_m) * e_v_xy + lanes(half_w_m) * n_xy;
        const double z = clip.origin_m.z + c.u_m * clip.e_u.z + c.v_m * clip.e_v.z + half_w_m * clip.n.z;
        // Made where it is stored (a point built aside was then copied), its features chosen
        // rather than swapped after. A plain struct built from parentheses is C++20's (P0960);
        // Clang before 16 lacks it (the fuzz and sanitizer builds), and takes the braced copy.
#if defined(__cpp_aggregate_paren_init)
        out.emplace_back(Vec3{xy[0], xy[1], z}, normal, -c.w_m, ref_is_a ? c.feature_reference : c.feature_incident,
                         ref_is_a ? c.feature_incident : c.feature_reference, shares[i]);
#else
        out.push_back({Vec3{xy[0], xy[1], z}, normal, -c.w_m, ref_is_a ? c.feature_reference : c.feature_incident,
                       ref_is_a ? c.feature_incident : c.feature_reference, shares[i]});
#endif
    }
}

// Face contact: the incident face clipped by the reference face's sides (in the reference face's
// frame when that face is a box's rectangle, geometry/box_face_clip_3d.hpp), each clipped corner
// below the reference plane a point; for a pair that is not two boxes, the edge axis's point where
// there is none (below).
void face_contact(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc, bool ref_is_a,
                  const BoxPair* pair, ContactScratch3d& scratch, std::vector<ContactGeometry3d>& out) {
    IncidentExtent extent;  // (along the reference normal; left unmeasured for two boxes)
    const std::uint32_t inc_face = pair != nullptr ? most_opposed_box_face(ref, ref_face, inc, *pair, ref_is_a)
                                                   : incident_face_at_deepest_vertex(inc, face_normal(ref, ref_face), extent);
    // Two boxes: the rectangle clip applies (a box face has 4 corners), no need to ask; its
    // polygon is read in the face's frame.
    if (pair != nullptr) {
        BoxFaceClip3d clip;
        if (clip_box_face_where_below(ref, ref_face, inc, inc_face, clip)) {
            box_face_points(clip, ref_is_a, true, out);
            return;
        }
        clip_by_face_sides(ref, ref_face, inc, inc_face, scratch);
    } else if (!box_face_clip_applies(ref, inc, inc_face) ||
               !clip_by_box_face(ref, ref_face, inc, inc_face, scratch.polygon)) {
        clip_by_face_sides(ref, ref_face, inc, inc_face, scratch);
    }
    // The reference normal only here: two boxes' clip in the face's frame (above) reads its own.
    const Vec3 n = face_normal(ref, ref_face);
    // The polygon's size and arrays read once (the writes below could alias the vectors' own).
    const std::size_t count = scratch.polygon.size();
    const ClipCorner3d* polygon = scratch.polygon.data();
    const auto& ref_corners = ref.shape->faces[ref_face];
    // The shares come from the whole clipped polygon, corners above the reference plane included,
    // so that a corner crossing the plane changes no other corner's share. A corner that is still
    // one of the incident face's own keeps that face's edges as its two sides, so on a box it turns
    // by exactly a quarter.
    // The scratch arrays only grow (their first count entries are used): a resize to each
    // polygon's size would construct or drop entries at every pair whose count differs.
    if (scratch.corners_m.size() < count) scratch.corners_m.resize(count);
    if (scratch.shares.size() < count) scratch.shares.resize(count);
    Vec3* corners_m = scratch.corners_m.data();
    const double* shares = scratch.shares.data();
    const bool incident_is_box = inc.box != nullptr && inc.box->is_box;
    if (incident_is_box) {
        if (scratch.quarter_turns.size() < count) scratch.quarter_turns.resize(count);
        std::uint8_t* quarter_turns = scratch.quarter_turns.data();
        for (std::size_t i = 0; i < count; ++i) {
            corners_m[i] = polygon[i].point_m;
            quarter_turns[i] = feature_kind(polygon[i].feature_incident) == FeatureKind3d::vertex;
        }
    } else {
        for (std::size_t i = 0; i < count; ++i) corners_m[i] = polygon[i].point_m;
    }
    corner_shares_3d(corners_m, count, scratch.shares.data(), incident_is_box ? scratch.quarter_turns.data() : nullptr);
    const double plane_m = dot(n, ref.vertices_m[ref_corners[0]]);
    const Vec3 normal = ref_is_a ? n : -n;
    std::size_t made = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const ClipCorner3d& c = polygon[i];
        const double depth_m = plane_m - dot(n, c.point_m);
        if (depth_m <= 0.0) continue;
        ++made;
        ContactGeometry3d g{c.point_m + (0.5 * depth_m) * n, normal, depth_m, c.feature_reference, c.feature_incident,
                            shares[i]};
        if (!ref_is_a) std::swap(g.feature_a, g.feature_b);
        out.push_back(g);
    }
    // A face kept over a shallower edge axis (the 0.95 preference) whose clip leaves no point
    // below its plane while the incident body's deepest vertex is below it by more than round-off
    // (1e-9 of the body's extent along the normal: faces that touch to round-off, drums stacked,
    // make no point, as before): that vertex lies past the reference face's sides,
    // and the overlap is the edges' (two hulls crossing edge on edge, deeply), which would
    // otherwise go unfelt (docs/3d.md, "The incident face of a hull"): the edge axis's point. It
    // is found again here, not handed from the test: any change to polyhedron_contact_3d's code
    // moved its registers, +19 instructions a pair on the box pairs' path. Where the edge axis
    // was taken and its point failed, the same call fails again (rare: its closest points fall
    // outside an edge). Two boxes keep their own rule: their face clips touching to round-off
    // give no point on purpose (geometry/box_face_clip_3d.hpp).
    const bool two_boxes = ref.box != nullptr && ref.box->is_box && inc.box != nullptr && inc.box->is_box;
    const double deepest_below_m = plane_m - extent.least_m;
    if (!two_boxes && made == 0 && deepest_below_m > 1e-9 * (extent.greatest_m - extent.least_m)) {
        const PosedPolyhedron& a = ref_is_a ? ref : inc;
        const PosedPolyhedron& b = ref_is_a ? inc : ref;
        bool apart = false;
        const EdgeAxis edge = best_edge_axis(a, b, apart);
        if (!apart && edge.separation_m > -std::numeric_limits<double>::infinity()) edge_contact(a, b, edge, out);
    }
}

}  // namespace

void clip_by_face_sides(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                        std::uint32_t inc_face, ContactScratch3d& scratch) {
    const Vec3 n = face_normal(ref, ref_face);
    auto& polygon = scratch.polygon;
    auto& clipped = scratch.clipped;
    polygon.clear();
    const auto& inc_corners = inc.shape->faces[inc_face];
    for (std::size_t k = 0; k < inc_corners.size(); ++k)
        polygon.push_back({inc.vertices_m[inc_corners[k]],
                           feature_3d(FeatureKind3d::vertex, static_cast<std::uint32_t>(inc_corners[k])),
                           feature_3d(FeatureKind3d::face, ref_face),
                           feature_3d(FeatureKind3d::edge, inc.edges->face_edges[inc_face][k]), false});
    const auto& ref_corners = ref.shape->faces[ref_face];
    const std::size_t m = ref_corners.size();
    for (std::size_t k = 0; k < m && !polygon.empty(); ++k) {
        const Vec3 p0 = ref.vertices_m[ref_corners[k]];
        const Vec3 p1 = ref.vertices_m[ref_corners[(k + 1) % m]];
        const Vec3 side = cross(p1 - p0, n);  // outward in the face's plane, |side| = the edge's length
        // A corner on the side plane to round-off (faces that coincide, as drums stacked) counts
        // as inside: 1e-9 of the edge, so that it is neither dropped nor doubled by a crossing.
        const double plane = dot(side, p0);
        const double slack = 1e-9 * dot(side, side);
        const std::uint32_t ref_edge = feature_3d(FeatureKind3d::edge, ref.edges->face_edges[ref_face][k]);
        clipped.clear();
        // Each corner's height over the side plane once (a corner is "here" once and "next" once).
        auto& heights = scratch.heights_m2;
        heights.resize(polygon.size());
        for (std::size_t i = 0; i < polygon.size(); ++i) heights[i] = dot(side, polygon[i].point_m) - plane;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const std::size_t i_next = i + 1 == polygon.size() ? 0 : i + 1;
            const ClipCorner3d& here = polygon[i];
            const ClipCorner3d& next = polygon[i_next];
            const double dh = heights[i];
            const double dn = heights[i_next];
            const bool here_in = dh <= slack;
            if (here_in) clipped.push_back(here);
            if (here_in == (dn <= slack)) continue;
            ClipCorner3d c;
            // On the plane itself: the slack decides in or out, not where the crossing is.
            c.point_m = here.point_m + std::clamp(dh / (dh - dn), 0.0, 1.0) * (next.point_m - here.point_m);
            if (!here.line_is_reference) {  // an incident edge crossing this reference edge
                c.feature_incident = here.line_after;
                c.feature_reference = ref_edge;
            } else {  // two reference sides meet: a corner of the reference face inside the incident face
                const std::size_t u = ref_corners[k];
                const std::size_t v = ref_corners[(k + 1) % m];
                const Vec3 to_u = c.point_m - p0;
                const Vec3 to_v = c.point_m - p1;
                const bool nearer_u = dot(to_u, to_u) <= dot(to_v, to_v);
                c.feature_reference = feature_3d(FeatureKind3d::vertex, static_cast<std::uint32_t>(nearer_u ? u : v));
                c.feature_incident = feature_3d(FeatureKind3d::face, inc_face);
            }
            c.line_after = here_in ? ref_edge : here.line_after;
            c.line_is_reference = here_in ? true : here.line_is_reference;
            clipped.push_back(c);
        }
        std::swap(polygon, clipped);
    }
}

std::size_t polyhedron_contact_3d(const PosedPolyhedron& a, const PosedPolyhedron& b, ContactScratch3d& scratch,
                                  std::vector<ContactGeometry3d>& out) {
    bool apart = false;
    const bool boxes = a.box != nullptr && a.box->is_box && b.box != nullptr && b.box->is_box;
    // The incident face from the dots when both boxes' normals are their directions to the bit
    // (read here, with is_box, while the frames are at hand).
    const bool exact_boxes = boxes && a.box->normals_are_directions && b.box->normals_are_directions;
    FirstRows first_rows;
    const BoxPair pair = boxes ? box_pair(a, b, first_rows) : BoxPair{};
    const FaceAxis face_a = boxes ? box_face_axis_of_a(a, b, pair, first_rows, apart) : best_face_axis(a, b, apart);
    if (apart) return 0;
    // Overlaps (>= 0); a candidate replaces the preferred one only when it is clearly smaller.
    constexpr double clearly = 0.95;
    // Two boxes turned alike, overlapping beyond round-off: b's faces shown to lose unmeasured.
    const Alignment alignment =
        boxes ? aligned_beyond_round_off(pair, a.box->half_lengths_m, b.box->half_lengths_m, face_a.separation_m,
                                         clearly)
              : Alignment::none;
    const bool aligned = alignment != Alignment::none;
    const FaceAxis face_b = aligned ? FaceAxis{}
                            : boxes ? box_face_axis_of_b(a, b, pair, apart)
                                    : best_face_axis(b, a, apart);
    if (apart) return 0;
    const std::size_t first = out.size();
    const bool use_b = !aligned && -face_b.separation_m < clearly * -face_a.separation_m;
    const double face_overlap_m = use_b ? -face_b.separation_m : -face_a.separation_m;
    const EdgeAxis edge = boxes ? box_edge_axis(a, b, pair, alignment, -clearly * face_overlap_m, apart)
                                : best_edge_axis(a, b, apart);
    if (apart) return 0;
    const bool use_edge = -edge.separation_m < clearly * face_overlap_m;
    if (!use_edge || !edge_contact(a, b, edge, out)) {
        const BoxPair* exact_pair = exact_boxes ? &pair : nullptr;
        if (use_b)
            face_contact(b, face_b.face, a, false, exact_pair, scratch, out);
        else
            face_contact(a, face_a.face, b, true, exact_pair, scratch, out);
    }
    // Sorted by key by insertion, stable (a box face gives at most 8 points, mostly in order
    // already), each key packed into one integer so that a comparison is one. Up to 16 points this
    // is the order std::sort gave (it sorts such ranges by the same insertion); beyond, equal keys
    // (one place found twice) keep their clip order, and which of them stands for both is a
    // choice among points at one place.
    // The key from the two features read one by one, as they were just stored: read as one 8-byte
    // word across the two 4-byte stores the point's making left, the load waited for both stores
    // to reach the cache (a store forwarding that fails; 13 % of this function on an Intel Xeon VM),
    // where the two loads, a shift and an or cost a few instructions.
    const auto key = [](const ContactGeometry3d& g) {
        return (static_cast<std::uint64_t>(g.feature_a) << 32) | g.feature_b;
    };
    // The insertion runs from the right: each point goes into the sorted run after it. The same
    // order as from the left (a stable sort's order is unique), with fewer moves on a wall: its
    // face clips mostly give the points one step round from key order (a corner of the incident
    // face first, then the crossings, then the other corners), which from the left moves every
    // point but the first (9 copies of a 72-byte point for 4 points) and from the right moves the
    // first point alone (5).
    // A key found twice (a reference corner found from both its sides, two corners at one place)
    // is seen by the sort itself: equal keys end as neighbours, a point placed left of its equal
    // (a point goes before the first key not below its own), and no key can come between them
    // afterwards; so comparing for equality with the right neighbour where a point is placed finds
    // every duplicate. Without one the points are final as sorted, and the merge pass is skipped.
    const auto begin = out.begin() + static_cast<std::ptrdiff_t>(first);
    const auto end = out.end();
    bool duplicate = false;
    if (end - begin > 1) {
        // The least key of the sorted run, its first point's.
        std::uint64_t least = key(*(end - 1));
        for (auto it = end - 1; it != begin;) {
            --it;
            const std::uint64_t k = key(*it);
            if (k <= least) {
                duplicate |= k == least;
                least = k;
                continue;
            }
            const ContactGeometry3d moved = *it;
            auto hole = it;
            do {
                *hole = *(hole + 1);
                ++hole;
            } while (hole + 1 != end && key(*(hole + 1)) < k);
            duplicate |= hole + 1 != end && key(*(hole + 1)) == k;
            *hole = moved;
            least = key(*it);
        }
    }
    // The first of equal keys stands for them, with all their shares. A point is moved only once a
    // duplicate went before it.
    if (duplicate) {
        auto kept = begin;
        for (auto it = begin + 1; it != out.end(); ++it) {
            if (it->feature_a == kept->feature_a && it->feature_b == kept->feature_b)
                kept->stiffness_share += it->stiffness_share;
            else if (++kept != it)
                *kept = *it;
        }
        out.erase(kept + 1, out.end());
    }
    return out.size() - first;
}

}  // namespace blockdem
