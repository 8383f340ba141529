// The rectangle clip (geometry/box_face_clip_3d.hpp) against the general face clip it stands in
// for (clip_by_face_sides, geometry/polyhedron_contact_3d.hpp): the same corners in the same order
// round the polygon, with the same features, over random poses of a box's face against a box's
// and a prism's, and on flush faces whose corners lie on the side planes.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "geometry/box_face_clip_3d.hpp"
#include "geometry/box_frame_3d.hpp"
#include "geometry/corner_share_3d.hpp"

namespace blockdem {
namespace {

// A shape about its centroid, turned by q and moved to c, as the world poses it.
struct Posed {
    Polyhedron shape;
    PolyhedronEdges edges;
    BoxFrame3d frame;
    std::vector<Vec3> vertices, normals, directions;
    Vec3 centre;
    Posed(const std::vector<Vec3>& body_vertices, Quaternion q, Vec3 c)
        : shape(convex_polyhedron(body_vertices)), edges(polyhedron_edges(shape)), frame(box_frame(shape, edges)),
          centre(c) {
        for (const Vec3& v : shape.vertices_m) vertices.push_back(c + rotate(q, v));
        for (const Vec3& n : shape.face_normals) normals.push_back(rotate(q, n));
        for (const Vec3& d : edges.directions) directions.push_back(rotate(q, d));
    }
    PosedPolyhedron view() const {
        return {&shape, &edges, vertices.data(), normals.data(), directions.data(), &centre, &frame};
    }
};

// The incident face the narrow phase takes for reference normal n: the most opposed.
std::uint32_t most_opposed_face(const Posed& p, Vec3 n) {
    std::uint32_t best = 0;
    for (std::uint32_t f = 1; f < p.normals.size(); ++f)
        if (dot(p.normals[f], n) < dot(p.normals[best], n)) best = f;
    return best;
}

struct Tally {
    int corners = 0;          // clipped corners compared
    int incident_edges = 0;   // an incident edge crossing a reference side
    int reference_corners = 0;// a reference corner inside the incident face
};

// Both clips of b's most opposed face by each face of the box a; every corner compared in order.
void expect_same_clips(const Posed& a, const Posed& b, double tolerance_m, Tally& tally) {
    const PosedPolyhedron ref = a.view();
    const PosedPolyhedron inc = b.view();
    for (std::uint32_t f = 0; f < a.shape.faces.size(); ++f) {
        const std::uint32_t inc_face = most_opposed_face(b, a.normals[f]);
        ASSERT_TRUE(box_face_clip_applies(ref, inc, inc_face));
        ContactScratch3d general;
        clip_by_face_sides(ref, f, inc, inc_face, general);
        std::vector<ClipCorner3d> rectangle;
        ASSERT_TRUE(clip_by_box_face(ref, f, inc, inc_face, rectangle));
        ASSERT_EQ(general.polygon.size(), rectangle.size()) << "face " << f;
        for (std::size_t k = 0; k < rectangle.size(); ++k) {
            const ClipCorner3d& g = general.polygon[k];
            const ClipCorner3d& r = rectangle[k];
            EXPECT_EQ(g.feature_incident, r.feature_incident);
            EXPECT_EQ(g.feature_reference, r.feature_reference);
            EXPECT_EQ(g.line_after, r.line_after);
            EXPECT_EQ(g.line_is_reference, r.line_is_reference);
            EXPECT_NEAR(length(g.point_m - r.point_m), 0.0, tolerance_m);
            ++tally.corners;
            if (feature_kind(r.feature_incident) == FeatureKind3d::edge) ++tally.incident_edges;
            if (feature_kind(r.feature_reference) == FeatureKind3d::vertex) ++tally.reference_corners;
        }
    }
}

TEST(BoxFaceClip3d, GivesTheGeneralClipsCornersInOrderOverRandomPoses) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    const std::vector<Vec3> slab = box_vertices({2.0, 1.0, 0.5}, {});
    const std::vector<Vec3> prism = prism_vertices({{0.1, 0.0}, {0.0, 0.08}, {-0.1, 0.02}, {-0.05, -0.07}, {0.06, -0.06}}, 0.1);
    Tally tally;
    for (int trial = 0; trial < 1000; ++trial) {
        const double turn = trial % 2 == 0 ? 0.02 : 0.6;
        const int kind = trial % 3;  // 0: brick on slab, 1: brick on brick, 2: prism on brick
        const Quaternion qa = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const Quaternion qb = from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const Posed a(kind == 0 ? slab : brick, qa, {0.0, 0.0, 0.0});
        const Posed b(kind == 2 ? prism : brick, qb,
                      {0.1 * u(random), 0.05 * u(random), (kind == 0 ? 0.3 : 0.1) + 0.01 * u(random)});
        // Round-off of the frame change (sums of products of lengths below 2 m, 1e-15 m), which a
        // crossing of an edge nearly parallel to a side plane magnifies by |h| / |h - h_next|: up to
        // 7e-14 m seen over the 6000 faces clipped here (most far from any contact), so 1e-12 m.
        expect_same_clips(a, b, 1e-12, tally);
    }
    // Every kind of corner is exercised, many times.
    EXPECT_GT(tally.corners, 10000);
    EXPECT_GT(tally.incident_edges, 2000);
    EXPECT_GT(tally.reference_corners, 1500);
}

// The polygon left in the reference face's frame, as the narrow phase reads it, against the
// general clip's world corners: each corner's depth -w against the world depth (plane - n . p),
// and the shares from the turns in the face's frame against the shares from the world corners.
TEST(BoxFaceClip3d, TheFacesFrameGivesTheWorldsDepthsAndShares) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    int corners = 0, cut_corners = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const double turn = trial % 2 == 0 ? 0.02 : 0.6;
        const Posed a(brick, from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)}), {});
        const Posed b(brick, from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)}),
                      {0.1 * u(random), 0.05 * u(random), 0.1 + 0.01 * u(random)});
        const PosedPolyhedron ref = a.view();
        const PosedPolyhedron inc = b.view();
        for (std::uint32_t f = 0; f < a.shape.faces.size(); ++f) {
            const std::uint32_t inc_face = most_opposed_face(b, a.normals[f]);
            ContactScratch3d general;
            clip_by_face_sides(ref, f, inc, inc_face, general);
            BoxFaceClip3d clip;
            ASSERT_TRUE(clip_box_face_in_frame(ref, f, inc, inc_face, clip));
            ASSERT_EQ(general.polygon.size(), clip.count);
            const std::size_t count = clip.count;
            std::vector<Vec3> world(count), in_frame(count);
            std::vector<double> world_shares(count), frame_shares(count);
            const double plane_m = dot(a.normals[f], a.vertices[a.shape.faces[f][0]]);
            for (std::size_t k = 0; k < count; ++k) {
                world[k] = general.polygon[k].point_m;
                in_frame[k] = {clip.corners[k].u_m, clip.corners[k].v_m, clip.corners[k].w_m};
                // Sums of products of lengths below 0.3 m: a few 1e-17 m of round-off each.
                EXPECT_NEAR(-clip.corners[k].w_m, plane_m - dot(a.normals[f], world[k]), 1e-14);
                EXPECT_NEAR(length(clip.world_m(in_frame[k].x, in_frame[k].y, in_frame[k].z) - world[k]), 0.0, 1e-12);
                if (feature_kind(clip.corners[k].feature_incident) != FeatureKind3d::vertex) ++cut_corners;
                ++corners;
            }
            corner_shares_3d(world.data(), count, world_shares.data());
            corner_shares_3d(in_frame.data(), count, frame_shares.data());
            // A turn is an arctangent of ratios of sides at least 1e-9 of the longest (shorter
            // ones group their corners), whose round-off of 1e-16 m it divides by them: 1e-10.
            for (std::size_t k = 0; k < count; ++k) EXPECT_NEAR(frame_shares[k], world_shares[k], 1e-10) << k;
        }
    }
    EXPECT_GT(corners, 5000);
    EXPECT_GT(cut_corners, 1000);
}

