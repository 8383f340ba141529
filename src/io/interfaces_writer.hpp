#pragma once
// interfaces.csv: the interfaces (world/interface_monitor.hpp) at the output interval, in long
// form, one row per (time, interface), so that its width stays the same for a block or a wall:
//   t [s], body_a, body_b, normal_force_n [N], shear_force_n [N], points, opening_m [m], slip_m [m]
// With every touching pair followed, a row is written for each pair touching then; named pairs
// get a row at every output time (points 0 and forces 0 while apart). Comment lines starting
// with '#' come first (read with pandas.read_csv(path, comment="#")).
// The summary's "interfaces" entry: per interface its peak and residual slip and peak opening.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "io/output_file.hpp"
#include "world/interface_monitor.hpp"
#include "world/simulation.hpp"

namespace blockdem {

class InterfacesWriter : public Recorder {
public:
    /// mode append: the file already holds the header and the rows before a restart (io/run_restart.hpp).
    InterfacesWriter(const std::filesystem::path& file, const InterfaceSelection& selection,
                     OutputFile::Mode mode = OutputFile::Mode::replace);
    /// Every step, before record().
    void observe(const World& w) { monitor_.observe(w); }
    void record(const World& w) override;
    void finish(const World& w) override;
    /// Writes the buffered rows (before a state file that counts them).
    void flush() { out_.flush(); }
    const InterfaceMonitor& monitor() const { return monitor_; }
    /// Rows written at output times (not the extra row an interrupted run writes as it stops):
    /// with every touching pair followed, a time has as many rows as pairs touching then, so a
    /// restart cuts the file back by this count, which a state file keeps.
    std::int64_t output_time_rows() const { return output_time_rows_; }
    /// Continues from a state file: the monitor's interfaces and the rows the file holds.
    void restore(std::vector<InterfaceState> states, std::int64_t output_time_rows);

private:
    InterfaceMonitor monitor_;
    OutputFile out_;
    std::int64_t rows_ = 0;
    std::int64_t output_time_rows_ = 0;
};

/// Per interface: the bodies, when it first touched, peak |slip|, residual (final) slip, peak
/// opening; with the definitions' units.
nlohmann::json interfaces_summary(const World& w, const InterfaceMonitor& monitor);

}  // namespace blockdem
