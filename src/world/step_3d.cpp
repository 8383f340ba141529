#include "world/step_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "dynamics/rigid_rotation_3d.hpp"
#include "geometry/packed_vec3.hpp"
#include "laws/contact_law_3d.hpp"
#include "laws/double_lanes.hpp"
#include "laws/linear_spring_dashpot.hpp"
#include "world/parallel.hpp"
#include "world/vex_clones.hpp"

namespace blockdem {
namespace {

using namespace law_3d;  // the law at a pair's points (laws/contact_law_3d.hpp)

int thread_index() {
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

int thread_count() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

// How many slots the step's per-thread scratch needs, asked before its own regions: one for each of
// their threads, and one for the caller's thread number, which the step's serial parts use (a step
// run inside a caller's parallel region, e.g. one world per thread of an outer loop, has its
// thread number there, which can exceed the threads its own regions would have).
std::size_t thread_slots() {
    return static_cast<std::size_t>(std::max(thread_count(), thread_index() + 1));
}

// Step 1: a driven body rides the table; a fixed one stays. Called per body in the pose's
// parallel loop (a serial loop over all bodies was a piece of the step's serial part).
void place_driven_body(World3d& w, std::size_t i, Vec3 displacement_m, Vec3 velocity_m_s) {
    if (w.kinds[i] != BodyKind3d::driven) return;
    RigidBody3d& b = w.bodies[i];
    b.position_m = w.rest_positions_m[i] + displacement_m;
    b.velocity_m_s = velocity_m_s;
    b.velocity_at_t_m_s = velocity_m_s;
}

// Whether the pose stores a body's turned face normals: not for a box whose normals are its
// directions to the bit, whose normals the narrow phase reads from its directions
// (geometry/polyhedron_contact_3d.hpp, face_normal): 144 B a box a step not written.
bool stores_normals(const BoxFrame3d& frame) { return !(frame.is_box && frame.normals_are_directions); }

// What the narrow phase's views are made from now (world/world_3d.hpp, PosedSources3d).
PosedSources3d posed_sources(const World3d& w) {
    const WorldScratch3d& s = w.scratch;
    return {w.bodies.data(),         w.edges.data(),      w.box_frames.data(),
            s.world_vertices_m.data(), s.world_normals.data(), s.world_directions.data(), s.centroids_m.data(),
            w.bodies.size()};
}

// Each body's view for the narrow phase: pointers to its shape, edges, frame and centroid and to its
// runs in the pose arrays. None of them moves while those arrays keep their buffers, so the views
// are written here, when one of the buffers is another, and not by every step's pose (72 B a body
// a step, in a loop bound by its stores).
void point_posed_views(World3d& w) {
    WorldScratch3d& s = w.scratch;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const RigidBody3d& b = w.bodies[i];
        s.posed[i] = {&b.shape,
                      &w.edges[i],
                      s.world_vertices_m.data() + s.vertex_start[i],
                      stores_normals(w.box_frames[i]) ? s.world_normals.data() + s.face_start[i] : nullptr,
                      s.world_directions.data() + s.direction_start[i],
                      &s.centroids_m[i],
                      &w.box_frames[i]};
    }
    s.posed_sources = posed_sources(w);
}

// The offsets of each body's entries in the flat pose arrays, when the bodies changed, and the
// narrow phase's views when what they point into did (a body added, a world copied).
void size_pose_arrays(World3d& w) {
    WorldScratch3d& s = w.scratch;
    const std::size_t n = w.bodies.size();
    if (s.vertex_start.size() != n + 1) {
        s.vertex_start.assign(n + 1, 0);
        s.face_start.assign(n + 1, 0);
        s.direction_start.assign(n + 1, 0);
        for (std::size_t i = 0; i < n; ++i) {
            s.vertex_start[i + 1] = s.vertex_start[i] + static_cast<std::uint32_t>(w.bodies[i].shape.vertices_m.size());
            const std::size_t normals = stores_normals(w.box_frames[i]) ? w.bodies[i].shape.face_normals.size() : 0;
            s.face_start[i + 1] = s.face_start[i] + static_cast<std::uint32_t>(normals);
            s.direction_start[i + 1] = s.direction_start[i] + static_cast<std::uint32_t>(w.edges[i].directions.size());
        }
        s.world_vertices_m.resize(s.vertex_start[n]);
        s.world_normals.resize(s.face_start[n]);
        s.world_directions.resize(s.direction_start[n]);
        s.body_directions.resize(s.direction_start[n]);
        for (std::size_t i = 0; i < n; ++i)
            std::copy(w.edges[i].directions.begin(), w.edges[i].directions.end(), &s.body_directions[s.direction_start[i]]);
        s.angular_velocity_world_rad_s.resize(n);
        s.centroids_m.resize(n);
        s.rotations.resize(n);
        s.boxes.resize(n);
        s.is_static.resize(n);
        s.posed.resize(n);
    }
    if (!(s.posed_sources == posed_sources(w))) point_posed_views(w);
}

// The 8 corners centre +/- a +/- b +/- c, corner k on the + side of a when bit 0 of k is set, of
// b for bit 1, of c for bit 2 (BoxFrame3d::vertex_corner's numbering). Inlined at both calls:
// called, its arguments went through memory (116 instructions a box where 66 do the work).
[[gnu::always_inline]] inline void box_corners(const PackedVec3& centre_m, const PackedVec3& a, const PackedVec3& b,
                                               const PackedVec3& c, Vec3* corners) {
    const PackedVec3 along_c[2] = {centre_m - c, centre_m + c};
    const PackedVec3 along_bc[4] = {along_c[0] - b, along_c[0] + b, along_c[1] - b, along_c[1] + b};
    for (std::size_t k = 0; k < 4; ++k) {
        store(along_bc[k] - a, &corners[2 * k]);
        store(along_bc[k] + a, &corners[2 * k + 1]);
    }
}

// A box posed from its orientation's matrix: its 3 world edge directions d_i, its 8 corners
// centre +/- h_0 d_0 +/- h_1 d_1 +/- h_2 d_2 in its vertex order, its 6 face normals where it
// stores them, and its bounding box centre +/- sum h_i |d_i|. Why: 9 products and 42 sums for the corners where
// turning each vertex costs 15 operations (120 a box), and 15 for the bounding box where the
// corners' minima and maxima cost 42. The corners are the box the narrow phase tests
// (geometry/box_frame_3d.hpp: its separating axes use h_i and d_i), and they differ from the
// turned vertices only by round-off and by the 1e-12 of the box's size that box_frame allows a
// vertex off its corner. What the frame says is read into locals before it is needed after a
// store: a store through the output pointers could alias the frame, which would then be read again.
// Inlined into pose_body and so into pose_run's copies: called from the AVX copy, it would be the
// baseline one (world/vex_clones.hpp).
[[gnu::always_inline]] inline Aabb3d pose_box(const Matrix3d& rotation, Vec3 centre_m, const BoxFrame3d& frame,
                                              const Vec3* body_directions, const Polyhedron& shape, Vec3* directions,
                                              Vec3* vertices_m, Vec3* normals) {
    const PackedRotation turn = packed(rotation);
    const PackedVec3 d[3] = {turn * body_directions[0], turn * body_directions[1], turn * body_directions[2]};
    const Vec3 h = frame.half_lengths_m;
    const std::array<std::uint8_t, 8> corner_of = frame.vertex_corner;
    // A box whose normals are its directions to the bit (BoxFrame3d::normals_are_directions) has
    // none stored: the narrow phase reads them from its directions (stores_normals).
    if (!frame.normals_are_directions)
        for (std::size_t k = 0; k < 6; ++k) normals[k] = rotation * shape.face_normals[k];
    for (std::size_t k = 0; k < 3; ++k) store(d[k], &directions[k]);
    const PackedVec3 a = h.x * d[0];
    const PackedVec3 b = h.y * d[1];
    const PackedVec3 c = h.z * d[2];
    const PackedVec3 centre = packed(centre_m);
    // A box listed in corner order (as geometry/polyhedron.hpp's box_vertices lists it) takes its
    // corners where they are made; another order goes through a copy (65 instructions a box).
    constexpr std::array<std::uint8_t, 8> corner_order{0, 1, 2, 3, 4, 5, 6, 7};
    if (corner_of == corner_order) {
        box_corners(centre, a, b, c, vertices_m);
    } else {
        Vec3 corners[8];
        box_corners(centre, a, b, c, corners);
        for (std::size_t k = 0; k < 8; ++k) vertices_m[k] = corners[corner_of[k]];
    }
    const PackedVec3 reach = absolute(a) + absolute(b) + absolute(c);
    Aabb3d box;
    store(centre - reach, &box.lo);
    store(centre + reach, &box.hi);
    return box;
}

// Any other polyhedron's vertices, normals and edge directions turned by the matrix, and its
// bounding box.
Aabb3d pose_polyhedron(const Matrix3d& rotation, Vec3 centre_m, const Polyhedron& shape, const PolyhedronEdges& edges,
                       Vec3* directions, Vec3* vertices_m, Vec3* normals) {
    for (std::size_t k = 0; k < edges.directions.size(); ++k) directions[k] = rotation * edges.directions[k];
    for (std::size_t k = 0; k < shape.face_normals.size(); ++k) normals[k] = rotation * shape.face_normals[k];
    Aabb3d box{centre_m, centre_m};
    for (std::size_t k = 0; k < shape.vertices_m.size(); ++k) {
        const Vec3 v = centre_m + rotation * shape.vertices_m[k];
        vertices_m[k] = v;
        box.lo = {std::min(box.lo.x, v.x), std::min(box.lo.y, v.y), std::min(box.lo.z, v.z)};
        box.hi = {std::max(box.hi.x, v.x), std::max(box.hi.y, v.y), std::max(box.hi.z, v.z)};
    }
    return box;
}

// Step 2: each body's vertices, normals (where it stores them) and edge directions in the world
// frame and its box, where the narrow phase's view of it points (WorldScratch3d::posed), from its
// orientation's matrix (one a body, kept for the kick and the drift). What is read from the body
// is read before the first store, for pose_box's reason. Inlined into pose_run, for pose_box's
// other reason.
[[gnu::always_inline]] inline void pose_body(World3d& w, std::size_t i) {
    WorldScratch3d& s = w.scratch;
    const RigidBody3d& b = w.bodies[i];
    const Matrix3d rotation = rotation_matrix_by_products(b.orientation);
    const Vec3 centre_m = b.position_m;
    // The drift turned the body about this axis, so its world direction is the same at both ends.
    const Vec3 omega_world_rad_s = rotation * b.angular_velocity_body_rad_s;
    const bool is_static = w.kinds[i] != BodyKind3d::dynamic || is_taken_out(w.domain, i);
    const BoxFrame3d& frame = w.box_frames[i];
    const PolyhedronEdges& edges = w.edges[i];
    Vec3* directions = &s.world_directions[s.direction_start[i]];
    Vec3* vertices = &s.world_vertices_m[s.vertex_start[i]];
    Vec3* normals = s.world_normals.data() + s.face_start[i];  // (none for a box that stores none: data() may be null)
    s.boxes[i] = frame.is_box ? pose_box(rotation, centre_m, frame, &s.body_directions[s.direction_start[i]], b.shape,
                                         directions, vertices, normals)
                              : pose_polyhedron(rotation, centre_m, b.shape, edges, directions, vertices, normals);
    s.rotations[i] = rotation;
    s.centroids_m[i] = centre_m;
    s.angular_velocity_world_rad_s[i] = omega_world_rad_s;
    s.is_static[i] = is_static;
}

// Steps 1 and 2 for bodies begin .. end - 1, and their forces set to gravity for step 5
// (world/vex_clones.hpp: compiled for AVX where there is AVX).
BLOCKDEM_VEX_CLONES void pose_run(World3d& w, std::ptrdiff_t begin, std::ptrdiff_t end, Vec3 displacement_m,
                                  Vec3 velocity_m_s) {
    for (std::ptrdiff_t i = begin; i < end; ++i) {
        place_driven_body(w, static_cast<std::size_t>(i), displacement_m, velocity_m_s);
        pose_body(w, static_cast<std::size_t>(i));
        w.bodies[i].force_n = {0.0, 0.0, -w.gravity_m_s2 * w.bodies[i].mass_kg};
        w.bodies[i].torque_n_m = {};
    }
}

// A large scene's candidate pairs are cut into chunks for the narrow phase and the table's layout:
// at least min_layout_chunks (for the threads to share), and one for every candidates_per_chunk
// (WorldScratch3d, 512) beyond, so that a chunk's run of the table stays in the core's cache from
// its fill to its law (300 candidates, 1230 points, 216 kB a chunk of the 1e4-brick wall; at 1e5
// bricks, 64 chunks were 2.2 MB each, and the law read its points back from memory). The count
// depends on the candidates' number alone, never the thread count (world/parallel.hpp, rule 3); a
// small scene's candidates are one chunk, run serially.
constexpr std::size_t min_layout_chunks = 64;

std::size_t candidate_chunk_count(const WorldScratch3d& s, std::size_t candidates) {
    if (static_cast<std::ptrdiff_t>(candidates) < parallel_threshold) return 1;
    const std::size_t per_chunk = std::max<std::size_t>(s.candidates_per_chunk, 1);
    return std::max(min_layout_chunks, (candidates + per_chunk - 1) / per_chunk);
}

// Calls work(k) for each chunk k < chunks, on all threads when there are several, and then tail()
// on each thread as soon as no chunk is left for it to take (no barrier between the two). No
// parallel region for none or one chunk: waking the threads costs more than a small scene's step.
template <class Work, class Tail>
void for_fixed_chunks_then(std::size_t chunks, Work work, Tail tail) {
    if (chunks <= 1) {
        if (chunks == 1) work(0);
        tail();
        return;
    }
    const auto count = static_cast<std::ptrdiff_t>(chunks);
#pragma omp parallel
    {
#pragma omp for schedule(dynamic) nowait
        for (std::ptrdiff_t k = 0; k < count; ++k) work(static_cast<std::size_t>(k));
        tail();
    }
}

// Calls work(k) for each chunk k < chunks, on all threads when there are several.
template <class Work>
void for_fixed_chunks(std::size_t chunks, Work work) {
    for_fixed_chunks_then(chunks, work, [] {});
}

// Brings the line at p into the core's cache, owned by it for writing: PREFETCHW on x86 (a no-op on
// an x86 without it), in inline assembly since GCC emits it from __builtin_prefetch only with
// -mprfchw, which the build does not assume; elsewhere the compiler's write prefetch.
#if defined(__x86_64__) || defined(__i386__)
[[gnu::always_inline]] inline void prefetch_to_write(const char* p) { asm volatile("prefetchw %0" : : "m"(*p)); }
#else
[[gnu::always_inline]] inline void prefetch_to_write(const char* p) { __builtin_prefetch(p, 1, 1); }
#endif

// Where the fill of a chunk will write and read the table, as last step's layout of that chunk
// says (a guess: this step's layout differs by the points gained or lost before it), fetched a few
// lines at each candidate of the chunk's narrow phase, whose arithmetic hides the loads. Why: the
// fill writes this step's runs into lines last touched two steps before, and it waited on them: a
// fifth to a quarter of the one-thread step on the 1e4 wall (an Intel Xeon VM; its time grew with
// the point's bytes), a tenth with the lines fetched ahead. A wrong guess costs only the loads; a
// prefetch changes no value.
struct TableWarmup {
    const char* write_lines = nullptr;  ///< this step's table at the chunk's guessed place
    const char* read_lines = nullptr;   ///< last step's table at the chunk's place then
    std::size_t bytes = 0;              ///< the guessed run's bytes in each
    /// Candidate i of the chunk's n: its share of the lines.
    void touch(std::size_t i, std::size_t n) const {
        constexpr std::size_t line_bytes = 64;
        const std::size_t to = bytes * (i + 1) / n;
        for (std::size_t b = bytes * i / n / line_bytes * line_bytes; b < to; b += line_bytes) {
            prefetch_to_write(write_lines + b);
            __builtin_prefetch(read_lines + b, 0, 1);
        }
    }
};

// Step 3 for chunk k of the candidates: the narrow phase at each pair, its points appended to the
// flat array of the point buffer the chunk was lent, and the pair listed with their number when it
// has any.
void find_chunk_points(WorldScratch3d& s, std::size_t k, std::size_t chunks, TableWarmup warm) {
    CandidateChunk3d& chunk = s.candidate_chunks[k];
    std::vector<ContactGeometry3d>& points = s.point_buffers[chunk.buffer];
    points.clear();
    chunk.touching.clear();
    ContactScratch3d& clipping = s.clipping[thread_index()];
    const std::size_t candidates = s.pairs.size();
    const std::size_t begin = candidates * k / chunks;
    const std::size_t end = candidates * (k + 1) / chunks;
    for (std::size_t c = begin; c < end; ++c) {
        warm.touch(c - begin, end - begin);
        const BodyPair ab = s.pairs[c];
        const std::size_t count = polyhedron_contact_3d(s.posed[ab.first], s.posed[ab.second], clipping, points);
        if (count > 0) chunk.touching.push_back({static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(count)});
    }
}

// The chunks' point buffers are lent from a pool, the one given back last first: a chunk's points
// are written by its narrow phase and read by its fill soon after, so a few buffers in turn stay in
// the core's cache, where one buffer per chunk (9 MB on the 1e4-brick wall) was read from memory
// before it was written and written back after, every step. A thread is lent first the buffers it
// was lent before in the step and got back, still in its own core's cache (one last written by
// another core is fetched from that core's, slower than from memory on some processors), then from
// the shared ones. The pool holds a buffer per chunk (empty until lent), made before the narrow
// phase: it never grows while the threads lend from it.
void pool_point_buffers(WorldScratch3d& s, std::size_t chunks) {
    s.thread_free_point_buffers.resize(thread_slots());
    for (std::vector<std::uint32_t>& own : s.thread_free_point_buffers) own.clear();
    if (s.free_point_buffers.size() != s.point_buffers.size()) {
        // Not all given back (a step that threw): every buffer is free again.
        s.free_point_buffers.resize(s.point_buffers.size());
        std::iota(s.free_point_buffers.begin(), s.free_point_buffers.end(), std::uint32_t{0});
    }
    if (s.point_buffers.size() < chunks) {
        // The new ones go under the free ones already there, used least often.
        const std::size_t before = s.point_buffers.size();
        s.point_buffers.resize(chunks);
        s.free_point_buffers.insert(s.free_point_buffers.begin(), chunks - before, 0);
        std::iota(s.free_point_buffers.begin(), s.free_point_buffers.begin() + static_cast<std::ptrdiff_t>(chunks - before),
                  static_cast<std::uint32_t>(before));
    }
    s.point_buffer_lender.resize(s.point_buffers.size());
}

// Lends chunk k a point buffer for thread's narrow phase (under the caller's lock where threads
// share the pool).
void lend_point_buffer(WorldScratch3d& s, std::size_t k, std::size_t thread) {
    std::vector<std::uint32_t>& own = s.thread_free_point_buffers[thread];
    std::vector<std::uint32_t>& from = own.empty() ? s.free_point_buffers : own;
    const std::uint32_t buffer = from.back();
    from.pop_back();
    s.candidate_chunks[k].buffer = buffer;
    s.point_buffer_lender[buffer] = static_cast<std::uint32_t>(thread);
}

// Takes chunk k's point buffer back once its runs are filled, for the thread it was lent to
// (likewise under the lock).
void take_back_point_buffer(WorldScratch3d& s, std::size_t k) {
    const std::uint32_t buffer = s.candidate_chunks[k].buffer;
    s.thread_free_point_buffers[s.point_buffer_lender[buffer]].push_back(buffer);
}

// At the step's end, every buffer back with the shared ones (the threads' own on top).
void gather_point_buffers(WorldScratch3d& s) {
    for (std::vector<std::uint32_t>& own : s.thread_free_point_buffers) {
        s.free_point_buffers.insert(s.free_point_buffers.end(), own.begin(), own.end());
        own.clear();
    }
}

// Frees the memory of the buffers under the top keep of the free ones. A step filling as it places
// lends a few in turn, but one whose chunks were filled after the narrow phase (the first, with no
// table before it to size the room) lent every chunk its own, and a thread the host stalls on one
// chunk lets the others find the chunks after it, each with its buffer, until it is placed.
void trim_point_buffers(WorldScratch3d& s, std::size_t keep) {
    const std::size_t count = s.free_point_buffers.size();
    for (std::size_t i = 0; i + keep < count; ++i) {
        std::vector<ContactGeometry3d>& buffer = s.point_buffers[s.free_point_buffers[i]];
        if (buffer.capacity() > 0) std::vector<ContactGeometry3d>().swap(buffer);
    }
}

// The table's layout, made while the narrow phase runs: each chunk's pairs in contact and their
// points go after those of the chunks before it (a prefix sum over the chunks), in candidate
// order: the same layout as one serial pass, at any thread count. A chunk is placed once it and
// every chunk before it have found their points (find_contacts' lock guards this).
// (CandidateChunk3d::found: the chunk's narrow phase has ended.)
struct TableLayout {
    std::size_t placed = 0;  ///< chunks placed: WorldScratch3d::chunk_pairs, chunk_points known up to it
};

// Places the found chunks that follow the placed ones (layout.placed moves past them).
void place_found_chunks(WorldScratch3d& s, TableLayout& layout, std::size_t chunks) {
    for (std::size_t& k = layout.placed; k < chunks && s.candidate_chunks[k].found; ++k) {
        const CandidateChunk3d& chunk = s.candidate_chunks[k];
        s.chunk_pairs[k + 1] = s.chunk_pairs[k] + static_cast<std::uint32_t>(chunk.touching.size());
        // (Its buffer holds its points until its fill, which comes after its place.)
        s.chunk_points[k + 1] = s.chunk_points[k] + static_cast<std::uint32_t>(s.point_buffers[chunk.buffer].size());
    }
}

// Writes a pair's count points into its run of the table from the narrow phase's points, field by
// field (a default point built and copied in cost 0.3 M instructions a step on the 1000-brick
// wall), each then handed to carry(point), which gives it its history, as soon as it is written;
// this step's state (force, sliding) is the law's to write.
template <class CarryHistory>
[[gnu::always_inline]] inline void write_run(std::uint32_t a, std::uint32_t b, const ContactGeometry3d* points,
                                             std::uint32_t count, ContactPoint3d* run, CarryHistory carry) {
    // The key as the two 64-bit words it is stored as: the pair's bodies, then the point's
    // features (a's then b's, adjacent in ContactGeometry3d too). Built as four 32-bit fields it
    // went through vector registers, about ten instructions a point.
    std::uint64_t key_words[2];
    const ContactKey3d bodies{a, b, 0, 0};
    std::memcpy(key_words, &bodies, sizeof key_words);
    static_assert(sizeof(ContactKey3d) == sizeof key_words);
    static_assert(offsetof(ContactGeometry3d, feature_b) == offsetof(ContactGeometry3d, feature_a) + 4);
    const ContactGeometry3d* const end = points + count;
    for (const ContactGeometry3d* g = points; g != end; ++g, ++run) {
        ContactPoint3d& p = *run;
        std::memcpy(&key_words[1], &g->feature_a, sizeof key_words[1]);
        std::memcpy(static_cast<void*>(&p.key), key_words, sizeof key_words);
        p.point_m = g->point_m;
        p.normal = g->normal;
        p.overlap_m = g->overlap_m;
        p.stiffness_share = g->stiffness_share;
        carry(p);
    }
}

// Step 4 for chunk k: its pairs' entries and runs in the table, filled from the chunk's points,
// with last step's history.
void fill_chunk(World3d& w, std::size_t k) {
    WorldScratch3d& s = w.scratch;
    const CandidateChunk3d& chunk = s.candidate_chunks[k];
    std::uint32_t pair_index = s.chunk_pairs[k];
    std::uint32_t first_point = s.chunk_points[k];
    const ContactGeometry3d* points = s.point_buffers[chunk.buffer].data();
    const std::size_t ranked_pairs = s.previous_run_starts.size();
    for (const TouchingCandidate3d& touching : chunk.touching) {
        const auto [a, b] = s.pairs[touching.candidate];
        const std::uint32_t count = touching.points;
        // The dashpots take the pair's reduced mass M in proportion to the points' stiffness
        // shares w (the 2-D per-length rule), M w / S, so that every point has the requested
        // damping ratio and a box landing flat keeps its restitution. M / S is taken once a pair;
        // where no point has stiffness (S = 0) each takes M / n (and has no spring to damp). Only
        // M / S is kept, in the pair's entry: a point's own M w is point_dashpot_masses_kg's
        // (world/world_3d.hpp) to make again, where the stable step is looked for.
        double shares = 0.0;
        for (std::uint32_t j = 0; j < count; ++j) shares += points[j].stiffness_share;
        const bool by_share = shares > 0.0;
        const double mass_per_share_kg = pair_reduced_mass_kg(w, a, b) / (by_share ? shares : static_cast<double>(count));
        s.contact_pairs[pair_index] = {touching.candidate, first_point, count, by_share ? mass_per_share_kg : 0.0, {}, {}};
        ContactPoint3d* run = &w.contacts[first_point];
        s.run_starts[pair_index] = first_point;
        // Last step's run of the pair is looked for first where last step's pair of the same rank
        // was (exact while the set of pairs in contact holds): when it is there, each point takes
        // its history as it is written, the two runs merged straight; else the run is written
        // and then its history searched for from there (a hint only).
        const bool ranked = pair_index < ranked_pairs;
        const std::size_t start = ranked ? s.previous_run_starts[pair_index] : first_point;
        const std::size_t end = pair_index + 1 < ranked_pairs ? s.previous_run_starts[pair_index + 1] : s.previous.size();
        const ContactKey3d pair_key{a, b, 0, 0};
        if (ranked && is_run_of(s.previous, start, end, pair_key)) {
            RunHistoryWalk walk{&s.previous[start], s.previous.data() + end};
            write_run(a, b, points, count, run, [&](ContactPoint3d& p) { walk.carry(p); });
        } else {
            write_run(a, b, points, count, run, [](ContactPoint3d&) {});
            carry_history(s.previous, run, count, start, ranked);
        }
        points += count;
        first_point += count;
        ++pair_index;
    }
}

// Sizes v to n, its capacity kept near n: a resize past the capacity doubles it (the vector's
// growth), which the table's room, a little above last step's size, did at the first step and then
// kept (twice the table's memory, 1.6 kB a box at 1e5 bricks, for nothing); 1/16 more than n
// spares a table that grows a reallocation every step.
template <class T>
void resize_within(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) v.reserve(n + n / 16);
    v.resize(n);
}

// resize_within for a vector whose elements are all to be written again (the table of the step
// before last, its pairs and runs, swapped out for this step's fill): past its capacity they are
// dropped before the new buffer is taken, not copied into it. Copied, the 15 MB table of the 1e4
// wall was read and written on one thread while the other waited (docs/performance.md).
template <class T>
void room_within(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) v.clear();
    resize_within(v, n);
}

