#include "io/vtk_3d_writer.hpp"

#include <iterator>
#include <system_error>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/vtk_writer.hpp"

namespace blockdem {

std::string vtk_contacts_3d_polydata(const World3d& w) {
    const std::vector<ContactPoint3d>& c = w.contacts;
    std::string points, cells, offsets;
    for (std::size_t k = 0; k < c.size(); ++k) {
        fmt::format_to(std::back_inserter(points), "{:.9g} {:.9g} {:.9g}\n", c[k].point_m.x, c[k].point_m.y, c[k].point_m.z);
        fmt::format_to(std::back_inserter(cells), "{} ", k);
        fmt::format_to(std::back_inserter(offsets), "{} ", k + 1);
    }
    std::string data;
    auto column = [&](const char* type, const char* name, int components, auto write) {
        fmt::format_to(std::back_inserter(data), "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">",
                       type, name, components);
        for (const ContactPoint3d& p : c) write(p);
        data += "</DataArray>\n";
    };
    auto normal_n = [](const ContactPoint3d& p) { return dot(p.force_n, p.normal); };
    auto real = [&](double x) { fmt::format_to(std::back_inserter(data), "{:.9g} ", x); };
    auto vec = [&](Vec3 v) { fmt::format_to(std::back_inserter(data), "{:.9g} {:.9g} {:.9g} ", v.x, v.y, v.z); };
    column("Float64", "normal_force_n", 1, [&](const ContactPoint3d& p) { real(normal_n(p)); });
    column("Float64", "shear_force_n", 1, [&](const ContactPoint3d& p) { real(length(p.force_n - normal_n(p) * p.normal)); });
    column("Float64", "overlap_m", 1, [&](const ContactPoint3d& p) { real(p.overlap_m); });
    column("Int32", "sliding", 1, [&](const ContactPoint3d& p) { fmt::format_to(std::back_inserter(data), "{} ", p.sliding ? 1 : 0); });
    column("Int32", "body_a", 1, [&](const ContactPoint3d& p) { fmt::format_to(std::back_inserter(data), "{} ", p.key.body_a); });
    column("Int32", "body_b", 1, [&](const ContactPoint3d& p) { fmt::format_to(std::back_inserter(data), "{} ", p.key.body_b); });
    column("Float64", "normal", 3, [&](const ContactPoint3d& p) { vec(p.normal); });
    column("Float64", "force_n", 3, [&](const ContactPoint3d& p) { vec(p.force_n); });
    return fmt::format("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                       "<PolyData>\n<Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\">\n"
                       "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n{1}</DataArray></Points>\n"
                       "<Verts>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">{2}</DataArray>\n"
                       "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">{3}</DataArray>\n</Verts>\n"
                       "<PointData Scalars=\"normal_force_n\" Vectors=\"force_n\">\n{4}</PointData>\n"
                       "</Piece>\n</PolyData>\n</VTKFile>\n",
                       c.size(), points, cells, offsets, data);
}

Vtk3dWriter::Vtk3dWriter(std::filesystem::path dir, double frame_interval_s, bool contacts)
    : dir_(std::move(dir)), frame_interval_s_(frame_interval_s), contacts_(contacts) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw InputError({dir_.string(), "", 0, 0}, "cannot create the VTK folder: " + ec.message());
}

void Vtk3dWriter::record(const World3d& w, const ResponseMonitor3d& monitor) {
    // (Half a step of slack: times are sums of dt, and a frame due at 0.04 s must not slip a step.)
    if (w.time_s < static_cast<double>(times_s_.size()) * frame_interval_s_ - 0.5 * w.dt_s) return;
    std::string points, connectivity, offsets, body, tilt, speed;
    std::size_t point_count = 0, face_count = 0, offset = 0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const RigidBody3d& b = w.bodies[i];
        for (std::size_t k = 0; k < b.shape.vertices_m.size(); ++k) {
            const Vec3 v = world_vertex(b, k) + (position_now_m(w, i) - b.position_m);
            fmt::format_to(std::back_inserter(points), "{:.9g} {:.9g} {:.9g}\n", v.x, v.y, v.z);
        }
        const double body_tilt = tilt_rad(turn_since_start(w, monitor.bodies()[i], i));
        for (const auto& face : b.shape.faces) {
            for (std::size_t corner : face) fmt::format_to(std::back_inserter(connectivity), "{} ", point_count + corner);
            offset += face.size();
            fmt::format_to(std::back_inserter(offsets), "{} ", offset);
            fmt::format_to(std::back_inserter(body), "{} ", i);
            fmt::format_to(std::back_inserter(tilt), "{:.6g} ", body_tilt);
            fmt::format_to(std::back_inserter(speed), "{:.6g} ", length(velocity_now_m_s(w, i)));
            ++face_count;
        }
        point_count += b.shape.vertices_m.size();
    }
    const std::string name = fmt::format("bodies_{:06d}.vtp", times_s_.size());
    write_output_file(
        dir_ / name,
        fmt::format("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "<PolyData>\n<Piece NumberOfPoints=\"{}\" NumberOfPolys=\"{}\">\n"
                    "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n{}</DataArray></Points>\n"
                    "<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">{}</DataArray>\n"
                    "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">{}</DataArray>\n</Polys>\n"
                    "<CellData Scalars=\"body\">\n<DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">{}</DataArray>\n"
                    "<DataArray type=\"Float64\" Name=\"tilt_rad\" format=\"ascii\">{}</DataArray>\n"
                    "<DataArray type=\"Float64\" Name=\"speed_m_s\" format=\"ascii\">{}</DataArray>\n</CellData>\n"
                    "</Piece>\n</PolyData>\n</VTKFile>\n",
                    point_count, face_count, points, connectivity, offsets, body, tilt, speed));
    if (contacts_) {
        try {
            write_output_file(dir_ / fmt::format("contacts_{:06d}.vtp", times_s_.size()), vtk_contacts_3d_polydata(w));
        } catch (const OutputError&) {
            // The frame is a pair: a bodies file without its contacts would not be listed anyway.
            std::error_code ignored;
            std::filesystem::remove(dir_ / name, ignored);
            throw;
        }
    }
    times_s_.push_back(w.time_s);
}

void Vtk3dWriter::finish() {
    write_vtk_collection(dir_ / "bodies.pvd", "bodies", times_s_);
    if (contacts_) write_vtk_collection(dir_ / "contacts.pvd", "contacts", times_s_);
}

}  // namespace blockdem
