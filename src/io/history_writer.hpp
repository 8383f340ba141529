#pragma once
// history.csv: one row per output time. Column t [s], then for every recorded body
// <name>.x, .y [m] (centroid), .rot [rad] (counter-clockwise from the start), .vx, .vy [m/s],
// .vrot [rad/s], .ax, .ay [m/s^2], .arot [rad/s^2]. Rows are flushed regularly and at the end,
// also when a run stops on an error or a signal, so what was written stays readable; a write
// that fails throws OutputError and leaves only complete rows.
#include <filesystem>
#include <vector>

#include "io/output_file.hpp"
#include "world/simulation.hpp"

namespace blockdem {

class HistoryWriter : public Recorder {
public:
    /// mode append: the file already holds the header and the rows before a restart (io/run_restart.hpp).
    HistoryWriter(const std::filesystem::path& file, const World& w, OutputFile::Mode mode = OutputFile::Mode::replace);
    void record(const World& w) override;
    void finish(const World& w) override;
    /// Writes the rows buffered so far (before a state file is saved, so that the file holds
    /// every row the state counts).
    void flush() { out_.flush(); }

private:
    OutputFile out_;
    std::vector<std::uint32_t> bodies_;
    std::int64_t rows_ = 0;
};

/// Units of each column suffix, for the summary and the docs.
const std::vector<std::pair<const char*, const char*>>& history_column_units();

}  // namespace blockdem