// Steps 3 to 5a: this step's points, sorted by key, with last step's history, and the law at
// them, a fixed chunk of the candidates at a time (in parallel): the chunk finds its pairs' points
// and, as soon as its place in the table is known (every chunk before it has found its points),
// its pairs' runs are filled with last step's history and chunk_law(first pair, end pair) runs on
// them, while the chunk's points and runs are still in cache (a chunk of the 1e4-brick wall: 1230
// points, 86 kB found, 216 kB filled), where a pass of each over the whole table (14 MB there) read
// them back from memory. The table is sized to last step's and a little more beforehand: a chunk
// placed beyond that waits for the narrow phase's end (as all do where fill_as_placed is off).
// Each chunk is filled at its own place whoever fills it and when, so the table and forces are
// those of the plain passes at any thread count. Returns chunk_law's values summed in chunk order:
// the chunks depend on the candidates' number only (world/parallel.hpp, rule 3).
template <class ChunkLaw>
LawTotals3d find_contacts(World3d& w, ChunkLaw chunk_law) {
    WorldScratch3d& s = w.scratch;
    s.broad_phase.find_pairs(s.boxes, s.is_static, s.pairs);
    // A body taken out is static, but a dynamic body could still reach its box: it is in no pair.
    if (!w.domain.left.empty())
        std::erase_if(s.pairs, [&](const BodyPair& p) {
            return is_taken_out(w.domain, p.first) || is_taken_out(w.domain, p.second);
        });
    const std::size_t chunks = candidate_chunk_count(s, s.pairs.size());
    if (s.candidate_chunks.size() < chunks) s.candidate_chunks.resize(chunks);
    if (s.clipping.size() < thread_slots()) s.clipping.resize(thread_slots());
    std::swap(s.previous, w.contacts);
    std::swap(s.previous_run_starts, s.run_starts);
    // Last step's layout of the chunks, the fill's places guessed from it (TableWarmup).
    std::swap(s.previous_chunk_points, s.chunk_points);
    const std::vector<std::uint32_t>& last_chunk_points = s.previous_chunk_points;
    const bool guessed = last_chunk_points.size() == chunks + 1 && chunks > 1;
    s.chunk_pairs.assign(chunks + 1, 0);
    s.chunk_points.assign(chunks + 1, 0);
    // The room: last step's table and 1/256 more (the shaken 1e4 wall gains about 50 points a
    // step); what the table grows by is constructed, so a large margin would cost writes.
    const std::size_t room_points = s.previous.size() + s.previous.size() / 256;
    const std::size_t room_pairs = s.contact_pairs.size() + s.contact_pairs.size() / 256;
    room_within(w.contacts, room_points);
    room_within(s.contact_pairs, room_pairs);
    room_within(s.run_starts, room_pairs);
    s.chunk_law_totals.assign(chunks, {});
    for (std::size_t k = 0; k < chunks; ++k) s.candidate_chunks[k].found = s.candidate_chunks[k].filled = false;
    const auto fill_and_law = [&](std::size_t k) {
        fill_chunk(w, k);
        s.chunk_law_totals[k] = chunk_law(s.chunk_pairs[k], s.chunk_pairs[k + 1]);
        s.candidate_chunks[k].filled = true;
    };
    pool_point_buffers(s, chunks);
    TableLayout layout;
    std::mutex layout_lock;  // guards the layout, the claimed chunks and the pool of point buffers
    // s.posed: each body posed for the narrow phase once (pose_body), not once for each pair side.
    // The placed chunks are filled by whichever thread claims them next (claimed: the chunks
    // claimed so far, under the lock), not by the thread that placed them: that one found the chunk
    // the layout waited for, often the thread the host slowed, and it was left the fill and the law
    // of every chunk found behind it while the others waited at the barrier.
    std::size_t claimed = 0;
    const auto fill_placed = [&] {
        std::size_t done = chunks;  // the chunk this thread filled last, its buffer given back at the next lock
        for (;;) {
            std::size_t j = 0;
            {
                const std::lock_guard<std::mutex> hold(layout_lock);
                if (done < chunks) take_back_point_buffer(s, done);
                if (claimed == layout.placed) return;
                j = claimed++;
            }
            const bool fits = s.chunk_points[j + 1] <= room_points && s.chunk_pairs[j + 1] <= room_pairs;
            if (fits) fill_and_law(j);
            done = fits ? j : chunks;
        }
    };
    for_fixed_chunks_then(
        chunks,
        [&](std::size_t k) {
            {
                const std::lock_guard<std::mutex> hold(layout_lock);
                lend_point_buffer(s, k, static_cast<std::size_t>(thread_index()));
            }
            TableWarmup warm;
            // In order and within both tables: a step stopped by an exception (a build without
            // OpenMP lets one out) leaves zeros after its placed chunks.
            if (guessed && last_chunk_points[k] <= last_chunk_points[k + 1] &&
                last_chunk_points[k + 1] <= std::min(w.contacts.size(), s.previous.size())) {
                warm.write_lines = reinterpret_cast<const char*>(w.contacts.data() + last_chunk_points[k]);
                warm.read_lines = reinterpret_cast<const char*>(s.previous.data() + last_chunk_points[k]);
                warm.bytes = (last_chunk_points[k + 1] - last_chunk_points[k]) * sizeof(ContactPoint3d);
            }
            find_chunk_points(s, k, chunks, warm);
            if (!s.fill_as_placed) return;
            {
                const std::lock_guard<std::mutex> hold(layout_lock);
                s.candidate_chunks[k].found = true;
                place_found_chunks(s, layout, chunks);
            }
            fill_placed();
        },
        [&] {
            // No chunk left for this thread to find: it fills chunks as the others place them,
            // until every chunk is placed and claimed.
            if (!s.fill_as_placed) return;
            for (;;) {
                fill_placed();
                {
                    const std::lock_guard<std::mutex> hold(layout_lock);
                    if (claimed == chunks) return;
                }
                std::this_thread::yield();
            }
        });
    for (std::size_t k = 0; k < chunks; ++k) s.candidate_chunks[k].found = true;
    place_found_chunks(s, layout, chunks);
    resize_within(w.contacts, s.chunk_points[chunks]);
    resize_within(s.contact_pairs, s.chunk_pairs[chunks]);
    resize_within(s.run_starts, s.chunk_pairs[chunks]);
    std::vector<std::uint32_t>& late = s.late_chunks;
    late.clear();
    for (std::size_t k = 0; k < chunks; ++k)
        if (!s.candidate_chunks[k].filled) late.push_back(static_cast<std::uint32_t>(k));
    for_fixed_chunks(late.size(), [&](std::size_t j) { fill_and_law(late[j]); });
    for (const std::uint32_t k : late) take_back_point_buffer(s, k);
    gather_point_buffers(s);
    if (s.fill_as_placed) trim_point_buffers(s, 2 * static_cast<std::size_t>(thread_count()));
    s.chunks_filled_late = late.size();
    LawTotals3d total{};
    for (std::size_t k = 0; k < chunks; ++k) total += s.chunk_law_totals[k];
    return total;
}

