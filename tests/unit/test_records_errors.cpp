// Malformed record files: truncated, wrong NPTS, non-numeric values, unknown units. Each must be
// an InputError that names the file and the line where the problem shows.
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "record_failure_helpers.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using testing::at2_header;
using testing::read_failure;
using testing::RecordFailure;

void expect_failure(const std::string& name, const std::string& content, int line, const std::string& words,
                    RecordReadOptions options = {}) {
    const RecordFailure f = read_failure(name, content, options);
    EXPECT_NE(f.file.find(name), std::string::npos) << f.message;
    EXPECT_EQ(f.line, line) << f.message;
    EXPECT_NE(f.message.find(words), std::string::npos) << f.message;
    if (line > 0)
        EXPECT_NE(f.message.find(name + ":" + std::to_string(line)), std::string::npos) << "message names file:line: " << f.message;
}

TEST(MalformedAt2, Truncated) {
    expect_failure("truncated.AT2", at2_header + "NPTS=   8, DT= .0100 SEC\n .1E-01 .2E-01 .3E-01 .4E-01 .5E-01\n .6E-01\n", 6,
                   "truncated: the file ends after 6 of the 8 values");
}

TEST(MalformedAt2, MoreValuesThanNpts) {
    expect_failure("wrong_npts.AT2", at2_header + "NPTS=   4, DT= .0100 SEC\n .1E-01 .2E-01 .3E-01 .4E-01 .5E-01\n .6E-01\n", 5,
                   "2 more values than the NPTS = 4 of line 4");
}

TEST(MalformedAt2, NonNumericValue) {
    const RecordFailure f = read_failure("non_numeric.AT2", at2_header + "NPTS=   6, DT= .0100 SEC\n .1E-01 .2E-01 .3E-01\n .4E-01 O.5E-01 .6E-01\n");
    EXPECT_EQ(f.line, 6);
    EXPECT_NE(f.message.find("'O.5E-01' is not a number (value 5 of 6)"), std::string::npos) << f.message;
    EXPECT_NE(f.message.find("non_numeric.AT2:6:9"), std::string::npos) << "column of the bad value: " << f.message;
}

TEST(MalformedAt2, UnknownUnits) {
    expect_failure("furlongs.AT2",
                   "PEER\nBad Event, 1/2/2003, Bad Station, 90\nACCELERATION TIME SERIES IN UNITS OF FURLONGS/FORTNIGHT2\n"
                   "NPTS=   2, DT= .0100 SEC\n .1E-01 .2E-01\n",
                   3, "unknown acceleration units 'FURLONGS/FORTNIGHT2'");
}

TEST(MalformedAt2, VelocityFileRefused) {
    expect_failure("velocity.VT2",
                   "PEER\nBad Event, 1/2/2003, Bad Station, 90\nVELOCITY TIME SERIES IN UNITS OF CM/S\nNPTS=   2, DT= .0100 SEC\n 1. 2.\n", 3,
                   "velocity or displacement file");
}

TEST(MalformedAt2, BadDt) {
    expect_failure("bad_dt.AT2", at2_header + "NPTS=   2, DT= -.0100 SEC\n 1. 2.\n", 4, "not a positive number");
}

TEST(MalformedAt2, UnknownUnitOverrideNamesTheOption) {
    RecordReadOptions o;
    o.units = "furlong";
    const auto path = testing::write_temp_file("ok.AT2", at2_header + "NPTS=   2, DT= .0100 SEC\n 1. 2.\n");
    try {
        read_ground_motion_record(path, o);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.where().key, "units");
    }
}

std::string knet(const std::string& scale, const std::string& data) {
    return "Origin Time       2003/01/02 04:05:00\nLat.              35.0\nLong.             135.0\nDepth. (km)       10\n"
           "Mag.              5.0\nStation Code      BAD001\nStation Lat.      35.1\nStation Long.     135.1\n"
           "Station Height(m) 0\nRecord Time       2003/01/02 04:05:20\nSampling Freq(Hz) 4Hz\nDuration Time(s)  1\n"
           "Dir.              N-S\nScale Factor      " + scale + "\nMax. Acc. (gal)   0.0\nLast Correction   2003/01/02 04:05:05\n"
           "Memo.\n" + data;
}

TEST(MalformedKnet, Truncated) { expect_failure("short.NS", knet("3920(gal)/6182761", "     1      2      3\n"), 18, "after 3 of the 4 values"); }

TEST(MalformedKnet, MoreValuesThanRateTimesDuration) {
    expect_failure("long.NS", knet("3920(gal)/6182761", "     1      2      3      4      5\n"), 18, "1 more than the 4 values");
}