TEST(BoxFaceClip3d, FlushFacesKeepTheCornersOnTheSidePlanes) {
    // Bricks of one wythe in running bond: a brick on two below it, faces flush along y, its
    // corners exactly on the reference face's side planes (the slack decides, in both clips alike).
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    Tally tally;
    for (double shift_m : {0.0, 0.1, 0.05, -0.1, 1e-12, 0.2}) {
        const Posed a(brick, Quaternion{}, {0.0, 0.0, 0.0});
        const Posed b(brick, Quaternion{}, {shift_m, 0.0, 0.1 - 1e-6});
        expect_same_clips(a, b, 1e-15, tally);
    }
    EXPECT_GT(tally.corners, 24);
}

}  // namespace
}  // namespace blockdem

namespace blockdem {
namespace {

// The one-pass clip (clip_box_face_in_one_pass) against the passes it stands in for
// (clip_box_face_by_passes): where it answers, the same corners in the same order with the same
// keys and coordinates, to the bit (it makes them with the passes' own formula). So too the clip
// the narrow phase takes (clip_box_face_in_frame), which where the one pass declines keeps its cut
// by the first cutting side and goes on with the passes from the next side.
struct OnePassTally {
    int answered = 0;   // faces the one pass clipped
    int declined = 0;   // faces it left to the passes
    int cut = 0;        // answered with a cut (a new corner)
    int two_sides = 0;  // declined faces whose polygon holds a reference corner: two sides or more cut them
};

void expect_one_pass_as_passes(const Posed& a, const Posed& b, OnePassTally& tally) {
    const PosedPolyhedron ref = a.view();
    const PosedPolyhedron inc = b.view();
    for (std::uint32_t f = 0; f < a.shape.faces.size(); ++f) {
        const std::uint32_t inc_face = most_opposed_face(b, a.normals[f]);
        BoxFaceClip3d passes, one_pass, either;
        ASSERT_TRUE(clip_box_face_by_passes(ref, f, inc, inc_face, passes));
        ASSERT_TRUE(clip_box_face_in_frame(ref, f, inc, inc_face, either));
        const bool answered = clip_box_face_in_one_pass(ref, f, inc, inc_face, one_pass);
        // What the narrow phase takes is the passes' polygon whether or not the one pass answered.
        const BoxFaceClip3d* clips[2] = {&either, answered ? &one_pass : &either};
        if (answered) ++tally.answered; else ++tally.declined;
        for (const BoxFaceClip3d* clip : clips) {
            ASSERT_EQ(clip->count, passes.count) << "face " << f;
            std::vector<Vec3> mine(clip->count), theirs(clip->count);
            for (std::size_t k = 0; k < clip->count; ++k) {
                const BoxClipCorner3d& m = clip->corners[k];
                const BoxClipCorner3d& p = passes.corners[k];
                EXPECT_EQ(m.feature_incident, p.feature_incident) << "face " << f << " corner " << k;
                EXPECT_EQ(m.feature_reference, p.feature_reference) << "face " << f << " corner " << k;
                EXPECT_EQ(m.line_after, p.line_after);
                EXPECT_EQ(m.line_is_reference, p.line_is_reference);
                mine[k] = {m.u_m, m.v_m, m.w_m};
                theirs[k] = {p.u_m, p.v_m, p.w_m};
                EXPECT_EQ(m.u_m, p.u_m) << "face " << f << " corner " << k;
                EXPECT_EQ(m.v_m, p.v_m) << "face " << f << " corner " << k;
                EXPECT_EQ(m.w_m, p.w_m) << "face " << f << " corner " << k;
                if (clip == &one_pass && feature_kind(m.feature_incident) != FeatureKind3d::vertex) ++tally.cut;
            }
            std::vector<double> my_shares(clip->count), their_shares(clip->count);
            corner_shares_3d(mine.data(), mine.size(), my_shares.data());
            corner_shares_3d(theirs.data(), theirs.size(), their_shares.data());
            for (std::size_t k = 0; k < clip->count; ++k) EXPECT_EQ(my_shares[k], their_shares[k]) << k;
        }
        if (!answered) {
            bool reference_corner = false;
            for (std::size_t k = 0; k < passes.count; ++k)
                reference_corner |= feature_kind(passes.corners[k].feature_reference) == FeatureKind3d::vertex;
            if (reference_corner) ++tally.two_sides;
        }
    }
}

TEST(BoxFaceClip3d, OnePassGivesThePassesPolygonOverRandomPoses) {
    std::mt19937 random(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    const std::vector<Vec3> slab = box_vertices({2.0, 1.0, 0.5}, {});
    OnePassTally tally;
    for (int trial = 0; trial < 600; ++trial) {
        const double turn = trial % 3 == 0 ? 0.6 : trial % 3 == 1 ? 0.02 : 1e-7;
        const bool on_slab = trial % 4 == 0;
        const Posed a(on_slab ? slab : brick, from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)}), {});
        const Posed b(brick, from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)}),
                      {0.15 * u(random), 0.08 * u(random), (on_slab ? 0.3 : 0.1) + 0.01 * u(random)});
        expect_one_pass_as_passes(a, b, tally);
    }
    // Both ways are taken, many times, the one pass makes new corners, and the passes go on after
    // its cut where two sides cut.
    EXPECT_GT(tally.answered, 600);
    EXPECT_GT(tally.declined, 600);
    EXPECT_GT(tally.cut, 600);
    EXPECT_GT(tally.two_sides, 1200);  // 1690 of the 2657 declined
}