// The pair's motion (law_3d::PairMotion): a body that is not dynamic moves without turning.
[[gnu::always_inline]] inline PairMotion pair_motion(const World3d& w, std::uint32_t a, std::uint32_t b) {
    const Vec3 omega_a =
        w.kinds[a] == BodyKind3d::dynamic ? w.scratch.angular_velocity_world_rad_s[a] : Vec3{};
    const Vec3 omega_b =
        w.kinds[b] == BodyKind3d::dynamic ? w.scratch.angular_velocity_world_rad_s[b] : Vec3{};
    const RigidBody3d& ba = w.bodies[a];
    const RigidBody3d& bb = w.bodies[b];
    return {bb.velocity_m_s - ba.velocity_m_s + cross(omega_b, ba.position_m - bb.position_m), omega_b - omega_a,
            ba.position_m};
}

// The pair's dashpot coefficients per share: 2 h sqrt(k) times sqrt(M / S) (law_3d::LawConstants).
[[gnu::always_inline]] inline PairDashpots pair_dashpots(const LawConstants& k, const ContactPairSums3d& pair) {
    const double root_mass = std::sqrt(pair.dashpot_mass_per_share_kg);
    return {k.cn_per_root_mass * root_mass, k.cs_per_root_mass * root_mass};
}

// point_law at one point of a pair, its force and moment about a's centroid added to the pair's.
// Out of line: inlined, the pair's loop built the call's closure at every pair, for the few points
// that leave the two-lane line (about 2 % on the 1000-brick wall).
[[gnu::noinline]] void one_point_law(const PairMotion& m, const LawConstants& constants, PairDashpots d,
                                     ContactPoint3d& c, PairEnergySums& e, Vec3& force_n, Vec3& torque_n_m) {
    PairLaw law = constants.law;
    law.cn_per_share_N_s_m = d.cn_per_share_N_s_m;
    law.cs_per_share_N_s_m = d.cs_per_share_N_s_m;
    const Vec3 r = c.point_m - m.centroid_a_m;
    const Vec3 f = point_law(m, law, c, r, e);
    force_n += f;
    torque_n_m += cross(r, f);
}

