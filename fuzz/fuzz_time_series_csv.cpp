// Fuzzes the CSV motion reader (type = "csv", read_time_series_csv) with the column choices a
// scenario can make: time and acceleration by index, one column with a fixed dt, and columns
// named by header text.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_workspace.hpp"
#include "io/time_series_csv.hpp"

namespace {

using namespace blockdem;

CsvSeriesSpec spec(const std::filesystem::path& file, std::string time_column, std::string acceleration_column,
                   std::optional<double> dt_s) {
    CsvSeriesSpec s;
    s.file = file;
    s.time_column = std::move(time_column);
    s.acceleration_column = std::move(acceleration_column);
    s.dt_s = dt_s;
    s.unit_factor = 0.01;  // gal
    return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = fuzz::write_input("motion.csv", data, size);
    for (const CsvSeriesSpec& s : {spec(file, "0", "1", {}), spec(file, "", "0", 0.01), spec(file, "", "2", 0.005),
                                   spec(file, "time", "acceleration", {})})
        fuzz::expect_input_errors([&] { (void)read_time_series_csv(s); });
    return 0;
}
