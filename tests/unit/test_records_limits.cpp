// Records from anywhere (issue 11, section 2): a header phrase thousands of characters long, a
// line past the limit, counts a file cannot hold or that overflow, sample intervals no
// instrument has, and a file too large to read. Each must be an InputError naming the file and
// the line, never a crash (std::regex recursed once per character and overflowed the stack), a
// std::bad_alloc or an unlocated "stoul".
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/records/record_text.hpp"
#include "record_failure_helpers.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using testing::at2_header;
using testing::RecordFailure;

// The shared reader, plus the check that every refusal here names its file.
RecordFailure read_refusal(const std::string& name, const std::string& content, RecordReadOptions options = {}) {
    const RecordFailure f = testing::read_failure(name, content, options);
    EXPECT_NE(f.file.find(name), std::string::npos) << f.message;
    return f;
}

void expect_refusal(const std::string& name, const std::string& content, int line, const std::string& words,
                    RecordReadOptions options = {}) {
    const RecordFailure f = read_refusal(name, content, options);
    EXPECT_EQ(f.line, line) << f.message;
    EXPECT_NE(f.message.find(words), std::string::npos) << f.message;
    EXPECT_LT(f.message.size(), 400u) << "a long field is shown as an excerpt";
}

std::string knet(const std::string& rate, const std::string& duration, const std::string& scale, const std::string& data) {
    return "Origin Time       2003/01/02 04:05:00\nLat.              35.0\nLong.             135.0\nDepth. (km)       10\n"
           "Mag.              5.0\nStation Code      BAD001\nStation Lat.      35.1\nStation Long.     135.1\n"
           "Station Height(m) 0\nRecord Time       2003/01/02 04:05:20\nSampling Freq(Hz) " + rate + "\nDuration Time(s)  " +
           duration + "\nDir.              N-S\nScale Factor      " + scale +
           "\nMax. Acc. (gal)   0.0\nLast Correction   2003/01/02 04:05:05\nMemo.\n" + data;
}

// The K-NET file of the issue: a 40,000-character Scale Factor (blockdem motion exited 139).
TEST(RecordLimits, KnetScaleFactorOf40000CharactersIsAnError) {
    expect_refusal("long_scale.NS", knet("4Hz", "1", std::string(40000, '3') + "(gal)/6182761", "1 2 3 4\n"), 14,
                   "Scale Factor '3333333333333333333333333333333333333333... (40013 characters)' has an invalid number");
    expect_refusal("long_unit.NS", knet("4Hz", "1", "3920(" + std::string(40000, 'g') + ")/6182761", "1 2 3 4\n"), 14,
                   "is not gal");
}

// Every reader read a header phrase with a regex repetition over the whole field.
TEST(RecordLimits, LongHeaderPhrasesInEveryFormatAreErrors) {
    const std::string digits(40000, '1');
    expect_refusal("long_npts.AT2", at2_header + "NPTS= " + digits + ", DT= .0100 SEC\n 1 2\n", 4,
                   "NPTS = 1111111111111111111111111111111111111111... (40000 characters) exceeds the limit of 20000000");
    expect_refusal("long_dt.AT2", at2_header + "NPTS= 2, DT= " + digits + " SEC\n 1 2\n", 4,
                   "DT '1111111111111111111111111111111111111111... (40000 characters)' is not a positive number");
    expect_refusal("long_units.AT2",
                   "PEER\nE, 1/2/2003, S, 90\nACCELERATION IN UNITS OF " + std::string(40000, 'G') + "\nNPTS= 2, DT= .01\n 1 2\n", 3,
                   "unknown acceleration units 'GGGG");
    RecordReadOptions cosmos;
    cosmos.format = RecordFormat::cosmos_v2;
    expect_refusal("long_title.V2", "Corrected acceleration (Format v01.20 with" + std::string(40000, ' ') + "13 text lines)\n", 1,
                   "the file ends inside the text header of 13 lines announced at line 1", cosmos);
    expect_refusal("long_unit_phrase.txt", "time, acc[" + std::string(40000, 'x') + "]\n0 1\n0.01 2\n0.02 3\n", 1,
                   "unknown acceleration units 'xxxx");
}

