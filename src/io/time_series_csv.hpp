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

/// A column named by its header text or by its 0-based index.
struct CsvColumn {
    std::string name;                  ///< header text; empty when index is given
    std::optional<std::size_t> index;  ///< 0-based
    std::string key = "column";        ///< the scenario key that chose it (for messages)
};

/// The most columns a time-series CSV may have (and so the largest index a key may give).
inline constexpr std::size_t max_csv_columns = 10'000;

struct CsvSeriesSpec {
    std::filesystem::path file;
    CsvColumn time_column{"", 0, "time_column"};     ///< unused when dt is given
    CsvColumn acceleration_column{"", 1, "column"};
    std::optional<double> dt_s;       ///< [s] sample interval for a one-column file
    double unit_factor = 1.0;         ///< multiplies the values to give m/s^2
};

/// Reads the series. Throws InputError naming the file and line for any bad line, and the key
/// of a column that the file does not have.
AccelerationSeries read_time_series_csv(const CsvSeriesSpec& spec);

/// Reads the keys of a type = "csv" motion component and the file they name.
AccelerationSeries read_time_series_csv_keys(TableReader& keys, const std::filesystem::path& scenario_dir);

}  // namespace blockdem