// The brick wall's exact cases: faces flush along one side (equal widths) with their corners on
// the side planes to round-off, half-brick and other offsets along the other, a turn of 1e-7 rad
// or none, the bricks placed far from the origin (coordinates of a long wall).
TEST(BoxFaceClip3d, OnePassGivesThePassesPolygonOnFlushFaces) {
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    OnePassTally tally;
    for (double far_m : {0.0, 7.3, 123.4})
        for (double turn_rad : {0.0, 1e-7, -3e-8})
            for (double shift_m : {0.0, 0.1, -0.1, 0.05, 0.2, 1e-12, -1e-17, 0.19999999999}) {
                const Quaternion q = from_rotation_vector({turn_rad, 0.5 * turn_rad, -turn_rad});
                const Vec3 base{far_m, 0.3 * far_m, 0.0};
                const Posed a(brick, Quaternion{}, base);
                const Posed b(brick, q, base + Vec3{shift_m, 0.0, 0.1 - 1e-6});
                const Posed side_by_side(brick, q, base + Vec3{0.2 - 1e-6, shift_m * 0.5, 0.0});
                expect_one_pass_as_passes(a, b, tally);
                expect_one_pass_as_passes(a, side_by_side, tally);
            }
    // Of the 864 faces, the one pass answers 228 (the faces in contact and the far ones that
    // a single side cuts), making 384 new corners; the others have two sides cutting them.
    EXPECT_GT(tally.answered, 200);
    EXPECT_GT(tally.cut, 300);
    EXPECT_GT(tally.two_sides, 400);  // 514 of the 636 declined
}