TEST(MalformedKnet, NonNumericCount) {
    expect_failure("letters.NS", knet("3920(gal)/6182761", "     1      2\n     x      4\n"), 19, "'x' is not a number");
}

TEST(MalformedKnet, ScaleFactorNotInGal) {
    expect_failure("kine.NS", knet("3920(kine)/6182761", "     1      2      3      4\n"), 14, "unit 'kine' is not gal");
}

TEST(MalformedKnet, HeaderCutShort) {
    RecordReadOptions o;
    o.format = RecordFormat::knet;  // too short to be detected as K-NET
    expect_failure("header.NS", "Origin Time       2003/01/02 04:05:00\nLat.              35.0\n", 2, "17 header lines", o);
}

TEST(MalformedCosmos, TruncatedValues) {
    std::ifstream in(testing::record_samples_dir() / "cosmos_sample.V2");
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    content = content.substr(0, content.find("   1.100000e+00"));  // drop the last data line and the trailer
    const RecordFailure f = read_failure("cut.V2", content);
    EXPECT_NE(f.message.find("after 10 of the 12 values"), std::string::npos) << f.message;
    EXPECT_GT(f.line, 40);
}

TEST(MalformedCosmos, UnknownUnits) {
    std::ifstream in(testing::record_samples_dir() / "cosmos_sample.V2");
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = content.find("units=cm/sec2");
    content.replace(at, 13, "units=in/sec2");
    const RecordFailure f = read_failure("inches.V2", content);
    EXPECT_NE(f.message.find("unknown acceleration units 'in/sec2'"), std::string::npos) << f.message;
    EXPECT_EQ(f.line, 49);  // the data header line
}

TEST(MalformedPlain, NonNumericInTheMiddle) {
    expect_failure("middle.csv", "time,acc[g]\n0.00,0.1\n0.01,abc\n0.02,0.3\n", 3, "'abc' is not a number");
}

TEST(MalformedPlain, UnevenTimeColumn) {
    expect_failure("uneven.csv", "time,acc[g]\n0.00,0.1\n0.01,0.2\n0.03,0.3\n0.04,0.3\n", 4, "not equally spaced");
}

TEST(MalformedPlain, UnknownUnitsInColumnName) {
    expect_failure("feet.csv", "time,acc[ft/s^2]\n0.00,0.1\n0.01,0.2\n", 1, "unknown acceleration units 'ft/s^2'");
}

TEST(MalformedPlain, NoUnitsStated) {
    expect_failure("bare.txt", "0.1 0.2 0.3\n0.4\n", 1, "does not state its units");
}

TEST(MalformedPlain, NoData) { expect_failure("empty.txt", "just words\n", 0, "no line of numbers"); }

// A value finite in the file but not in m/s^2 (1e308 g) was reported as "sample 2 is not
// finite" with neither the file nor the line: each format names them.
TEST(RecordOverflow, ValueBeyondRangeInSiUnitsNamesFileAndLine) {
    const std::string words = "is beyond the range of a number in m/s^2: the value or the units are wrong";
    expect_failure("huge.csv", "time,acc[g]\n0.00,0.1\n0.01,0.2\n0.02,1e308\n0.03,0.3\n", 4, "sample 3 (1e+308 in the file's units");
    expect_failure("huge_values.txt", "units of g\n0.1 0.2 0.3\n0.4 1e308\n", 3, words, {.dt_s = 0.01});
    expect_failure("huge.AT2", at2_header + "NPTS=   6, DT= .0100 SEC\n .1E-01 .2E-01 .3E-01\n .4E-01 1E308 .6E-01\n", 6,
                   "sample 5 (1e+308 in the file's units, 9.80665 m/s^2 each)");
    expect_failure("huge.NS", knet("3920(gal)/1", "     1      2\n     3  1e308\n"), 19, words);  // 39.2 m/s^2 a count
    expect_failure("huge_jma.csv",
                   " SITE CODE= X\n SAMPLING RATE= 100Hz\n UNIT  = gal\n NS,EW,UD\n 1,2,3\n 1e308,2,3\n", 6, words,
                   {.units = "g"});
    std::ifstream in(testing::record_samples_dir() / "cosmos_sample.V2");
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    content.replace(content.find("  -8.000000e-01"), 15, "   1.00000e+308");
    expect_failure("huge.V2", content, 51, "sample 8 (1e+308", {.units = "g"});
}

}  // namespace
}  // namespace blockdem
