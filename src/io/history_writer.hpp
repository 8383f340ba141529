#pragma once
// history.csv: one row per output time. Column t [s], then for every recorded body
// <name>.x, .y [m] (centroid), .rot [rad] (counter-clockwise from the start), .vx, .vy [m/s],
// .vrot [rad/s], .ax, .ay [m/s^2], .arot [rad/s^2]. Rows are flushed regularly and at the end,
// also when a run stops on an error, so what was written stays readable.
#include <filesystem>
#include <fstream>
#include <vector>

#include "world/simulation.hpp"

namespace blockdem {

class HistoryWriter : public Recorder {
public:
    HistoryWriter(const std::filesystem::path& file, const World& w);
    void record(const World& w) override;
    void finish(const World& w) override;

private:
    std::ofstream out_;
    std::vector<std::uint32_t> bodies_;
    std::int64_t rows_ = 0;
};

/// Units of each column suffix, for the summary and the docs.
const std::vector<std::pair<const char*, const char*>>& history_column_units();

}  // namespace blockdem