// A pair's totals once its points are summed (law_3d::pair_sums): the force and moment stored in the
// pair's slot, the energy terms times their factors, and the table's work.
[[gnu::always_inline]] inline LawTotals3d pair_totals(const World3d& w, const LawConstants& constants,
                                                    ContactPairSums3d& pair, std::uint32_t a, std::uint32_t b,
                                                    const PairSums& s, const Vec3& table_step_m) {
    const Vec3 force_n = s.force_n;
    const PairEnergySums& e = s.e;
    pair.force_n = force_n;
    pair.torque_about_a_n_m = s.torque_n_m;
    LawTotals3d t;
    t.elastic_j = constants.half_kn_N_m * e.share_overlap_squared_m2 +
                  constants.half_per_ks_m_N * e.spring_squared_per_share_n2;
    t.normal_dashpot_j = constants.minus_half_dt_s * e.normal_dashpot_power_w;
    t.shear_dashpot_j = constants.minus_half_dt_s * e.shear_dashpot_power_w;
    t.friction_j = e.friction_j;
    // The table's work: a driven body's force on the other, times the centred displacement.
    if (w.kinds[a] == BodyKind3d::driven) t.table_work_j += dot(force_n, table_step_m);
    if (w.kinds[b] == BodyKind3d::driven) t.table_work_j -= dot(force_n, table_step_m);
    return t;
}

