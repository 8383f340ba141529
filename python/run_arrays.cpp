#include "python/run_arrays.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace py = pybind11;

namespace blockdem::python {
namespace {

static_assert(sizeof(Vec2) == 2 * sizeof(double), "Vec2 must be two packed doubles for the N x 2 views");

py::array read_only(py::array array) {
    array.attr("setflags")(py::arg("write") = false);
    return array;
}

// One contact point, as numpy's structured dtype lays it out.
struct ContactRow {
    std::uint32_t body_a, body_b;
    double x_m, y_m;
    double normal_x, normal_y;
    double normal_force_n, shear_force_n;
    double overlap_m;
    bool sliding;
    std::uint8_t bond;
    std::uint8_t sub_point;   ///< 0: one of the pair's own points; k: its sub-contacts' interior point k
};

// One 3-D contact point (contact/contact_table_3d.hpp).
struct ContactRow3d {
    std::uint32_t body_a, body_b;
    double x_m, y_m, z_m;
    double normal_x, normal_y, normal_z;
    double force_x_n, force_y_n, force_z_n;
    double normal_force_n, shear_force_n;
    double overlap_m;
    bool sliding;
};

struct Field {
    const char* name;
    const char* format;
    std::size_t offset;
};

// A structured array of rows laid out as Row, its fields named for numpy.
template <class Row>
py::array structured_array(const std::vector<Row>& rows, const std::vector<Field>& fields) {
    py::list names, formats, offsets;
    for (const Field& f : fields) {
        names.append(f.name);
        formats.append(f.format);
        offsets.append(f.offset);
    }
    py::dict spec;
    spec["names"] = names;
    spec["formats"] = formats;
    spec["offsets"] = offsets;
    spec["itemsize"] = sizeof(Row);
    const py::dtype dtype = py::module_::import("numpy").attr("dtype")(spec);
    py::array array(dtype, std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows.size())}, std::vector<py::ssize_t>{});
    std::memcpy(array.mutable_data(), rows.data(), rows.size() * sizeof(Row));
    return array;
}

py::array rows_array(const std::vector<double>& values, std::size_t rows, std::size_t columns) {
    py::array_t<double> array({rows, columns});
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
}

// The energy columns of energy.csv, one array each (both dimensions).
py::dict energy_rows(const std::vector<EnergyLedger>& rows_of) {
    const std::size_t rows = rows_of.size();
    py::dict energy;
    auto column = [&](const char* name, auto term) {
        py::array_t<double> values(static_cast<py::ssize_t>(rows));
        for (std::size_t r = 0; r < rows; ++r) values.mutable_at(r) = term(rows_of[r]);
        energy[name] = values;
    };
    column("kinetic_J", [](const EnergyLedger& e) { return e.kinetic_j; });
    column("gravitational_change_J", [](const EnergyLedger& e) { return e.gravitational_j - e.initial_gravitational_j; });
    column("elastic_J", [](const EnergyLedger& e) { return e.elastic_j; });
    column("normal_dashpot_J", [](const EnergyLedger& e) { return e.normal_dashpot_j; });
    column("shear_dashpot_J", [](const EnergyLedger& e) { return e.shear_dashpot_j; });
    column("friction_J", [](const EnergyLedger& e) { return e.friction_j; });
    column("removed_J", [](const EnergyLedger& e) { return e.removed_j; });
    column("table_work_J", [](const EnergyLedger& e) { return e.table_work_j; });
    column("tilt_work_J", [](const EnergyLedger& e) { return e.tilt_work_j; });
    column("bond_breakage_J", [](const EnergyLedger& e) { return e.bond_breakage_j; });
    column("external_work_J", [](const EnergyLedger& e) { return e.external_work_j; });
    column("residual_J", [](const EnergyLedger& e) { return e.residual_j(); });
    column("balance_error", [](const EnergyLedger& e) { return e.balance_error(); });
    return energy;
}

}  // namespace

py::array vec2_view(const std::vector<Vec2>& values, const py::object& owner) {
    const auto n = static_cast<py::ssize_t>(values.size());
    return read_only(py::array(py::dtype::of<double>(), {n, py::ssize_t{2}},
                               {static_cast<py::ssize_t>(sizeof(Vec2)), static_cast<py::ssize_t>(sizeof(double))},
                               reinterpret_cast<const double*>(values.data()), owner));
}

