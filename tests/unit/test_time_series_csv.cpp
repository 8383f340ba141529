// Table motion from a CSV time series: columns by name or index, one column with dt, units,
// and errors that name the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/input_error.hpp"
#include "io/time_series_csv.hpp"

namespace blockdem {
namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("blockdem-csv-" + name);
    std::ofstream(path) << text;
    return path;
}

TEST(TimeSeriesCsv, HeaderNamesAndUnits) {
    CsvSeriesSpec spec;
    spec.file = write("named.csv", "# a comment\ntime_s,other,acc_gal\n0,9,0\n0.01,9,100\n0.02,9,-50\n");
    spec.time_column = {"time_s", std::nullopt, "time_column"};
    spec.acceleration_column = {"acc_gal", std::nullopt, "column"};
    spec.unit_factor = 0.01;
    const AccelerationSeries s = read_time_series_csv(spec);
    ASSERT_EQ(s.time_s.size(), 3u);
    EXPECT_DOUBLE_EQ(s.acceleration_m_s2[1], 1.0);
    EXPECT_DOUBLE_EQ(s.acceleration_m_s2[2], -0.5);
    EXPECT_NEAR(s.velocity_m_s[2], 0.5 * (0 + 1) * 0.01 + 0.5 * (1 - 0.5) * 0.01, 1e-15);
}

TEST(TimeSeriesCsv, OneColumnWithDt) {
    CsvSeriesSpec spec;
    spec.file = write("single.txt", "0.0\n0.5\n1.0\n");
    spec.acceleration_column = {"", 0, "column"};
    spec.dt_s = 0.02;
    const AccelerationSeries s = read_time_series_csv(spec);
    EXPECT_DOUBLE_EQ(s.time_s[2], 0.04);
}

TEST(TimeSeriesCsv, ErrorsNameFileAndLine) {
    CsvSeriesSpec spec;
    spec.file = write("bad.csv", "t,a\n0,0\n0.01,abc\n");
    try {
        read_time_series_csv(spec);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("blockdem-csv-bad.csv:3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'abc' is not a finite number"), std::string::npos) << e.what();
    }
    for (const char* bad : {"0,0\n0.01,nan\n", "0,0\n0.01,inf\n", "0,0\n0.01,,0.5\n"}) {
        spec.file = write("nonfinite.csv", bad);
        EXPECT_THROW(read_time_series_csv(spec), InputError) << bad;
    }
    spec.file = write("back.csv", "0,0\n0.02,1\n0.01,2\n");
    EXPECT_THROW(read_time_series_csv(spec), InputError);
    spec.file = write("short.csv", "0,0\n0.02\n");
    EXPECT_THROW(read_time_series_csv(spec), InputError);
    spec.file = "/nonexistent/motion.csv";
    EXPECT_THROW(read_time_series_csv(spec), InputError);
}

}  // namespace
}  // namespace blockdem