// The law at a pair's points, their forces summed into the pair's slot (the force on b and its
// moment about a's centroid), the pair's energy terms returned. Two points at a time where both
// stick inside their caps (two_point_law), one at a time otherwise.
[[gnu::always_inline]] inline LawTotals3d pair_law(World3d& w, const LawConstants& constants, ContactPairSums3d& pair,
                                                  const Vec3& table_step_m) {
    ContactPoint3d* points = &w.contacts[pair.first_point];
    const std::uint32_t a = points[0].key.body_a;
    const std::uint32_t b = points[0].key.body_b;
    const PairMotion m = pair_motion(w, a, b);
    const PairDashpots dashpots = pair_dashpots(constants, pair);
    const PairLanes both_lanes = pair_lanes(m, dashpots);
    PairLaneSums l{};
    PairEnergySums e;
    Vec3 force_n, torque_n_m;
    const auto one_point = [&](ContactPoint3d& c) {
        one_point_law(m, constants, dashpots, c, e, force_n, torque_n_m);
    };
    std::uint32_t k = 0;
    for (; k + 1 < pair.points; k += 2) {
        if (two_point_law(constants, both_lanes, points[k], points[k + 1], l)) continue;
        one_point(points[k]);
        one_point(points[k + 1]);
    }
    if (k < pair.points) one_point(points[k]);
    return pair_totals(w, constants, pair, a, b, pair_sums(l, e, force_n, torque_n_m), table_step_m);
}