// One side cuts the face and a later side holds corners between half its slack and its slack
// (beyond what the one pass may decide without the cut corners' heights, inside what the passes
// count as on the side): the one pass declines, and the clip the narrow phase takes goes on from
// its cut with the passes, to the bit. The brick above is shifted by half its length along x (one
// side cuts a's top face) and by 0.75 of the slack (1e-9 of the 0.2 m side) along y, either way:
// where the y side holding two corners comes after the cutting side in the rectangle's order, the
// one pass declines; where it comes before, the passes skip it as the one pass does.
TEST(BoxFaceClip3d, OneCutAndALaterSideWithinItsSlackGoOnWithThePasses) {
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    OnePassTally tally;
    int one_cut_declined = 0;
    for (double far_m : {0.0, 7.3})
        for (double x_m : {0.1, -0.1})
            for (double y_m : {1.5e-10, -1.5e-10}) {
                const Vec3 base{far_m, 0.3 * far_m, 0.0};
                const Posed a(brick, Quaternion{}, base);
                const Posed b(brick, Quaternion{}, base + Vec3{x_m, y_m, 0.1 - 1e-6});
                expect_one_pass_as_passes(a, b, tally);  // every face, the continuation included
                // a's top face against b's bottom: one side cuts, two of b's corners stay.
                std::uint32_t top = 0;
                for (std::uint32_t f = 0; f < a.shape.faces.size(); ++f)
                    if (a.normals[f].z > 0.5) top = f;
                const std::uint32_t bottom = most_opposed_face(b, a.normals[top]);
                BoxFaceClip3d one_pass, passes;
                const bool answered = clip_box_face_in_one_pass(a.view(), top, b.view(), bottom, one_pass);
                ASSERT_TRUE(clip_box_face_by_passes(a.view(), top, b.view(), bottom, passes));
                ASSERT_EQ(passes.count, 4u);
                std::size_t kept_corners = 0;
                for (std::size_t k = 0; k < passes.count; ++k)
                    kept_corners += feature_kind(passes.corners[k].feature_incident) == FeatureKind3d::vertex;
                EXPECT_EQ(kept_corners, 2u);
                if (!answered) ++one_cut_declined;
            }
    // In the rectangle's side order, the holding side comes after the cutting one for one pose of
    // the four at each place (x +0.1, y +1.5e-10): 2 of the 8 declined, measured.
    EXPECT_GE(one_cut_declined, 2);
}

}  // namespace
}  // namespace blockdem

