#include "io/vtk_3d_writer.hpp"

#include <iterator>
#include <system_error>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/output_file.hpp"

namespace blockdem {

Vtk3dWriter::Vtk3dWriter(std::filesystem::path dir, double frame_interval_s)
    : dir_(std::move(dir)), frame_interval_s_(frame_interval_s) {
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
    times_s_.push_back(w.time_s);
}

void Vtk3dWriter::finish() {
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (std::size_t k = 0; k < times_s_.size(); ++k)
        fmt::format_to(std::back_inserter(text), "<DataSet timestep=\"{:.9g}\" file=\"bodies_{:06d}.vtp\"/>\n", times_s_[k], k);
    text += "</Collection>\n</VTKFile>\n";
    write_output_file(dir_ / "bodies.pvd", text);
}

}  // namespace blockdem