#if BLOCKDEM_QUAD_LANES
// pair_law compiled for AVX2 (AVX's three-operand forms of the two-lane code), for the pairs that
// pair_law_avx leaves to it. Out of line, so that the four-point path keeps none of this path's
// values (the motion in memory for one_point_law, the two-lane constants) nor its registers.
[[gnu::noinline, gnu::target("avx2"), gnu::flatten]] LawTotals3d pair_law_in_twos_avx(World3d& w,
                                                                                   const LawConstants& constants,
                                                                                   ContactPairSums3d& pair,
                                                                                   const Vec3& table_step_m) {
    return pair_law(w, constants, pair, table_step_m);
}

// pair_law with four lanes, for processors that run AVX2 (quad_lanes_usable): a pair of four points,
// the usual face-to-face contact, goes through four_point_law, and where all four stick its sums
// are those of two_point_law at its two halves, to the bit; otherwise, or with other than four
// points, the pair goes to pair_law_in_twos_avx (what four_point_law computed is dropped: it wrote
// nothing).
[[gnu::always_inline, gnu::target("avx2")]] inline LawTotals3d pair_law_avx(World3d& w, const LawConstants& constants,
                                                                         const LawQuads& law, ContactPairSums3d& pair,
                                                                         const Vec3& table_step_m) {
    if (pair.points == 4) {
        ContactPoint3d* points = &w.contacts[pair.first_point];
        const std::uint32_t a = points[0].key.body_a;
        const std::uint32_t b = points[0].key.body_b;
        PairQuadTerms t;
        if (four_point_law(law, pair_quads(pair_motion(w, a, b), pair_dashpots(constants, pair)), points, t))
            return pair_totals(w, constants, pair, a, b, pair_sums(t), table_step_m);
    }
    return pair_law_in_twos_avx(w, constants, pair, table_step_m);
}