TEST(RecordLimits, LineLongerThanTheLimitIsRefusedByName) {
    const std::string line(records::max_record_line_chars + 1, '1');
    expect_refusal("wide.AT2", at2_header + "NPTS= 2, DT= .0100 SEC\n" + line + "\n", 5,
                   "this line is 65537 characters long; a record line may have at most 65536");
    // A line of exactly the limit is read (here: one number of 65536 digits, which is refused as a number).
    const std::string at_limit(records::max_record_line_chars, '1');
    expect_refusal("at_limit.AT2", at2_header + "NPTS= 2, DT= .0100 SEC\n" + at_limit + "\n", 5, "is not a number (value 1 of 2)");
}

TEST(RecordLimits, HeaderCountsAreCheckedBeforeAnyAllocation) {
    // NPTS = 1e18 ended in std::bad_alloc; NPTS = 1e23 in "error: stoul".
    expect_refusal("npts_1e18.AT2", at2_header + "NPTS= 1000000000000000000, DT= .0100 SEC\n 1 2 3\n", 4,
                   "NPTS = 1000000000000000000 exceeds the limit of 20000000");
    expect_refusal("npts_1e23.AT2", at2_header + "NPTS= 100000000000000000000000, DT= .0100 SEC\n 1 2 3\n", 4,
                   "NPTS = 100000000000000000000000 exceeds the limit of 20000000");
    expect_refusal("npts_1e6.AT2", at2_header + "NPTS= 1000000, DT= .0100 SEC\n 1 2 3\n", 4,
                   "NPTS = 1000000 values are announced, but the 1 line(s) after it can hold at most 3");
    // K-NET: the count is rate x duration; 1e18 s of record was a bad_alloc.
    expect_refusal("duration.NS", knet("100Hz", "1e18", "3920(gal)/6182761", "1 2 3 4\n"), 12,
                   "announce 1e+20 values, but the rest of the file can hold at most 4");
    expect_refusal("rate.NS", knet("1e18Hz", "1", "3920(gal)/6182761", "1 2 3 4\n"), 11,
                   "a sample interval of 1e-18 s is outside the accepted 1e-05 s to 1 s");
}

TEST(RecordLimits, CosmosCountsAreLocated) {
    std::ifstream in(testing::record_samples_dir() / "cosmos_sample.V2");
    const std::string sample((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string s = sample;
        const auto at = s.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return s.replace(at, from.size(), to);
    };
    expect_refusal("npts.V2", replaced("      12 acceleration pts", "99999999999999999999999 acceleration pts"), 49,
                   "the number of points = 99999999999999999999999 exceeds the limit of 20000000");
    expect_refusal("npts_big.V2", replaced("      12 acceleration pts", " 1000000 acceleration pts"), 49,
                   "the number of points = 1000000 values are announced");
    expect_refusal("comments.V2", replaced("   2 Comment line(s)", "99999999999999 Comment line(s)"), 46,
                   "the number of comment lines = 99999999999999 exceeds the limit of 10000000");
    expect_refusal("comments_past_end.V2", replaced("   2 Comment line(s)", "9999 Comment line(s)"), 46,
                   "9999 comment lines are announced but the file ends 7 lines later");
    expect_refusal("format.V2", replaced("Format=(5E15.6)", "Format=(5E99999999999999999999.6)"), 49,
                   "the Fortran field width = 99999999999999999999 exceeds the limit of 65536");
}

TEST(RecordLimits, SampleIntervalOutsideThePhysicalRangeIsRefused) {
    expect_refusal("tiny_dt.AT2", at2_header + "NPTS= 2, DT= 1E-300 SEC\n 1 2\n", 4,
                   "a sample interval of 1e-300 s is outside the accepted 1e-05 s to 1 s");
    expect_refusal("huge_dt.AT2", at2_header + "NPTS= 2, DT= 5000 SEC\n 1 2\n", 4, "5000 s is outside");
    RecordReadOptions given;
    given.units = "g";
    given.dt_s = 1e-200;
    const RecordFailure f = read_refusal("values.txt", "1 2 3\n", given);
    EXPECT_NE(f.message.find("key 'dt': dt = 1e-200 s is outside the accepted 1e-05 s to 1 s"), std::string::npos) << f.message;
}

TEST(RecordLimits, FileLargerThanTheLimitIsRefusedBeforeReading) {
    const auto path = testing::write_temp_file("huge.AT2", at2_header);
    std::filesystem::resize_file(path, records::max_record_file_bytes + 1);  // sparse: no disk used
    try {
        read_ground_motion_record(path);
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the file holds 268435457 bytes; a record file may have at most 268435456 bytes (256 MiB)"),
                  std::string::npos)
            << e.what();
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace blockdem
