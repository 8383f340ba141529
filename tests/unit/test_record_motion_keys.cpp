// Scenario keys of type = "record" and type = "synthetic" table motions.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "io/input_error.hpp"
#include "io/record_motion_keys.hpp"
#include "motion/intensity_measures.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

// The [table_motion.horizontal] table of a scenario text, with "type" already consumed.
struct Keys {
    toml::table root;
    std::optional<TableReader> reader;
    explicit Keys(std::string_view text) : root(toml::parse(text, std::string_view("scenario.toml"))) {
        reader.emplace(*root["table_motion"]["horizontal"].as_table(), "scenario.toml", "table_motion.horizontal");
        reader->has("type");
    }
};

TEST(RecordMotionKeys, SampleRecordScaledAndDelayed) {
    Keys k(R"(
[table_motion.horizontal]
type = "record"
file = "legacy_pea.AT2"
target_pga = 0.5
target_pga_unit = "g"
delay = 1.0
)");
    const auto s = read_record_motion(*k.reader, testing::record_samples_dir());
    ASSERT_EQ(s.time_s.size(), 12u);
    EXPECT_DOUBLE_EQ(s.time_s.front(), 1.0);
    EXPECT_NEAR(s.time_s.back(), 1.11, 1e-12);
    EXPECT_NEAR(s.acceleration_m_s2[11], -0.5 * 9.80665, 1e-12);
    EXPECT_NE(s.source.find("legacy_pea.AT2"), std::string::npos);
}

TEST(RecordMotionKeys, PlainTextNeedsItsUnitsAndDt) {
    Keys k(R"(
[table_motion.horizontal]
type = "record"
file = "values_only.txt"
format = "plain"
unit = "gal"
dt = 0.02
scale = 2.0
pad = 0.1
)");
    const auto s = read_record_motion(*k.reader, testing::record_samples_dir());
    EXPECT_EQ(s.time_s.size(), 17u);
    EXPECT_NEAR(s.acceleration_m_s2[11], -0.024 * 0.01, 1e-15);
}

TEST(RecordMotionKeys, BaselineBringsTheTableBackToRest) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    Keys k(R"(
[table_motion.horizontal]
type = "record"
file = "plain-text/elCentro.dat"
unit = "g"
dt = 0.02
baseline = "polynomial"
baseline_order = 4
start = 1.0
duration = 20.0
taper = 0.5
)");
    const auto s = read_record_motion(*k.reader, testing::ground_motions_dir());
    EXPECT_NEAR(s.time_s.back() - s.time_s.front(), 20.0, 1e-9);
    EXPECT_LT(std::abs(s.velocity_m_s.back()), 1e-9);
    EXPECT_LT(std::abs(s.displacement_m.back()), 1e-9);
}

void expect_key_error(std::string_view text, const std::string& key, const std::string& words) {
    Keys k(text);
    try {
        read_record_motion(*k.reader, testing::record_samples_dir());
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where().key, key) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST(RecordMotionKeys, Errors) {
    expect_key_error("[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\nscael = 2.0\n",
                     "table_motion.horizontal.scael", "did you mean 'scale'");
    expect_key_error("[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\nscale = 2.0\ntarget_pga = 1.0\n",
                     "table_motion.horizontal.target_pga", "not both");
    expect_key_error("[table_motion.horizontal]\ntype = \"record\"\nfile = \"nothing.AT2\"\n", "table_motion.horizontal.file",
                     "no record file");
    expect_key_error("[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\nunit = \"kine\"\n",
                     "table_motion.horizontal.unit", "unknown unit");
    expect_key_error("[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\nstart = 5.0\n",
                     "table_motion.horizontal.start", "fewer than 2 samples");
    expect_key_error("[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\nbaseline = \"cubic\"\n",
                     "table_motion.horizontal.baseline", "not one of");
}

TEST(RecordMotionKeys, ErrorsInsideTheRecordNameTheRecordFile) {
    Keys k("[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\ncomponent = \"180\"\n");
    try {
        read_record_motion(*k.reader, testing::record_samples_dir());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(e.where().file.find("legacy_pea.AT2"), std::string::npos);
        EXPECT_EQ(e.where().line, 2);
    }
}

TEST(SyntheticMotionKeys, ReproducibleAtRestAndScaled) {
    const char* text = R"(
[table_motion.horizontal]
type = "synthetic"
seed = 7
duration = 10.0
target_pga = 0.3
target_pga_unit = "g"
ground_frequency = 3.0
envelope = "trapezoidal"
rise_time = 1.0
strong_duration = 4.0
pad = 2.0
)";
    Keys a(text), b(text);
    const auto s1 = read_synthetic_motion(*a.reader);
    const auto s2 = read_synthetic_motion(*b.reader);
    EXPECT_EQ(s1.acceleration_m_s2, s2.acceleration_m_s2);
    EXPECT_EQ(s1.time_s.size(), 1201u);  // 10 s of motion and 2 s of padding at 0.01 s
    const auto m = intensity_measures(s1.acceleration_m_s2, 0.01);
    EXPECT_NEAR(m.pga_m_s2, 0.3 * 9.80665, 1e-9);
    EXPECT_LT(std::abs(s1.velocity_m_s.back()), 1e-9);  // polynomial baseline by default, over the padding too
    EXPECT_LT(std::abs(s1.displacement_m.back()), 1e-9);
}

TEST(SyntheticMotionKeys, TargetPgaRequired) {
    Keys k("[table_motion.horizontal]\ntype = \"synthetic\"\nseed = 1\n");
    EXPECT_THROW(read_synthetic_motion(*k.reader), InputError);
}

}  // namespace
}  // namespace blockdem