// pair_law_avx at pairs begin .. end - 1, their totals summed in order from zero (a chunk of
// deterministic_sum_of_chunks): one call a chunk, not a pair, so that no pair pays a call, the
// registers' saving and the frame, and the law's constants stay put across the pairs.
[[gnu::noinline, gnu::target("avx2"), gnu::flatten]] LawTotals3d pair_laws_avx(World3d& w, const LawConstants& constants,
                                                                            ContactPairSums3d* pairs,
                                                                            std::ptrdiff_t begin, std::ptrdiff_t end,
                                                                            const Vec3& table_step_m) {
    // Summed in a local, not in the returned value: that one is the caller's memory, which GCC wrote
    // at every pair (a pair's writes might have reached it, to the compiler).
    const LawQuads law = law_quads(constants);
    LawTotals3d sum{};
    for (std::ptrdiff_t i = begin; i < end; ++i) sum += pair_law_avx(w, constants, law, pairs[i], table_step_m);
    const LawTotals3d total = sum;
    return total;
}
#endif

// Each body's candidates in candidate order (a counting sort by body, serial), made again only
// when the candidates are not those it was made from: the skin list rebuilt or its filter keeping
// other pairs, bodies taken out, bodies added, a world made or read anew. Body i's entries are
// body_candidates[body_candidate_start[i] .. body_candidate_start[i + 1]). Made every step from the
// pairs in contact, this sort was a serial pass over the table that the other threads waited for.
void index_candidates_by_body(WorldScratch3d& s, std::size_t bodies) {
    std::vector<std::uint32_t>& start = s.body_candidate_start;
    start.assign(bodies + 2, 0);
    for (const BodyPair& ab : s.pairs) {
        ++start[ab.first + 2];
        ++start[ab.second + 2];
    }
    for (std::size_t i = 2; i < bodies + 2; ++i) start[i] += start[i - 1];
    // start[i + 1] is now body i's first entry; filling moves it to one past its last.
    s.body_candidates.resize(2 * s.pairs.size());
    for (std::uint32_t c = 0; c < s.pairs.size(); ++c) {
        const BodyPair& ab = s.pairs[c];
        s.body_candidates[start[ab.first + 1]++] = c;
        s.body_candidates[start[ab.second + 1]++] = c;
    }
    start.pop_back();
    s.indexed_pairs = s.pairs;
}

// Which candidates touch this step and where their pairs are in the table: each of find_contacts'
// fixed chunks stamps its touching candidates with this step's stamp and their pair's index (the
// chunk's pairs are the table's from chunk_pairs[k] on, in its touching order: lay_out_table and
// fill_chunk), and compares its candidates with those the per-body index was made from. In
// parallel, each chunk writing its own candidates' slots (rule 1). Then the index is made again
// if the candidates changed.
void index_contacts_by_body(WorldScratch3d& s, std::size_t bodies) {
    const std::size_t candidates = s.pairs.size();
    // A stamp that wrapped round could meet a mark 2^32 steps old: all marks cleared then.
    if (++s.contact_stamp == 0) {
        std::fill(s.candidate_contact.begin(), s.candidate_contact.end(), CandidateContact3d{});
        s.contact_stamp = 1;
    }
    if (s.candidate_contact.size() < candidates) s.candidate_contact.resize(candidates);
    const bool same_sizes = s.indexed_pairs.size() == candidates && s.body_candidate_start.size() == bodies + 1;
    const std::size_t chunks = candidate_chunk_count(s, candidates);
    s.chunk_changed.assign(chunks, same_sizes ? 0 : 1);
    const std::uint32_t stamp = s.contact_stamp;
    for_fixed_chunks(chunks, [&](std::size_t k) {
        std::uint32_t pair = s.chunk_pairs[k];
        for (const TouchingCandidate3d& t : s.candidate_chunks[k].touching) s.candidate_contact[t.candidate] = {stamp, pair++};
        if (!same_sizes) return;
        const std::size_t begin = candidates * k / chunks;
        const std::size_t end = candidates * (k + 1) / chunks;
        // Compared as bytes (two 32-bit indices, no padding: equal bytes are equal pairs), which the
        // library does many at a time; std::equal compared the pairs' members one by one. Not for
        // an empty chunk: an empty list's data() may be null, which memcmp may not be given.
        static_assert(sizeof(BodyPair) == 2 * sizeof(std::uint32_t));
        if (end > begin)
            s.chunk_changed[k] = std::memcmp(s.pairs.data() + begin, s.indexed_pairs.data() + begin,
                                             (end - begin) * sizeof(BodyPair)) != 0;
    });
    if (std::find(s.chunk_changed.begin(), s.chunk_changed.end(), 1) != s.chunk_changed.end())
        index_candidates_by_body(s, bodies);
}

// Body i takes its pairs' sums in table order, as one serial pass over the table adding each
// pair onto its two bodies did: its candidates are walked in candidate order, which is the table's
// (find_contacts keeps the candidates' order), and those that touch this step taken. The same terms
// in the same order, so the same bits at any thread count. About b's centroid the pair's moment is
// the one about a's plus (x_a - x_b) x F. The sums are kept in locals and stored once: added in the
// body's slot, each was stored and read again at every pair (the pair's doubles might have been the
// body's, to the compiler). Inlined into kick_run's loop.
[[gnu::always_inline]] inline void gather_pair_sums(World3d& w, std::size_t i) {
    const WorldScratch3d& s = w.scratch;
    RigidBody3d& body = w.bodies[i];
    const Vec3 position_m = body.position_m;
    Vec3 force_n = body.force_n;
    Vec3 torque_n_m = body.torque_n_m;
    const std::uint32_t stamp = s.contact_stamp;
    const std::uint32_t end = s.body_candidate_start[i + 1];
    for (std::uint32_t e = s.body_candidate_start[i]; e < end; ++e) {
        const std::uint32_t c = s.body_candidates[e];
        const CandidateContact3d mark = s.candidate_contact[c];
        if (mark.step != stamp) continue;  // apart this step
        const ContactPairSums3d& pair = s.contact_pairs[mark.pair];
        const BodyPair& ab = s.pairs[c];
        if (ab.second == i) {
            force_n += pair.force_n;
            torque_n_m += pair.torque_about_a_n_m + cross(w.bodies[ab.first].position_m - position_m, pair.force_n);
        } else {
            force_n -= pair.force_n;
            torque_n_m -= pair.torque_about_a_n_m;
        }
    }
    body.force_n = force_n;
    body.torque_n_m = torque_n_m;
}

// Step 5a for a chunk of the table just filled, its pairs first_pair .. end_pair - 1: the law at each
// pair, the pairs' totals summed in order from zero.
LawTotals3d law_on_chunk(World3d& w, const LawConstants& constants, std::uint32_t first_pair, std::uint32_t end_pair,
                       const Vec3& table_step_m) {
    ContactPairSums3d* pairs = w.scratch.contact_pairs.data();
    const std::ptrdiff_t begin = first_pair;
    const std::ptrdiff_t end = end_pair;
#if BLOCKDEM_QUAD_LANES
    if (quad_lanes_usable()) return pair_laws_avx(w, constants, pairs, begin, end, table_step_m);
#endif
    LawTotals3d sum{};
    for (std::ptrdiff_t i = begin; i < end; ++i) sum += pair_law(w, constants, pairs[i], table_step_m);
    return sum;
}

