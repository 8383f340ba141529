#pragma once
// sensors.csv: the sensors of [[sensors]] (world/sensor.hpp) at the output interval. Comment
// lines starting with '#' first (units, and each filter with its cut-off, order and delay; read
// with pandas.read_csv(path, comment="#")), then the header: t, then per point sensor
// <name>.ax, .ay [m/s^2], .vx, .vy [m/s], .x, .y [m]; per relative sensor <name>.dx, .dy [m].
// The sensors are observed, and filtered, at every step; only the rows are decimated.
#include <filesystem>
#include <vector>

#include "io/output_file.hpp"
#include "world/sensor.hpp"
#include "world/simulation.hpp"

namespace blockdem {

class SensorsWriter : public Recorder {
public:
    /// mode append: the file already holds the header and the rows before a restart (io/run_restart.hpp).
    SensorsWriter(const std::filesystem::path& file, const World& w, std::vector<SensorDef> sensors,
                  OutputFile::Mode mode = OutputFile::Mode::replace);
    /// Every step, before record(): feeds the filters.
    void observe(const World& w) { bank_.observe(w); }
    void record(const World& w) override;
    void finish(const World& w) override;
    /// Writes the buffered rows (before a state file that counts them).
    void flush() { out_.flush(); }
    /// The sensors and their filters (a state file saves and restores them).
    SensorBank& bank() { return bank_; }
    const SensorBank& bank() const { return bank_; }

private:
    SensorBank bank_;
    OutputFile out_;
    std::int64_t rows_ = 0;
};

/// The comment lines and the header row of sensors.csv.
std::string sensors_csv_header(const World& w, const SensorBank& bank);

}  // namespace blockdem
