// PEER AT2 reader: every real AT2 file against its sidecar, and the project's samples of each
// NPTS/DT header variant.
#include <cmath>
#include <regex>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using testing::ground_motions_dir;
using testing::record_samples_dir;

// The sidecar describes the component in words ("horizontal, azimuth 67 deg", "vertical (UP)"):
// the header's component must appear in it as a whole word.
bool sidecar_mentions(const nlohmann::json& j, const std::string& component) {
    const std::regex word("\\b" + component + "\\b");
    return !component.empty() && std::regex_search(j.at("component").get<std::string>(), word);
}

class RealAt2 : public ::testing::TestWithParam<const char*> {};

TEST_P(RealAt2, MatchesSidecar) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto path = ground_motions_dir() / "peer-at2" / GetParam();
    const auto j = testing::sidecar(path);
    const auto& computed = j.at("computed");
    const GroundMotionRecord r = read_ground_motion_record(path);
    EXPECT_EQ(r.format, RecordFormat::peer_at2);
    EXPECT_EQ(r.npts(), j.at("npts").get<std::size_t>());
    EXPECT_DOUBLE_EQ(r.dt_s, j.at("dt_s").get<double>());
    const auto [pga, at] = testing::absolute_peak(r.acceleration_m_s2);
    EXPECT_LT(testing::relative_error(pga, computed.at("pga_m_s2").get<double>()), 1e-6);
    EXPECT_EQ(at, computed.at("pga_index").get<std::size_t>());
    EXPECT_NEAR(r.acceleration_m_s2.front(), computed.at("first_value_m_s2").get<double>(), 1e-6 * pga);
    EXPECT_NEAR(r.acceleration_m_s2.back(), computed.at("last_value_m_s2").get<double>(), 1e-6 * pga);
    // Header facts: event, station and component are the comma fields of header line 2.
    const std::string line2 = j.at("parse").at("header_lines").at(1).get<std::string>();
    EXPECT_TRUE(sidecar_mentions(j, r.component)) << r.component << " in " << j.at("component");
    EXPECT_FALSE(r.station.empty());
    EXPECT_NE(line2.find(r.station), std::string::npos);
    EXPECT_EQ(line2.rfind(r.event, 0), 0u) << "event is the start of line 2";
    EXPECT_EQ(r.units_in_file, "G");
    EXPECT_DOUBLE_EQ(r.to_m_s2, 9.80665);
}

INSTANTIATE_TEST_SUITE_P(Files, RealAt2,
                         ::testing::Values("IELC180.AT2", "RSN6_IMPVALL.I_I-ELC180.AT2", "ARL360.at2", "Rinaldi228.AT2",
                                           "Rinaldi318.AT2", "RinaldiUP.AT2", "RSN763_LOMAP_GIL067.AT2",
                                           "RSN763_LOMAP_GIL337.AT2", "NIS090.AT2"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

TEST(RealAt2Header, ElCentroFacts) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto r = read_ground_motion_record(ground_motions_dir() / "peer-at2" / "IELC180.AT2");
    EXPECT_EQ(r.event, "IMPERIAL VALLEY 5/19/40 0439");
    EXPECT_EQ(r.station, "EL CENTRO ARRAY #9");
    EXPECT_EQ(r.component, "180");
    const auto w2 = read_ground_motion_record(ground_motions_dir() / "peer-at2" / "RSN6_IMPVALL.I_I-ELC180.AT2");
    EXPECT_EQ(w2.event, "Imperial Valley-02, 5/19/1940");
    EXPECT_EQ(w2.station, "El Centro Array #9");
}

// Samples: a_k = (-1)^k (k + 1) / 1000 g, k = 0..11.
struct Variant {
    const char* file;
    double dt_s;
    const char* component;
    const char* station;
};

class At2Variant : public ::testing::TestWithParam<Variant> {};

TEST_P(At2Variant, ReadsValuesAndHeader) {
    const Variant v = GetParam();
    const auto r = read_ground_motion_record(record_samples_dir() / v.file);
    EXPECT_EQ(r.format, RecordFormat::peer_at2);
    ASSERT_EQ(r.npts(), 12u);
    EXPECT_DOUBLE_EQ(r.dt_s, v.dt_s);
    for (std::size_t k = 0; k < 12; ++k)
        EXPECT_NEAR(r.acceleration_m_s2[k], (k % 2 ? -1.0 : 1.0) * (k + 1) * 1e-3 * 9.80665, 1e-12) << k;
    EXPECT_EQ(r.component, v.component);
    EXPECT_EQ(r.station, v.station);
}

INSTANTIATE_TEST_SUITE_P(Samples, At2Variant,
                         ::testing::Values(Variant{"legacy_pea.AT2", 0.01, "090", "SAMPLE ARRAY #1"},
                                           Variant{"nga_west2.AT2", 0.005, "45", "Sample Station - Hill Top"},
                                           Variant{"nga_west1.AT2", 0.02, "000", "SAMPLE-STATION"},
                                           Variant{"nga_filter.AT2", 0.01, "UP", "Pump Station"},
                                           Variant{"lowercase_dt.AT2", 0.00244, "270", "SAMPLE STATION"},
                                           Variant{"crcrlf.at2", 0.02, "360", "SAMPLE PARK"},
                                           Variant{"long_header.AT2", 0.01, "", ""}));

TEST(At2Component, AskedComponentMustMatchHeader) {
    RecordReadOptions o;
    o.component = "90";  // "090" in the file: numbers compare as numbers
    EXPECT_NO_THROW(read_ground_motion_record(record_samples_dir() / "legacy_pea.AT2", o));
    o.component = "180";
    try {
        read_ground_motion_record(record_samples_dir() / "legacy_pea.AT2", o);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where().line, 2);
        EXPECT_NE(std::string(e.what()).find("090"), std::string::npos);
    }
}

TEST(At2Units, OverrideReplacesFileUnits) {
    RecordReadOptions o;
    o.units = "gal";
    const auto r = read_ground_motion_record(record_samples_dir() / "legacy_pea.AT2", o);
    EXPECT_NEAR(r.acceleration_m_s2[11], -0.012 * 0.01, 1e-15);
}

}  // namespace
}  // namespace blockdem
