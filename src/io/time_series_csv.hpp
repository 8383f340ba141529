#pragma once
// Table motion from a CSV time series (type = "csv", docs/scenario.md): either a time column
// and an acceleration column, or one acceleration column with a fixed dt. Lines starting with
// '#' are comments; a first line that is not numeric is a header naming the columns.
// (Accelerograms in the databases' own formats are read by type = "record", docs/records.md.)
#include <filesystem>
#include <optional>
#include <string>

#include "io/toml_reader.hpp"
#include "motion/table_motion.hpp"

namespace blockdem {

struct CsvSeriesSpec {
    std::filesystem::path file;
    std::string time_column;          ///< header name or 0-based index; empty when dt is given
    std::string acceleration_column;  ///< header name or 0-based index
    std::optional<double> dt_s;       ///< [s] sample interval for a one-column file
    double unit_factor = 1.0;         ///< multiplies the values to give m/s^2
};

/// Reads the series. Throws InputError naming the file and line for any bad line.
AccelerationSeries read_time_series_csv(const CsvSeriesSpec& spec);

/// Reads the keys of a type = "csv" motion component and the file they name.
AccelerationSeries read_time_series_csv_keys(TableReader& keys, const std::filesystem::path& scenario_dir);

}  // namespace blockdem