py::array scalar_view(const std::vector<double>& values, const py::object& owner) {
    return read_only(py::array(py::dtype::of<double>(), {static_cast<py::ssize_t>(values.size())},
                               {static_cast<py::ssize_t>(sizeof(double))}, values.data(), owner));
}

py::array contacts_array(const World& w) {
    std::vector<ContactRow> rows;
    auto add = [&](const PairContact& pair, const ContactPoint& p, std::uint8_t sub_point) {
        rows.push_back({pair.a, pair.b, p.point_m.x, p.point_m.y, pair.normal.x, pair.normal.y, p.normal_force_n,
                        p.shear_force_n, p.overlap_m, p.sliding, static_cast<std::uint8_t>(p.bond), sub_point});
    };
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const PairContact& pair = w.contacts[i];
        // A pair's points in order along the joint: points[0], then the interior points of its
        // sub-contacts ([contact] sub_contacts > 2; they exist only while the pair has two
        // points, placed from points[0] towards points[1]: contact/sub_contacts.hpp), then points[1].
        const std::uint32_t interior = i < w.sub_contacts.size() ? w.sub_contacts[i].count : 0;
        for (std::uint32_t k = 0; k < pair.count; ++k) {
            add(pair, pair.points[k], 0);
            if (k == 0 && pair.count == 2)
                for (std::uint32_t j = 0; j < interior; ++j) add(pair, w.sub_contacts[i].points[j], static_cast<std::uint8_t>(j + 1));
        }
    }
    return structured_array(rows, {{"body_a", "u4", offsetof(ContactRow, body_a)},
                                   {"body_b", "u4", offsetof(ContactRow, body_b)},
                                   {"x", "f8", offsetof(ContactRow, x_m)},
                                   {"y", "f8", offsetof(ContactRow, y_m)},
                                   {"nx", "f8", offsetof(ContactRow, normal_x)},
                                   {"ny", "f8", offsetof(ContactRow, normal_y)},
                                   {"normal_force", "f8", offsetof(ContactRow, normal_force_n)},
                                   {"shear_force", "f8", offsetof(ContactRow, shear_force_n)},
                                   {"overlap", "f8", offsetof(ContactRow, overlap_m)},
                                   {"sliding", "?", offsetof(ContactRow, sliding)},
                                   {"bond", "u1", offsetof(ContactRow, bond)},
                                   {"sub_point", "u1", offsetof(ContactRow, sub_point)}});
}

py::array contacts_array_3d(const World3d& w) {
    std::vector<ContactRow3d> rows;
    for (const ContactPoint3d& p : w.contacts) {
        const double normal_n = dot(p.force_n, p.normal);
        rows.push_back({p.key.body_a, p.key.body_b, p.point_m.x, p.point_m.y, p.point_m.z, p.normal.x, p.normal.y, p.normal.z,
                        p.force_n.x, p.force_n.y, p.force_n.z, normal_n, length(p.force_n - normal_n * p.normal), p.overlap_m,
                        p.sliding});
    }
    return structured_array(rows, {{"body_a", "u4", offsetof(ContactRow3d, body_a)},
                                   {"body_b", "u4", offsetof(ContactRow3d, body_b)},
                                   {"x", "f8", offsetof(ContactRow3d, x_m)},
                                   {"y", "f8", offsetof(ContactRow3d, y_m)},
                                   {"z", "f8", offsetof(ContactRow3d, z_m)},
                                   {"nx", "f8", offsetof(ContactRow3d, normal_x)},
                                   {"ny", "f8", offsetof(ContactRow3d, normal_y)},
                                   {"nz", "f8", offsetof(ContactRow3d, normal_z)},
                                   {"fx", "f8", offsetof(ContactRow3d, force_x_n)},
                                   {"fy", "f8", offsetof(ContactRow3d, force_y_n)},
                                   {"fz", "f8", offsetof(ContactRow3d, force_z_n)},
                                   {"normal_force", "f8", offsetof(ContactRow3d, normal_force_n)},
                                   {"shear_force", "f8", offsetof(ContactRow3d, shear_force_n)},
                                   {"overlap", "f8", offsetof(ContactRow3d, overlap_m)},
                                   {"sliding", "?", offsetof(ContactRow3d, sliding)}});
}