namespace blockdem {
namespace {

// The shares as the narrow phase takes them for two boxes (corner_shares_without_groups reading
// the clip's own corners, a kept incident corner known to be a right angle) against
// corner_shares_3d on a copy of the corners and flags: the same bits, and a polygon with a short
// side left to corner_shares_3d (the template says it cannot).
struct ClipCornersForShares {
    const BoxClipCorner3d* polygon;
    Vec3 at(std::size_t i) const { return {polygon[i].u_m, polygon[i].v_m, polygon[i].w_m}; }
    bool known(std::size_t i) const { return feature_kind(polygon[i].feature_incident) == FeatureKind3d::vertex; }
};

TEST(BoxFaceClip3d, SharesReadFromTheClipAreTheSharesOfACopy) {
    std::mt19937 random(31);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    int polygons = 0, known_corners = 0, measured_corners = 0, grouped = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const double turn = trial % 3 == 0 ? 0.6 : trial % 3 == 1 ? 0.02 : 1e-7;
        const bool sliver = trial % 4 == 0;
        const Quaternion qa =
            sliver ? Quaternion{} : from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const Posed a(brick, qa, {});
        // One trial in four overlaps a's top by a sliver 1e-12 m wide along x (b end to end with
        // a but for 1e-12 m): a polygon with sides shorter than 1e-9 of the longest, which groups.
        const Quaternion qb =
            sliver ? Quaternion{} : from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)});
        const Vec3 cb = sliver ? Vec3{0.2 - 1e-12, 1e-12, 0.1 - 1e-6} : Vec3{0.15 * u(random), 0.08 * u(random), 0.1 - 1e-6};
        const Posed b(brick, qb, cb);
        for (std::uint32_t f = 0; f < a.shape.faces.size(); ++f) {
            BoxFaceClip3d clip;
            ASSERT_TRUE(clip_box_face_in_frame(a.view(), f, b.view(), most_opposed_face(b, a.normals[f]), clip));
            std::vector<Vec3> corners(clip.count);
            std::vector<std::uint8_t> flags(clip.count);
            for (std::size_t k = 0; k < clip.count; ++k) {
                corners[k] = {clip.corners[k].u_m, clip.corners[k].v_m, clip.corners[k].w_m};
                flags[k] = feature_kind(clip.corners[k].feature_incident) == FeatureKind3d::vertex;
                if (flags[k] != 0) ++known_corners; else ++measured_corners;
            }
            std::vector<double> copied(clip.count), read(clip.count, -1.0);
            corner_shares_3d(corners.data(), clip.count, copied.data(), flags.data());
            ++polygons;
            if (!corner_shares_without_groups(ClipCornersForShares{clip.corners}, clip.count, read.data())) {
                ++grouped;
                continue;
            }
            for (std::size_t k = 0; k < clip.count; ++k) EXPECT_EQ(read[k], copied[k]) << "face " << f << " corner " << k;
        }
    }
    EXPECT_EQ(polygons, 2400);
    EXPECT_GT(known_corners, 1500);
    EXPECT_GT(measured_corners, 3000);
    EXPECT_GT(grouped, 50);  // the slivers have short sides
}

}  // namespace
}  // namespace blockdem

namespace blockdem {
namespace {

// clip_box_face_where_below, what the narrow phase takes for two boxes, against
// clip_box_face_in_frame: where some incident corner is below the reference plane, the same
// polygon to the bit (keys, order, coordinates); where it gives no corner, the full clip has no
// corner below the plane (no point was lost). Random poses, and the wall's faces that touch to
// round-off: heights of exactly 0 and of +/- a few 1e-17 m, where a crossing's rounding would
// matter if it could take a height below its ends'.
struct BelowTally {
    int skipped = 0;       // faces with no incident corner below: no polygon made
    int clipped = 0;       // faces clipped
    int skipped_cut = 0;   // skipped faces whose full clip has crossings (their heights interpolated)
};

void expect_where_below_as_in_frame(const Posed& a, const Posed& b, BelowTally& tally) {
    const PosedPolyhedron ref = a.view();
    const PosedPolyhedron inc = b.view();
    for (std::uint32_t f = 0; f < a.shape.faces.size(); ++f) {
        const std::uint32_t inc_face = most_opposed_face(b, a.normals[f]);
        BoxFaceClip3d full, below;
        ASSERT_TRUE(clip_box_face_in_frame(ref, f, inc, inc_face, full));
        ASSERT_TRUE(clip_box_face_where_below(ref, f, inc, inc_face, below));
        if (below.count == 0) {
            ++tally.skipped;
            bool cut = false;
            for (std::size_t k = 0; k < full.count; ++k) {
                EXPECT_GE(full.corners[k].w_m, 0.0) << "face " << f << " corner " << k;
                cut = cut || feature_kind(full.corners[k].feature_incident) != FeatureKind3d::vertex;
            }
            if (cut) ++tally.skipped_cut;
            continue;
        }
        ++tally.clipped;
        ASSERT_EQ(below.count, full.count) << "face " << f;
        for (std::size_t k = 0; k < full.count; ++k) {
            const BoxClipCorner3d& m = below.corners[k];
            const BoxClipCorner3d& p = full.corners[k];
            EXPECT_EQ(m.feature_incident, p.feature_incident);
            EXPECT_EQ(m.feature_reference, p.feature_reference);
            EXPECT_EQ(m.line_after, p.line_after);
            EXPECT_EQ(m.line_is_reference, p.line_is_reference);
            EXPECT_EQ(m.u_m, p.u_m);
            EXPECT_EQ(m.v_m, p.v_m);
            EXPECT_EQ(m.w_m, p.w_m);
        }
    }
}

TEST(BoxFaceClip3d, NoCornerBelowThePlaneMeansNoPolygonCornerBelow) {
    std::mt19937 random(41);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    BelowTally tally;
    for (int trial = 0; trial < 600; ++trial) {
        const double turn = trial % 3 == 0 ? 0.6 : trial % 3 == 1 ? 0.02 : 1e-7;
        const Posed a(brick, from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)}), {});
        const Posed b(brick, from_rotation_vector({turn * u(random), turn * u(random), turn * u(random)}),
                      {0.15 * u(random), 0.08 * u(random), 0.1 + 0.01 * u(random)});
        expect_where_below_as_in_frame(a, b, tally);
    }
    // The wall's touching faces: course on course and end to end at a gap of exactly 0 or of
    // +/- 1e-17 m, offsets of a half brick and others, unturned or turned by 1e-7 rad, near the
    // origin and far from it (where the coordinates' round-off is 1e-14 m).
    const std::vector<Vec3> unit_cube = box_vertices({1.0, 1.0, 1.0}, {});
    for (double far_m : {0.0, 7.3, 123.4})
        for (double turn_rad : {0.0, 1e-7, -3e-8})
            for (double gap_m : {0.0, 1e-17, -1e-17})
                for (double shift_m : {0.0, 0.1, -0.1, 0.05, 1e-12, 0.19999999999}) {
                    const Quaternion q = from_rotation_vector({turn_rad, 0.5 * turn_rad, -turn_rad});
                    const Vec3 base{far_m, 0.3 * far_m, 0.0};
                    const Posed a(brick, Quaternion{}, base);
                    expect_where_below_as_in_frame(a, Posed(brick, q, base + Vec3{shift_m, 0.0, 0.1 + gap_m}), tally);
                    expect_where_below_as_in_frame(a, Posed(brick, q, base + Vec3{0.2 + gap_m, 0.5 * shift_m, 0.0}), tally);
                    expect_where_below_as_in_frame(Posed(unit_cube, Quaternion{}, base),
                                                   Posed(brick, q, base + Vec3{shift_m, 0.0, 0.55 + gap_m}), tally);
                }
    // Both ways are taken many times, and skipped faces include cut polygons (crossings whose
    // heights are interpolated, the case the rule is about).
    EXPECT_GT(tally.skipped, 1000);
    EXPECT_GT(tally.clipped, 1000);
    EXPECT_GT(tally.skipped_cut, 100);
}

}  // namespace
}  // namespace blockdem

