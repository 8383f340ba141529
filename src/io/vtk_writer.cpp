#include "io/vtk_writer.hpp"

#include <iterator>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/output_file.hpp"

namespace blockdem {
namespace {

using Buffer = fmt::memory_buffer;

void begin_file(Buffer& out, double time_s) {
    fmt::format_to(std::back_inserter(out),
                   "<?xml version=\"1.0\"?>\n"
                   "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
                   "<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                   "format=\"ascii\">{:.9g}</DataArray>\n</FieldData>\n",
                   time_s);
}

void end_file(Buffer& out) { fmt::format_to(std::back_inserter(out), "</Piece>\n</PolyData>\n</VTKFile>\n"); }

// One DataArray whose values are produced by write(out, i) for i in [0, n).
template <class Write>
void data_array(Buffer& out, const char* type, const char* name, int components, std::size_t n, Write write) {
    fmt::format_to(std::back_inserter(out), "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n",
                   type, name, components);
    for (std::size_t i = 0; i < n; ++i) {
        write(out, i);
        out.push_back('\n');
    }
    fmt::format_to(std::back_inserter(out), "</DataArray>\n");
}

void vec3(Buffer& out, Vec2 v) { fmt::format_to(std::back_inserter(out), "{:.9g} {:.9g} 0", v.x, v.y); }

void body_cell_data(Buffer& out, const Bodies& b) {
    const std::size_t n = b.size();
    fmt::format_to(std::back_inserter(out), "<CellData Scalars=\"id\" Vectors=\"velocity_m_s\">\n");
    data_array(out, "Int32", "id", 1, n, [](Buffer& o, std::size_t i) { fmt::format_to(std::back_inserter(o), "{}", i); });
    data_array(out, "Int32", "kind", 1, n, [&](Buffer& o, std::size_t i) {
        fmt::format_to(std::back_inserter(o), "{}", static_cast<int>(b.kind[i]));
    });
    data_array(out, "Int32", "material", 1, n,
               [&](Buffer& o, std::size_t i) { fmt::format_to(std::back_inserter(o), "{}", b.material[i]); });
    data_array(out, "Float64", "velocity_m_s", 3, n, [&](Buffer& o, std::size_t i) { vec3(o, b.velocity_at_t_m_s[i]); });
    data_array(out, "Float64", "angular_velocity_rad_s", 1, n, [&](Buffer& o, std::size_t i) {
        fmt::format_to(std::back_inserter(o), "{:.9g}", b.angular_velocity_at_t_rad_s[i]);
    });
    data_array(out, "Float64", "rotation_rad", 1, n,
               [&](Buffer& o, std::size_t i) { fmt::format_to(std::back_inserter(o), "{:.9g}", b.rotation_rad[i]); });
    data_array(out, "Float64", "displacement_m", 3, n,
               [&](Buffer& o, std::size_t i) { vec3(o, b.position_m[i] - b.initial_position_m[i]); });
    data_array(out, "Float64", "acceleration_m_s2", 3, n,
               [&](Buffer& o, std::size_t i) { vec3(o, b.acceleration_m_s2[i]); });
    fmt::format_to(std::back_inserter(out), "</CellData>\n");
}

// Corner velocities (v + omega x r), so that ParaView can colour a rocking block by how fast
// each of its corners moves.
void body_point_data(Buffer& out, const Bodies& b, const std::vector<std::uint32_t>& owner) {
    fmt::format_to(std::back_inserter(out), "<PointData Vectors=\"velocity_m_s\">\n");
    data_array(out, "Float64", "velocity_m_s", 3, owner.size(), [&](Buffer& o, std::size_t k) {
        const std::uint32_t i = owner[k];
        vec3(o, b.velocity_at_t_m_s[i] + cross(b.angular_velocity_at_t_rad_s[i], b.world_vertices_m[k] - b.position_m[i]));
    });
    fmt::format_to(std::back_inserter(out), "</PointData>\n");
}

std::vector<const ContactPoint*> active_points(const World& w, std::vector<const PairContact*>& pair_of) {
    std::vector<const ContactPoint*> points;
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const PairContact& pair = w.contacts[i];
        for (std::uint32_t k = 0; k < pair.count; ++k) {
            points.push_back(&pair.points[k]);
            pair_of.push_back(&pair);
        }
        // The interior points of sub-contacts (contact/sub_contacts.hpp) after the pair's own.
        if (i < w.sub_contacts.size())
            for (std::uint32_t k = 0; k < w.sub_contacts[i].count; ++k) {
                points.push_back(&w.sub_contacts[i].points[k]);
                pair_of.push_back(&pair);
            }
    }
    return points;
}

void write_text(const std::filesystem::path& file, const char* data, std::size_t size) {
    write_output_file(file, std::string_view(data, size));
}

}  // namespace

