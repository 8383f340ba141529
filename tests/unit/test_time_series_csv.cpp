// Table motion from a CSV time series: columns by name or index, one column with dt, units,
// and errors that name the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

// The message of reading spec ("" when it reads).
std::string csv_error(const CsvSeriesSpec& spec) {
    try {
        read_time_series_csv(spec);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expect_in(const std::string& message, const std::string& words) {
    EXPECT_NE(message.find(words), std::string::npos) << message;
}

// Times before 0 had the table moving at the start of the run (a motion starts at rest).
TEST(TimeSeriesCsv, NegativeTimesAreRefusedWithFileAndLine) {
    CsvSeriesSpec spec;
    spec.file = write("negative.csv", "t,a\n-1,0\n-0.99,1\n-0.98,0\n");
    const std::string m = csv_error(spec);
    expect_in(m, "blockdem-csv-negative.csv:2:");
    expect_in(m, "time -1 s is before 0: a motion starts at rest at its first sample");
    expect_in(m, "shift the times to start at 0 or later");
    spec.file = write("late.csv", "t,a\n0.5,0\n0.51,1\n0.52,0\n");  // a later start is a delay
    EXPECT_DOUBLE_EQ(read_time_series_csv(spec).time_s.front(), 0.5);
}

// A row longer or shorter than the header has a value too many or missing: refused, not read.
TEST(TimeSeriesCsv, RowsOfAnotherWidthThanTheHeaderAreRefused) {
    CsvSeriesSpec spec;
    spec.file = write("wide.csv", "t,a\n0,0\n0.01,1,2\n0.02,1\n");
    std::string m = csv_error(spec);
    expect_in(m, "blockdem-csv-wide.csv:3:");
    expect_in(m, "this line has 3 columns but the header has 2");
    spec.file = write("narrow.csv", "t,a,b\n0,0,0\n0.01,1\n0.02,1,0\n");
    expect_in(csv_error(spec), "blockdem-csv-narrow.csv:3: this line has 2 columns but the header has 3");
    spec.file = write("ragged.csv", "0 0\n0.01 1\n0.02 1 7\n");  // no header: the first row sets the width
    expect_in(csv_error(spec), "blockdem-csv-ragged.csv:3: this line has 3 columns but the first row has 2");
    // Rows ended by a comma (a spreadsheet's export) have no column more.
    spec.file = write("trailing.csv", "t,a,\n0,0,\n0.01,1\n0.02,0.5,\n");
    EXPECT_EQ(read_time_series_csv(spec).acceleration_m_s2.size(), 3u);
}

// dt given and the default column 0 read the time column as the acceleration (a ramp).
TEST(TimeSeriesCsv, TimeColumnReadAsAccelerationIsRefused) {
    CsvSeriesSpec spec;
    spec.dt_s = 0.01;
    spec.acceleration_column = {"", 0, "column"};
    spec.file = write("dt_time.csv", "t,a\n0,0\n0.01,1\n0.02,0\n");
    const std::string m = csv_error(spec);
    expect_in(m, "blockdem-csv-dt_time.csv:1:");
    expect_in(m, "column selects column 0 ('t'), which by its header holds time, as the acceleration: pick the "
                 "acceleration column with `column` (a header name or 0-based index) or drop `dt` to take the times "
                 "from the file");
    for (const char* name : {"time", "Time (s)", "TIME_S", "t[s]", "t (s)", "t_s", "sec", "seconds"}) {
        spec.file = write("dt_names.csv", std::string(name) + ",a\n0,0\n0.01,1\n");
        expect_in(csv_error(spec), "which by its header holds time");
    }
    spec.acceleration_column = {"a", std::nullopt, "column"};  // the acceleration column named: read
    spec.file = write("dt_named.csv", "t,a\n0,0\n0.01,1\n0.02,0\n");
    EXPECT_DOUBLE_EQ(read_time_series_csv(spec).acceleration_m_s2[1], 1.0);
    for (const char* name : {"a", "tilt", "acc_g", "temperature"}) {  // not time names
        spec.acceleration_column = {"", 0, "column"};
        spec.file = write("dt_other.csv", std::string(name) + "\n0\n1\n");
        EXPECT_EQ(csv_error(spec), "") << name;
    }
    spec.dt_s.reset();  // without dt, a column naming time taken as the acceleration is refused too
    spec.time_column = {"", 1, "time_column"};
    spec.acceleration_column = {"", 0, "column"};
    spec.file = write("swapped.csv", "time,a\n0,0\n0.01,1\n");
    const std::string swapped = csv_error(spec);
    expect_in(swapped, "column selects column 0 ('time')");
    EXPECT_EQ(swapped.find("drop `dt`"), std::string::npos) << swapped;
}

}  // namespace
}  // namespace blockdem
