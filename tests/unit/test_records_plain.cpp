// Plain-text, CSV and JMA-style CSV readers, and format detection from content.
#include <cmath>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using testing::ground_motions_dir;
using testing::record_samples_dir;

double peak(const GroundMotionRecord& r) {
    double p = 0.0;
    for (double a : r.acceleration_m_s2) p = std::max(p, std::abs(a));
    return p;
}

TEST(PlainRecord, NorthridgeTwoColumnsWithUnitsInHeader) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto path = ground_motions_dir() / "plain-text" / "Northridge.dat";
    const auto j = testing::sidecar(path);
    const auto r = read_ground_motion_record(path);
    EXPECT_EQ(r.format, RecordFormat::plain_text);
    EXPECT_EQ(r.npts(), j.at("npts").get<std::size_t>());
    EXPECT_NEAR(r.dt_s, j.at("dt_s").get<double>(), 1e-12);
    EXPECT_EQ(r.units_in_file, "g");
    EXPECT_LT(testing::relative_error(peak(r), j.at("computed").at("pga_m_s2").get<double>()), 1e-6);
    EXPECT_NE(r.station.find("24278"), std::string::npos);
}

TEST(PlainRecord, ElCentroValuesOnlyNeedsDtAndUnits) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto path = ground_motions_dir() / "plain-text" / "elCentro.dat";
    EXPECT_THROW(read_ground_motion_record(path), InputError);
    RecordReadOptions o;
    o.units = "g";
    EXPECT_THROW(read_ground_motion_record(path, o), InputError);  // dt still missing
    o.dt_s = 0.02;
    const auto r = read_ground_motion_record(path, o);
    const auto j = testing::sidecar(path);
    EXPECT_EQ(r.npts(), j.at("npts").get<std::size_t>());
    EXPECT_LT(testing::relative_error(peak(r), j.at("computed").at("pga_m_s2").get<double>()), 1e-6);
}

TEST(PlainRecord, JmaSyntheticMatchesSidecarPerComponent) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto path = ground_motions_dir() / "synthetic" / "SYNTHETIC-jma-style.csv";
    const auto j = testing::sidecar(path);
    for (const char* c : {"NS", "EW", "UD"}) {
        RecordReadOptions o;
        o.component = c;
        const auto r = read_ground_motion_record(path, o);
        EXPECT_EQ(r.format, RecordFormat::jma_csv);
        EXPECT_EQ(r.component, c);
        EXPECT_EQ(r.npts(), 300u);
        EXPECT_DOUBLE_EQ(r.dt_s, 0.01);
        EXPECT_LT(testing::relative_error(peak(r), j.at("computed_SI").at(c).at("pga_m_s2").get<double>()), 1e-6) << c;
    }
}

TEST(PlainRecord, SampleTwoColumnCsvWithUnitsInColumnName) {
    const auto r = read_ground_motion_record(record_samples_dir() / "two_columns.csv");
    EXPECT_EQ(r.units_in_file, "gal");
    ASSERT_EQ(r.npts(), 12u);
    EXPECT_NEAR(r.dt_s, 0.01, 1e-12);
    EXPECT_NEAR(r.acceleration_m_s2[11], -1.2 * 0.01, 1e-12);  // -1.2 gal
    EXPECT_EQ(r.station, "nowhere");
}

TEST(PlainRecord, SampleValuesOnlyWithTrailer) {
    RecordReadOptions o;
    o.units = "g";
    o.dt_s = 0.005;
    const auto r = read_ground_motion_record(record_samples_dir() / "values_only.txt", o);
    ASSERT_EQ(r.npts(), 12u);
    EXPECT_NEAR(r.acceleration_m_s2[11], -0.012 * 9.80665, 1e-12);
}

TEST(PlainRecord, SampleJmaColumns) {
    RecordReadOptions o;
    o.component = "ew";
    const auto r = read_ground_motion_record(record_samples_dir() / "jma_sample.csv", o);
    EXPECT_EQ(r.component, "EW");
    EXPECT_NEAR(r.acceleration_m_s2[0], -0.1 * 0.01, 1e-12);
    o.component = "XY";
    EXPECT_THROW(read_ground_motion_record(record_samples_dir() / "jma_sample.csv", o), InputError);
}

TEST(RecordFormatDetection, FromContentNotName) {
    const std::pair<const char*, RecordFormat> cases[] = {
        {"legacy_pea.AT2", RecordFormat::peer_at2}, {"nga_west1.AT2", RecordFormat::peer_at2},
        {"long_header.AT2", RecordFormat::peer_at2}, {"knet_sample.EW", RecordFormat::knet},
        {"kiknet_sample.EW2", RecordFormat::knet},   {"cosmos_sample.V2", RecordFormat::cosmos_v2},
        {"jma_sample.csv", RecordFormat::jma_csv},   {"two_columns.csv", RecordFormat::plain_text},
    };
    for (const auto& [file, format] : cases) {
        // Copied under a neutral name so that only the content can tell.
        std::ifstream in(record_samples_dir() / file, std::ios::binary);
        const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const auto copy = testing::write_temp_file("record.dat", content);
        EXPECT_EQ(read_ground_motion_record(copy).format, format) << file;
    }
}

TEST(RecordFormatNames, RoundTrip) {
    for (auto f : {RecordFormat::automatic, RecordFormat::peer_at2, RecordFormat::knet, RecordFormat::cosmos_v2,
                   RecordFormat::jma_csv, RecordFormat::plain_text})
        EXPECT_EQ(parse_record_format(record_format_name(f)), f);
    EXPECT_THROW(parse_record_format("seisan"), std::invalid_argument);
}

}  // namespace
}  // namespace blockdem