void write_vtk_collection(const std::filesystem::path& file, const std::string& prefix, const std::vector<double>& times_s) {
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
    for (std::size_t k = 0; k < times_s.size(); ++k)
        text += fmt::format("<DataSet timestep=\"{:.9g}\" group=\"\" part=\"0\" file=\"{}_{:06d}.vtp\"/>\n", times_s[k],
                            prefix, k);
    text += "</Collection>\n</VTKFile>\n";
    write_text(file, text.data(), text.size());
}


std::string vtk_bodies_polydata(const World& w) {
    const Bodies& b = w.bodies;
    // The bodies' outlines (they come first in the vertex arrays), not the parts of concave ones.
    const std::size_t corners = b.outline_corners();
    std::vector<std::uint32_t> owner(corners);
    for (std::uint32_t i = 0; i < b.size(); ++i)
        for (std::uint32_t k = 0; k < b.vertex_count[i]; ++k) owner[b.vertex_begin[i] + k] = i;
    Buffer out;
    begin_file(out, w.time_s);
    fmt::format_to(std::back_inserter(out), "<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
                   "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">\n<Points>\n", corners, b.size());
    data_array(out, "Float64", "position_m", 3, corners,
               [&](Buffer& o, std::size_t k) { vec3(o, b.world_vertices_m[k]); });
    fmt::format_to(std::back_inserter(out), "</Points>\n<Polys>\n");
    data_array(out, "Int64", "connectivity", 1, b.size(), [&](Buffer& o, std::size_t i) {
        for (std::uint32_t k = 0; k < b.vertex_count[i]; ++k)
            fmt::format_to(std::back_inserter(o), "{}{}", k ? " " : "", b.vertex_begin[i] + k);
    });
    data_array(out, "Int64", "offsets", 1, b.size(), [&](Buffer& o, std::size_t i) {
        fmt::format_to(std::back_inserter(o), "{}", b.vertex_begin[i] + b.vertex_count[i]);
    });
    fmt::format_to(std::back_inserter(out), "</Polys>\n");
    body_cell_data(out, b);
    body_point_data(out, b, owner);
    end_file(out);
    return fmt::to_string(out);
}

std::string vtk_contacts_polydata(const World& w) {
    std::vector<const PairContact*> pair_of;
    const std::vector<const ContactPoint*> points = active_points(w, pair_of);
    const std::size_t n = points.size();
    Buffer out;
    begin_file(out, w.time_s);
    fmt::format_to(std::back_inserter(out), "<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" "
                   "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n", n, n);
    data_array(out, "Float64", "position_m", 3, n, [&](Buffer& o, std::size_t k) { vec3(o, points[k]->point_m); });
    fmt::format_to(std::back_inserter(out), "</Points>\n<Verts>\n");
    data_array(out, "Int64", "connectivity", 1, n, [](Buffer& o, std::size_t k) { fmt::format_to(std::back_inserter(o), "{}", k); });
    data_array(out, "Int64", "offsets", 1, n, [](Buffer& o, std::size_t k) { fmt::format_to(std::back_inserter(o), "{}", k + 1); });
    fmt::format_to(std::back_inserter(out), "</Verts>\n<PointData Scalars=\"normal_force_n\" Vectors=\"force_n\">\n");
    auto real = [&](const char* name, auto value) {
        data_array(out, "Float64", name, 1, n,
                   [&](Buffer& o, std::size_t k) { fmt::format_to(std::back_inserter(o), "{:.9g}", value(k)); });
    };
    auto integer = [&](const char* name, auto value) {
        data_array(out, "Int32", name, 1, n,
                   [&](Buffer& o, std::size_t k) { fmt::format_to(std::back_inserter(o), "{}", value(k)); });
    };
    real("normal_force_n", [&](std::size_t k) { return points[k]->normal_force_n; });
    real("shear_force_n", [&](std::size_t k) { return points[k]->shear_force_n; });
    real("overlap_m", [&](std::size_t k) { return points[k]->overlap_m; });
    integer("sliding", [&](std::size_t k) { return points[k]->sliding ? 1 : 0; });
    // 0 no bond, 1 intact, 2 broken in tension, 3 broken in shear (laws/mohr_coulomb_joint.hpp).
    integer("bond", [&](std::size_t k) { return static_cast<int>(points[k]->bond); });
    integer("body_a", [&](std::size_t k) { return pair_of[k]->a; });
    integer("body_b", [&](std::size_t k) { return pair_of[k]->b; });
    data_array(out, "Float64", "normal", 3, n, [&](Buffer& o, std::size_t k) { vec3(o, pair_of[k]->normal); });
    data_array(out, "Float64", "force_n", 3, n, [&](Buffer& o, std::size_t k) {
        const Vec2 nrm = pair_of[k]->normal;
        vec3(o, points[k]->normal_force_n * nrm + points[k]->shear_force_n * perp(nrm));
    });
    fmt::format_to(std::back_inserter(out), "</PointData>\n");
    end_file(out);
    return fmt::to_string(out);
}

VtkWriter::VtkWriter(std::filesystem::path dir, VtkSettings settings) : dir_(std::move(dir)), settings_(settings) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw InputError({dir_.string(), "", 0, 0}, "cannot create the VTK folder: " + ec.message());
}

