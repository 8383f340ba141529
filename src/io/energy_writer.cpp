#include "io/energy_writer.hpp"

#include <fmt/format.h>

namespace blockdem {

const char* const energy_csv_header =
    "t_s,kinetic_J,gravitational_change_J,elastic_J,normal_dashpot_J,shear_dashpot_J,friction_J,removed_J,"
    "table_work_J,tilt_work_J,bond_breakage_J,residual_J,balance_error\n";

// residual_J = kinetic + gravitational change + elastic + dissipated + removed - table work - tilt
// work - the initial kinetic and elastic energy: every term that closes the balance is a column.
std::string energy_csv_row(double t_s, const EnergyLedger& e) {
    return fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g}\n", t_s,
                       e.kinetic_j, e.gravitational_j - e.initial_gravitational_j, e.elastic_j, e.normal_dashpot_j,
                       e.shear_dashpot_j, e.friction_j, e.removed_j, e.table_work_j, e.tilt_work_j, e.bond_breakage_j,
                       e.residual_j(), e.balance_error());
}

EnergyWriter::EnergyWriter(const std::filesystem::path& file, OutputFile::Mode mode) : out_(file, mode) {
    if (mode == OutputFile::Mode::append) return;
    out_.append(energy_csv_header);
    out_.flush();
}

void EnergyWriter::record(const World& w) {
    out_.append(energy_csv_row(w.time_s, w.energy));
    if (++rows_ % 200 == 0) out_.flush();
}

void EnergyWriter::finish(const World&) { out_.close(); }

}  // namespace blockdem
