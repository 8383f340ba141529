// Fuzzes the CSV motion reader (type = "csv") through read_time_series_csv_keys, as a scenario's
// table motion reads it, with the column choices a scenario can make: time and acceleration by
// index (the defaults and given), one column with a fixed dt, and columns named by header text.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_workspace.hpp"
#include "io/time_series_csv.hpp"

namespace {

using namespace blockdem;

// The keys of [table_motion.horizontal] after type = "csv" (the reader has consumed type).
std::vector<toml::table> key_sets() {
    return {
        toml::table{{"file", "motion.csv"}, {"unit", "gal"}},
        toml::table{{"file", "motion.csv"}, {"dt", 0.01}},
        toml::table{{"file", "motion.csv"}, {"dt", 0.005}, {"column", 2}, {"scale", 2.0}},
        toml::table{{"file", "motion.csv"}, {"time_column", "time"}, {"column", "acceleration"}, {"unit", "g"}},
    };
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<toml::table> keys = key_sets();
    const auto file = fuzz::write_input("motion.csv", data, size);
    for (const toml::table& table : keys) {
        TableReader reader(table, "fuzz.toml", "table_motion.horizontal");
        fuzz::expect_input_errors([&] { (void)read_time_series_csv_keys(reader, file.parent_path()); });
    }
    return 0;
}
