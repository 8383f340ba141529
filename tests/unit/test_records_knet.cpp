// K-NET / KiK-net reader: the data set's synthetic K-NET file against its sidecar, and the
// project's K-NET and KiK-net samples (scale factor, mean removal, channel numbers).
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using testing::record_samples_dir;

TEST(KnetRecord, SyntheticSampleMatchesSidecar) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto path = testing::ground_motions_dir() / "synthetic" / "SYNTHETIC-knet-SYN0010001010000.NS";
    const auto j = testing::sidecar(path);
    const auto& expected = j.at("computed_after_mean_removal_SI");
    const auto r = read_ground_motion_record(path);
    EXPECT_EQ(r.format, RecordFormat::knet);
    EXPECT_EQ(r.npts(), j.at("expected").at("npts").get<std::size_t>());
    EXPECT_DOUBLE_EQ(r.dt_s, j.at("expected").at("dt_s").get<double>());
    double pga = 0.0;
    for (double a : r.acceleration_m_s2) pga = std::max(pga, std::abs(a));
    EXPECT_LT(testing::relative_error(pga, expected.at("pga_m_s2").get<double>()), 1e-6);
    EXPECT_NEAR(r.acceleration_m_s2.front(), expected.at("first_value_m_s2").get<double>(), 1e-7);
    // NIED's header "Max. Acc." is max |S (c - mean c)| to 3 decimals (gal).
    EXPECT_NEAR(pga * 100.0, j.at("expected").at("header_max_acc_gal").get<double>(), 5e-4);
    EXPECT_EQ(r.station, "SYN001");
    EXPECT_EQ(r.component, "N-S");
}

// counts = offset + a / S with a = 100 (-1)^k (k + 1) / 1000 gal; after mean removal the values
// are a - mean(a) up to the rounding of the counts (S / 2).
void expect_sample_values(const GroundMotionRecord& r, double gal_per_count) {
    ASSERT_EQ(r.npts(), 12u);
    std::vector<double> a(12);
    for (std::size_t k = 0; k < 12; ++k) a[k] = (k % 2 ? -1.0 : 1.0) * (k + 1) * 0.1;  // [gal]
    const double mean = std::accumulate(a.begin(), a.end(), 0.0) / 12.0;
    for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(r.acceleration_m_s2[k], (a[k] - mean) * 0.01, gal_per_count * 0.01) << k;
}

TEST(KnetRecord, SampleScaleFactorAndMeanRemoval) {
    const auto r = read_ground_motion_record(record_samples_dir() / "knet_sample.EW");
    EXPECT_EQ(r.format, RecordFormat::knet);
    EXPECT_DOUBLE_EQ(r.dt_s, 1.0 / 12.0);
    EXPECT_EQ(r.component, "E-W");
    EXPECT_EQ(r.station, "TST001");
    EXPECT_NE(r.event.find("2003/01/02 04:05:00"), std::string::npos);
    expect_sample_values(r, 3920.0 / 6182761.0);
}

TEST(KnetRecord, KiknetChannelNumber) {
    const auto r = read_ground_motion_record(record_samples_dir() / "kiknet_sample.EW2");
    EXPECT_EQ(r.component, "5 (E-W surface)");
    expect_sample_values(r, 7845.0 / 8223790.0);
    RecordReadOptions o;
    o.component = "4";
    EXPECT_THROW(read_ground_motion_record(record_samples_dir() / "kiknet_sample.EW2", o), InputError);
}

}  // namespace
}  // namespace blockdem
