#pragma once
// energy.csv: the energy ledger at every output time, so that the balance can be plotted over
// the run and not only read at its end (summary.json). Columns, all in J except t_s [s] and
// balance_error [-]:
//   t_s, kinetic_J, gravitational_change_J (m g (y - y0) summed), elastic_J,
//   normal_dashpot_J, shear_dashpot_J, friction_J (dissipated so far), table_work_J (done by
//   driven bodies so far), residual_J, balance_error.
// residual_J = kinetic + gravitational_change + elastic + dissipated - table_work
//              - (initial kinetic + initial elastic); it is 0 for an exact integration.
#include <filesystem>
#include <string>

#include "io/output_file.hpp"
#include "world/simulation.hpp"

namespace blockdem {

/// energy.csv's header line and one row of it (shared by the 2-D and 3-D runs).
extern const char* const energy_csv_header;
std::string energy_csv_row(double t_s, const EnergyLedger& e);

class EnergyWriter : public Recorder {
public:
    /// mode append: the file already holds the header and the rows before a restart.
    explicit EnergyWriter(const std::filesystem::path& file, OutputFile::Mode mode = OutputFile::Mode::replace);
    void record(const World& w) override;
    void finish(const World& w) override;
    /// Writes the rows buffered so far (before a state file is saved, so that the file holds
    /// every row the state counts).
    void flush() { out_.flush(); }

private:
    OutputFile out_;
    std::int64_t rows_ = 0;
};

}  // namespace blockdem
