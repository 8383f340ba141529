#include "world/world_3d.hpp"

namespace blockdem {

std::uint32_t add_body(World3d& w, RigidBody3d body, BodyKind3d kind, std::string assembly) {
    w.assembly.push_back(std::move(assembly));
    w.edges.push_back(polyhedron_edges(body.shape));
    w.box_frames.push_back(box_frame(body.shape, w.edges.back()));
    w.rest_positions_m.push_back(body.position_m);
    w.kinds.push_back(kind);
    w.bodies.push_back(std::move(body));
    return static_cast<std::uint32_t>(w.bodies.size() - 1);
}

Momentum3d momentum(const World3d& w) {
    Momentum3d m;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        const RigidBody3d& b = w.bodies[i];
        const Vec3 p = b.mass_kg * b.velocity_m_s;
        m.linear_kg_m_s += p;
        m.angular_kg_m2_s += cross(b.position_m, p) + b.angular_momentum_kg_m2_s;
    }
    return m;
}

std::vector<double> point_dashpot_masses_kg(const World3d& w, const std::vector<ContactPoint3d>& table) {
    std::vector<double> masses_kg(table.size(), 0.0);
    for (std::size_t first = 0; first < table.size();) {
        const std::uint32_t a = table[first].key.body_a, b = table[first].key.body_b;
        std::size_t end = first;
        double shares = 0.0;
        for (; end < table.size() && table[end].key.body_a == a && table[end].key.body_b == b; ++end)
            shares += table[end].stiffness_share;
        const bool by_share = shares > 0.0;
        const double mass_per_share_kg = pair_reduced_mass_kg(w, a, b) / (by_share ? shares : static_cast<double>(end - first));
        for (std::size_t k = first; k < end; ++k)
            masses_kg[k] = (by_share ? table[k].stiffness_share : 1.0) * mass_per_share_kg;
        first = end;
    }
    return masses_kg;
}

namespace {
template <class T>
std::size_t held(const std::vector<T>& v) { return v.capacity() * sizeof(T); }
}  // namespace

std::size_t memory_bytes(const World3d& w) {
    std::size_t bytes = sizeof(World3d) + held(w.bodies) + held(w.kinds) + held(w.edges) + held(w.box_frames) + held(w.rest_positions_m) +
                        held(w.assembly) + held(w.contacts);
    for (const std::string& a : w.assembly) bytes += a.capacity();
    for (const RigidBody3d& b : w.bodies) {
        bytes += b.name.capacity() + held(b.shape.vertices_m) + held(b.shape.faces) + held(b.shape.face_normals);
        for (const auto& f : b.shape.faces) bytes += held(f);
    }
    for (const PolyhedronEdges& e : w.edges) {
        bytes += held(e.edges) + held(e.face_edges) + held(e.directions) + held(e.edge_direction);
        for (const auto& f : e.face_edges) bytes += held(f);
    }
    const WorldScratch3d& s = w.scratch;
    bytes += held(s.vertex_start) + held(s.face_start) + held(s.direction_start) + held(s.world_vertices_m) +
             held(s.world_normals) + held(s.world_directions) + held(s.angular_velocity_world_rad_s) + held(s.boxes) + held(s.is_static) + held(s.pairs) +
             held(s.candidate_chunks) + held(s.previous) + held(s.contact_pairs) + held(s.run_starts) + held(s.previous_run_starts) + held(s.clipping) + s.broad_phase.memory_bytes() +
             held(s.chunk_pairs) + held(s.chunk_points) + held(s.indexed_pairs) + held(s.body_candidate_start) + held(s.body_candidates) +
             held(s.candidate_contact) + held(s.chunk_changed) + held(s.point_buffers) + held(s.free_point_buffers) + held(s.thread_free_point_buffers) + held(s.point_buffer_lender) +
             held(s.rotations) + held(s.posed) + held(s.body_directions) + held(s.centroids_m) +
             held(s.previous_chunk_points) + held(s.chunk_law_totals) + held(s.late_chunks);
    for (const CandidateChunk3d& c : s.candidate_chunks) bytes += held(c.touching);
    for (const auto& b : s.point_buffers) bytes += held(b);
    for (const auto& f : s.thread_free_point_buffers) bytes += held(f);
    for (const ContactScratch3d& c : s.clipping) bytes += held(c.polygon) + held(c.clipped) + held(c.heights_m2);
    return bytes;
}

}  // namespace blockdem