void VtkWriter::record(const World& w) {
    const double due_s = static_cast<double>(next_frame_) * settings_.frame_interval_s;
    if (w.time_s < due_s - 0.5 * w.dt_s) return;
    const std::int64_t index = frames_written();
    const std::string bodies = vtk_bodies_polydata(w);
    write_text(dir_ / fmt::format("bodies_{:06d}.vtp", index), bodies.data(), bodies.size());
    if (settings_.contacts) {
        const std::string contacts = vtk_contacts_polydata(w);
        try {
            write_text(dir_ / fmt::format("contacts_{:06d}.vtp", index), contacts.data(), contacts.size());
        } catch (const OutputError&) {
            // The frame is a pair: a bodies file without its contacts would not be listed anyway.
            std::error_code ignored;
            std::filesystem::remove(dir_ / fmt::format("bodies_{:06d}.vtp", index), ignored);
            throw;
        }
    }
    times_s_.push_back(w.time_s);
    // The next multiple of the interval after now (several when outputs are sparser than frames).
    while (static_cast<double>(next_frame_) * settings_.frame_interval_s < w.time_s + 0.5 * w.dt_s) ++next_frame_;
}

void VtkWriter::resume(std::vector<double> times_s, double dt_s) {
    times_s_ = std::move(times_s);
    next_frame_ = 0;
    // As record() left it after the last of these frames.
    if (!times_s_.empty())
        while (static_cast<double>(next_frame_) * settings_.frame_interval_s < times_s_.back() + 0.5 * dt_s) ++next_frame_;
}

void VtkWriter::finish(const World&) {
    write_vtk_collection(dir_ / "bodies.pvd", "bodies", times_s_);
    if (settings_.contacts) write_vtk_collection(dir_ / "contacts.pvd", "contacts", times_s_);
}

}  // namespace blockdem