namespace blockdem {
namespace {

// The narrow phase's clip of two boxes (clip_box_face_where_below, its polygon in the
// reference face's frame) against the general clip (clip_by_face_sides, in the world) on boxes
// turned alike, as a wall's are: the same polygon (its corners, keys and order), each corner
// below the plane in both or in neither, positions within the round-off bound below, and the
// same shares within 1e-12, or within what a short side of the polygon makes of the positions'
// round-off. Why: it is the check a shorter path for such boxes must pass (docs/performance.md,
// "Branch face6": one from the boxes' frames was written, passed it and was measured slower).
struct AlikeTally {
    int clipped = 0;  // faces with a corner below the plane
    int skipped = 0;  // faces with none (no point)
    int cut = 0;      // clipped faces cut by a side (crossings made)
    int points = 0;   // corners below the plane compared
    int near_decision = 0;  // faces with a corner within round-off of a decision, not compared
};

struct FrameCorners {
    const BoxClipCorner3d* polygon;
    Vec3 at(std::size_t i) const { return {polygon[i].u_m, polygon[i].v_m, polygon[i].w_m}; }
    bool known(std::size_t i) const { return feature_kind(polygon[i].feature_incident) == FeatureKind3d::vertex; }
};

void expect_where_below_as_general(const Posed& a, const Posed& b, AlikeTally& tally) {
    for (bool ref_is_a : {true, false}) {
        const Posed& r = ref_is_a ? a : b;
        const Posed& i = ref_is_a ? b : a;
        const PosedPolyhedron ref = r.view();
        const PosedPolyhedron inc = i.view();
        // The face the narrow phase clips for these poses: the one facing the other box's centre.
        std::uint32_t f = 0;
        for (std::uint32_t g = 1; g < r.shape.faces.size(); ++g)
            if (dot(r.normals[g], i.centre - r.centre) > dot(r.normals[f], i.centre - r.centre)) f = g;
        {
            const std::uint32_t inc_face = most_opposed_face(i, r.normals[f]);
            BoxFaceClip3d frames;
            ASSERT_TRUE(clip_box_face_where_below(ref, f, inc, inc_face, frames));
            ContactScratch3d general;
            clip_by_face_sides(ref, f, inc, inc_face, general);
            const Vec3 n = r.normals[f];
            const double plane_m = dot(n, r.vertices[r.shape.faces[f][0]]);
            // A face with a corner within round-off of a decision (on the plane, or at a side's
            // slack) may be decided either way by either clip: none is asked of it here (a
            // short path must leave such faces to the vertices' clip, as the narrow phase has them).
            const double far_m = std::abs(r.centre.x) + std::abs(r.centre.y) + std::abs(r.centre.z);
            const double round_off_m = 1e-14 * (1.0 + far_m);
            bool near_decision = false;
            const auto& ref_corners = r.shape.faces[f];
            for (std::size_t c : i.shape.faces[inc_face]) {
                const Vec3 p = i.vertices[c];
                near_decision = near_decision || std::abs(plane_m - dot(n, p)) <= round_off_m;
                for (std::size_t k = 0; k < ref_corners.size(); ++k) {
                    const Vec3 p0 = r.vertices[ref_corners[k]];
                    const Vec3 edge = r.vertices[ref_corners[(k + 1) % ref_corners.size()]] - p0;
                    const double height_m = dot(normalized(cross(edge, n)), p - p0);
                    near_decision = near_decision || std::abs(height_m - 1e-9 * length(edge)) <= 4.0 * round_off_m;
                }
            }
            // Round-off bound: the coordinates' roundings at the positions' size (1e-14 m at
            // 123 m) times a small factor; an incident edge's crossing of a side is magnified by
            // the crossing's conditioning, 1 / |sin| of the angle between the edge and the side
            // plane (about 1 where boxes turned alike are cut across, up to 1e7 where an edge
            // turned by 1e-7 rad runs along a side plane and crosses it).
            const auto conditioning = [&](const ClipCorner3d& g) {
                if (feature_kind(g.feature_incident) != FeatureKind3d::edge) return 1.0;
                const Vec3 along = i.directions[i.edges.edge_direction[feature_index(g.feature_incident)]];
                const Vec3 side = normalized(cross(r.directions[r.edges.edge_direction[feature_index(g.feature_reference)]], n));
                return 1.0 + 1.0 / std::max(std::abs(dot(along, side)), 1e-12);
            };
            double tolerance_m = round_off_m;
            for (const ClipCorner3d& g : general.polygon) tolerance_m = std::max(tolerance_m, round_off_m * conditioning(g));
            // A crossing within its round-off of the plane is such a decision too, and so is one
            // of an edge within 1e-6 rad of the side plane it crosses: where it lands along the
            // edge, and whether the clip keeps the sliver it cuts, is round-off.
            for (const ClipCorner3d& g : general.polygon)
                near_decision = near_decision || conditioning(g) > 1e6 ||
                                std::abs(plane_m - dot(n, g.point_m)) <= 4.0 * round_off_m * conditioning(g);
            if (near_decision) {
                ++tally.near_decision;
                return;
            }
            bool general_below = false;
            for (const ClipCorner3d& c : general.polygon) general_below = general_below || plane_m - dot(n, c.point_m) > 0.0;
            if (frames.count == 0) {  // no corner below: the general clip makes no point either
                EXPECT_FALSE(general_below) << "face " << f;
                ++tally.skipped;
                return;
            }
            ++tally.clipped;
            ASSERT_EQ(frames.count, general.polygon.size()) << "face " << f;
            bool any_cut = false;
            std::vector<Vec3> world(frames.count);
            std::vector<std::uint8_t> quarter(frames.count);
            for (std::size_t k = 0; k < frames.count; ++k) {
                const BoxClipCorner3d& c = frames.corners[k];
                const ClipCorner3d& g = general.polygon[k];
                EXPECT_EQ(c.feature_incident, g.feature_incident);
                EXPECT_EQ(c.feature_reference, g.feature_reference);
                EXPECT_EQ(c.line_after, g.line_after);
                EXPECT_EQ(c.line_is_reference, g.line_is_reference);
                world[k] = frames.world_m(c.u_m, c.v_m, c.w_m);
                EXPECT_NEAR(length(world[k] - g.point_m), 0.0, tolerance_m) << "face " << f << " corner " << k;
                EXPECT_EQ(c.w_m < 0.0, plane_m - dot(n, g.point_m) > 0.0) << "face " << f << " corner " << k;
                if (c.w_m < 0.0) ++tally.points;
                quarter[k] = feature_kind(g.feature_incident) == FeatureKind3d::vertex;
                any_cut = any_cut || !quarter[k];
            }
            if (any_cut) ++tally.cut;
            // The shares as the narrow phase takes each polygon.
            std::vector<double> general_shares(frames.count), frame_shares(frames.count);
            std::vector<Vec3> general_corners(frames.count);
            for (std::size_t k = 0; k < frames.count; ++k) general_corners[k] = general.polygon[k].point_m;
            corner_shares_3d(general_corners.data(), frames.count, general_shares.data(), quarter.data());
            // As box_face_points takes them: without groups, or on a copy where a side is short.
            if (!corner_shares_without_groups(FrameCorners{frames.corners}, frames.count, frame_shares.data())) {
                std::vector<Vec3> in_frame(frames.count);
                for (std::size_t k = 0; k < frames.count; ++k) in_frame[k] = FrameCorners{frames.corners}.at(k);
                corner_shares_3d(in_frame.data(), frames.count, frame_shares.data());
            }
            // A turn is an arctangent of ratios of sides, whose round-off (tolerance_m) it divides
            // by their length: 1e-12, or that where the polygon has a side shorter than a few cm.
            double shortest_m = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < frames.count; ++k)
                shortest_m = std::min(shortest_m, length(general_corners[(k + 1) % frames.count] - general_corners[k]));
            const double share_tolerance = std::max(1e-12, 4.0 * tolerance_m / shortest_m);
            for (std::size_t k = 0; k < frames.count; ++k)
                EXPECT_NEAR(frame_shares[k], general_shares[k], share_tolerance) << "face " << f << " corner " << k;
        }
    }
}

TEST(BoxFaceClip3d, BoxesTurnedAlikeGiveTheGeneralClipOverRandomPoses) {
    std::mt19937 random(53);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    const std::vector<Vec3> slab = box_vertices({2.0, 1.0, 0.5}, {});
    AlikeTally tally;
    for (int trial = 0; trial < 600; ++trial) {
        // Both turned by one random turn, b by a tiny one more (0 to 1e-7 rad), b pressed into a's
        // top or its end by up to 1e-4 m and shifted along the face by up to a brick.
        const Quaternion q = from_rotation_vector({3.0 * u(random), 3.0 * u(random), 3.0 * u(random)});
        const double tiny = 1e-7 * unit(random);
        const Quaternion turn = from_rotation_vector({tiny * u(random), tiny * u(random), tiny * u(random)});
        const bool on_slab = trial % 4 == 0;
        const bool on_top = trial % 2 == 0;
        const Vec3 far{trial % 3 == 0 ? 123.4 : 0.0, trial % 3 == 1 ? -7.3 : 0.0, 0.0};
        const double press_m = 1e-4 * unit(random);
        const Vec3 offset = on_top ? Vec3{0.2 * u(random), 0.1 * u(random), (on_slab ? 0.3 : 0.1) - press_m}
                                   : Vec3{(on_slab ? 1.1 : 0.2) - press_m, 0.1 * u(random), 0.1 * u(random)};
        const Posed a(on_slab ? slab : brick, q, far);
        const Posed b(brick, turn * q, far + rotate(q, offset));
        expect_where_below_as_general(a, b, tally);
    }
    // Every pair is clipped (1200 faces, 1050 of them cut, 4800 points); none is near a decision.
    EXPECT_GT(tally.clipped, 1000);
    EXPECT_GT(tally.cut, 900);
    EXPECT_GT(tally.points, 4000);
}

TEST(BoxFaceClip3d, BoxesTurnedAlikeGiveTheGeneralClipOnTheWallsExactCases) {
    // Flush faces of equal width (corners on side planes to round-off), half-brick and other
    // offsets (a corner 1e-11 m inside a side), gaps of 0 and +/- 1e-17 m and pressed ones,
    // unturned and turned by 1e-7 rad, near the origin and 123 m from it.
    const std::vector<Vec3> brick = box_vertices({0.2, 0.1, 0.1}, {});
    AlikeTally tally;
    for (double far_m : {0.0, 7.3, 123.4})
        for (double turn_rad : {0.0, 1e-7, -3e-8})
            for (double gap_m : {0.0, 1e-17, -1e-17, -1e-6})
                for (double shift_m : {0.0, 0.1, -0.1, 0.05, 1e-12, 0.19999999999}) {
                    const Quaternion q = from_rotation_vector({turn_rad, 0.5 * turn_rad, -turn_rad});
                    const Vec3 base{far_m, 0.3 * far_m, 0.0};
                    const Posed a(brick, Quaternion{}, base);
                    expect_where_below_as_general(a, Posed(brick, q, base + Vec3{shift_m, 0.0, 0.1 + gap_m}), tally);
                    expect_where_below_as_general(a, Posed(brick, q, base + Vec3{0.2 + gap_m, 0.5 * shift_m, 0.0}), tally);
                }
    // 220 faces clipped (196 cut, 712 points), 13 with no corner below, 325 near a decision (the
    // gaps of 0 and 1e-17 m, the edges along a side plane).
    EXPECT_GT(tally.clipped, 200);
    EXPECT_GT(tally.cut, 150);
    EXPECT_GT(tally.skipped, 5);
    EXPECT_GT(tally.near_decision, 200);
}

}  // namespace
}  // namespace blockdem