// Step 5b, once every chunk has taken the law (t: their totals): which candidates touch, for each
// pair's sums to be gathered by its two bodies in the table's order (gather_pair_sums, in the
// kick's pass over the bodies), so that each body's sum has the same terms in the same order
// whatever the thread count, and the law's energy booked.
void apply_contact_law(World3d& w, const LawTotals3d& t) {
    index_contacts_by_body(w.scratch, w.bodies.size());
    EnergyLedger& ledger = w.ledger;
    ledger.elastic_j = t.elastic_j;
    ledger.normal_dashpot_j += t.normal_dashpot_j;
    ledger.shear_dashpot_j += t.shear_dashpot_j;
    ledger.friction_j += t.friction_j;
    ledger.table_work_j += t.table_work_j;
}

struct BodyTotals {
    double kinetic_j = 0.0;
    double gravitational_j = 0.0;
    double leaving_j = 0.0;        ///< [J] kinetic + gravitational energy of the bodies leaving the model now
    std::size_t leaving = 0;
    BodyTotals& operator+=(const BodyTotals& o) {
        kinetic_j += o.kinetic_j;
        gravitational_j += o.gravitational_j;
        leaving_j += o.leaving_j;
        leaving += o.leaving;
        return *this;
    }
};

// Step 6, the bodies: the kick, and each body's energy; a body leaving the model now (its box,
// posed this step, wholly outside the extent) is kicked as the others and its energy booked as
// leaving (world/model_domain_3d.hpp). Inlined into kick_run, so into its AVX copy: with the gather
// in the same loop GCC called it, the baseline copy (world/vex_clones.hpp).
[[gnu::always_inline]] inline BodyTotals kick_body(World3d& w, std::size_t i, bool starting) {
    BodyTotals e;
    if (w.kinds[i] != BodyKind3d::dynamic || is_taken_out(w.domain, i)) return e;
    RigidBody3d& b = w.bodies[i];
    // The pose's matrix: the orientation is still the one at t.
    const double kinetic_j = update_velocity_3d(b, w.scratch.rotations[i], w.dt_s, starting);
    const double gravitational_j = b.mass_kg * w.gravity_m_s2 * b.position_m.z;
    // Without a model extent (domain.active false) nothing leaves: no call a body to find it out.
    if (w.domain.active && is_outside(w.domain, w.scratch.boxes[i])) {
        e.leaving_j = kinetic_j + gravitational_j;
        e.leaving = 1;
    } else {
        e.kinetic_j = kinetic_j;
        e.gravitational_j = gravitational_j;
    }
    return e;
}

// The drift of bodies begin .. end - 1 (world/vex_clones.hpp: compiled for AVX where there is AVX).
BLOCKDEM_VEX_CLONES void drift_run(World3d& w, std::ptrdiff_t begin, std::ptrdiff_t end, double dt_s) {
    for (std::ptrdiff_t i = begin; i < end; ++i) {
        // The pose's matrix: step_begin posed every body at the orientation the drift starts from.
        if (w.kinds[i] == BodyKind3d::dynamic && !is_taken_out(w.domain, i))
            update_position_3d(w.bodies[i], w.scratch.rotations[i], dt_s);
    }
}

// The end of step 5 and the kick for bodies begin .. end - 1, in one pass over each body's state:
// its pairs' sums gathered, a caller's load added (world/external_loads_3d.hpp; only when there
// are loads: it reads and writes the body's own state and loads only), the kick; their totals
// added in body order (a chunk of deterministic_sum_of_chunks; world/vex_clones.hpp). Why one pass:
// the gather, the loads and the kick each went through every body's lines, and the step waits on
// memory.
BLOCKDEM_VEX_CLONES BodyTotals kick_run(World3d& w, std::ptrdiff_t begin, std::ptrdiff_t end, bool starting,
                                        bool loads) {
    BodyTotals totals{};
    for (std::ptrdiff_t i = begin; i < end; ++i) {
        const auto body = static_cast<std::size_t>(i);
        gather_pair_sums(w, body);
        if (loads) add_external_load(w, body);
        totals += kick_body(w, body, starting);
    }
    return totals;
}

// The bodies that left now, in body order (the list has one order at any thread count).
void take_out_leaving_bodies(World3d& w) {
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.kinds[i] == BodyKind3d::dynamic && !is_taken_out(w.domain, i) && is_outside(w.domain, w.scratch.boxes[i]))
            take_out(w, static_cast<std::uint32_t>(i));
}

}  // namespace

void step_begin(World3d& w) {
    const double dt = w.dt_s;
    const double t = w.time_s;
    const Vec3 d_now = table_displacement(w.table, t);
    const Vec3 d_before = table_displacement(w.table, t - dt);
    const Vec3 d_after = table_displacement(w.table, t + dt);
    const auto n = static_cast<std::ptrdiff_t>(w.bodies.size());
    const Vec3 table_velocity_m_s = (1.0 / dt) * (d_now - d_before);
    size_pose_arrays(w);
    parallel_for_runs(n, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
        pose_run(w, begin, end, d_now, table_velocity_m_s);
    });
    const LawConstants constants = law_constants(w.contact, w.dt_s);
    // The scheme's energy identity pairs F(t) with (x(t+dt) - x(t-dt)) / 2 (dynamics/central_difference.cpp).
    const Vec3 table_step_m = 0.5 * (d_after - d_before);
    const LawTotals3d law = find_contacts(w, [&](std::uint32_t first_pair, std::uint32_t end_pair) {
        return law_on_chunk(w, constants, first_pair, end_pair, table_step_m);
    });
    apply_contact_law(w, law);
    // Each body's contact sums, a caller's loads and the kick, in one pass.
    const bool starting = w.steps == 0;
    const bool loads = w.external_loads.any();
    const BodyTotals totals = deterministic_sum_of_chunks(
        n, [&](std::ptrdiff_t begin, std::ptrdiff_t end) { return kick_run(w, begin, end, starting, loads); });
    EnergyLedger& ledger = w.ledger;
    if (totals.leaving > 0) {
        take_out_leaving_bodies(w);
        ledger.removed_j += totals.leaving_j;
    }
    ledger.kinetic_j = totals.kinetic_j;
    ledger.gravitational_j = totals.gravitational_j;
    if (starting) {
        ledger.initial_j = ledger.stored_j();
        ledger.initial_gravitational_j = ledger.gravitational_j;
    }
    ledger.peak_scale_j = std::max(ledger.peak_scale_j, ledger.current_scale_j());
}

void step_end(World3d& w) {
    const double dt = w.dt_s;
    parallel_for_runs(static_cast<std::ptrdiff_t>(w.bodies.size()),
                      [&](std::ptrdiff_t begin, std::ptrdiff_t end) { drift_run(w, begin, end, dt); });
    if (w.external_loads.any()) w.ledger.external_work_j += external_load_work(w);
    w.time_s += dt;
    ++w.steps;
}

}  // namespace blockdem
