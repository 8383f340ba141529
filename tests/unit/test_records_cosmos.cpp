// COSMOS V2 reader: the real Anchorage file against its sidecar and its own header, and the
// project's sample (fixed-width values, several per line).
#include <cmath>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

TEST(CosmosRecord, RealFileMatchesSidecar) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto path = testing::ground_motions_dir() / "cosmos-v2" / "us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c";
    const auto j = testing::sidecar(path);
    const auto& computed = j.at("computed");
    const auto r = read_ground_motion_record(path);
    EXPECT_EQ(r.format, RecordFormat::cosmos_v2);
    EXPECT_EQ(r.npts(), j.at("npts").get<std::size_t>());
    EXPECT_DOUBLE_EQ(r.dt_s, j.at("dt_s").get<double>());
    const auto [pga, at] = testing::absolute_peak(r.acceleration_m_s2);
    EXPECT_LT(testing::relative_error(pga, computed.at("pga_m_s2").get<double>()), 1e-6);
    EXPECT_EQ(at, computed.at("pga_index").get<std::size_t>());
    // The file's own header: Max = -6.852 cm/sec2 at 76.215 sec.
    EXPECT_NEAR(static_cast<double>(at) * r.dt_s, 76.215, 1e-9);
    EXPECT_EQ(r.units_in_file, "cm/sec2");
    EXPECT_EQ(r.component, "BNZ");
    EXPECT_NE(r.event.find("Point MacKenzie"), std::string::npos);
    EXPECT_NE(r.station.find("AK-BMR"), std::string::npos);
}

TEST(CosmosRecord, Sample) {
    const auto r = read_ground_motion_record(testing::record_samples_dir() / "cosmos_sample.V2");
    EXPECT_EQ(r.format, RecordFormat::cosmos_v2);
    ASSERT_EQ(r.npts(), 12u);
    EXPECT_DOUBLE_EQ(r.dt_s, 0.01);
    for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(r.acceleration_m_s2[k], (k % 2 ? -1.0 : 1.0) * (k + 1) * 1e-3, 1e-15);
    EXPECT_EQ(r.component, "HNE (azimuth 90)");
    RecordReadOptions o;
    o.component = "HNN";
    EXPECT_THROW(read_ground_motion_record(testing::record_samples_dir() / "cosmos_sample.V2", o), InputError);
}

}  // namespace
}  // namespace blockdem