py::dict energy_dict(const EnergyLedger& e) {
    py::dict d;
    d["kinetic_J"] = e.kinetic_j;
    d["gravitational_change_J"] = e.gravitational_j - e.initial_gravitational_j;
    d["elastic_J"] = e.elastic_j;
    d["normal_dashpot_J"] = e.normal_dashpot_j;
    d["shear_dashpot_J"] = e.shear_dashpot_j;
    d["friction_J"] = e.friction_j;
    d["removed_J"] = e.removed_j;
    d["table_work_J"] = e.table_work_j;
    d["tilt_work_J"] = e.tilt_work_j;
    d["bond_breakage_J"] = e.bond_breakage_j;
    d["external_work_J"] = e.external_work_j;
    d["residual_J"] = e.residual_j();
    d["balance_error"] = e.balance_error();
    return d;
}

py::dict history_dict(const ScenarioRun& run) {
    const RunTrace* trace = run.trace();
    if (!trace) throw py::value_error("this Simulation keeps no history: create it with history=True");
    const std::size_t rows = trace->rows();
    const std::size_t n = trace->bodies.size();
    const Bodies& b = run.world().bodies;
    py::dict d;
    py::list names;
    for (std::uint32_t i : trace->bodies) names.append(b.name[i]);
    d["bodies"] = names;
    d["body_ids"] = py::array_t<std::uint32_t>(trace->bodies.size(), trace->bodies.data());
    d["t"] = py::array_t<double>(rows, trace->time_s.data());
    d["x"] = rows_array(trace->x_m, rows, n);
    d["y"] = rows_array(trace->y_m, rows, n);
    d["rot"] = rows_array(trace->rotation_rad, rows, n);
    d["vx"] = rows_array(trace->vx_m_s, rows, n);
    d["vy"] = rows_array(trace->vy_m_s, rows, n);
    d["vrot"] = rows_array(trace->angular_velocity_rad_s, rows, n);
    d["ax"] = rows_array(trace->ax_m_s2, rows, n);
    d["ay"] = rows_array(trace->ay_m_s2, rows, n);
    d["arot"] = rows_array(trace->angular_acceleration_rad_s2, rows, n);
    d["energy"] = energy_rows(trace->energy);
    return d;
}

py::dict history_dict_3d(const ScenarioRun3d& run) {
    const RunTrace3d* trace = run.trace();
    if (!trace) throw py::value_error("this Simulation3d keeps no history: create it with history=True");
    const std::size_t rows = trace->rows();
    const std::size_t n = trace->bodies.size();
    py::dict d;
    py::list names;
    for (std::uint32_t i : trace->bodies) names.append(run.world().bodies[i].name);
    d["bodies"] = names;
    d["body_ids"] = py::array_t<std::uint32_t>(trace->bodies.size(), trace->bodies.data());
    d["t"] = py::array_t<double>(rows, trace->time_s.data());
    const std::pair<const char*, const std::vector<double>*> columns[] = {
        {"x", &trace->x_m},         {"y", &trace->y_m},         {"z", &trace->z_m},         {"qw", &trace->qw},
        {"qx", &trace->qx},         {"qy", &trace->qy},         {"qz", &trace->qz},         {"tilt", &trace->tilt_rad},
        {"vx", &trace->vx_m_s},     {"vy", &trace->vy_m_s},     {"vz", &trace->vz_m_s},     {"wx", &trace->wx_rad_s},
        {"wy", &trace->wy_rad_s},   {"wz", &trace->wz_rad_s}};
    for (const auto& [name, values] : columns) d[name] = rows_array(*values, rows, n);
    d["energy"] = energy_rows(trace->energy);
    return d;
}

py::object json_to_python(const nlohmann::json& value) {
    return py::module_::import("json").attr("loads")(value.dump());
}

}  // namespace blockdem::python
