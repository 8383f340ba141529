// Intensity measures of every real record against the numbers in its sidecar (computed there
// with numpy by the conventions of the data set's README).
#include <gtest/gtest.h>

#include "motion/intensity_measures.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

struct Case {
    const char* file;       // under ground-motions/
    const char* component;  // for multi-component files
    double dt_s;            // for values-only files
};

class RealRecordMeasures : public ::testing::TestWithParam<Case> {};

TEST_P(RealRecordMeasures, MatchSidecar) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const Case c = GetParam();
    const auto path = testing::ground_motions_dir() / c.file;
    RecordReadOptions o;
    o.component = c.component;
    o.dt_s = c.dt_s;
    if (c.dt_s > 0.0) o.units = "g";
    const auto r = read_ground_motion_record(path, o);
    const auto j = testing::sidecar(path);
    const auto& s = j.contains("computed") ? j.at("computed")
                    : j.contains("computed_SI") ? j.at("computed_SI").at(c.component)
                                                : j.at("computed_after_mean_removal_SI");
    const IntensityMeasures m = intensity_measures(r.acceleration_m_s2, r.dt_s);
    EXPECT_LT(testing::relative_error(m.pga_m_s2, s.at("pga_m_s2").get<double>()), 1e-6);
    EXPECT_NEAR(m.pga_time_s, s.at("t_pga_s").get<double>(), 1e-9);
    EXPECT_NEAR(m.pga_signed_m_s2, s.at("pga_signed_m_s2").get<double>(), 1e-6 * m.pga_m_s2);
    EXPECT_LT(testing::relative_error(m.pgv_m_s, s.at("pgv_m_s").get<double>()), 1e-4);
    EXPECT_LT(testing::relative_error(m.arias_m_s, s.at("arias_m_s").get<double>()), 1e-4);
    EXPECT_NEAR(m.d5_95_s, s.at("d5_95_s").get<double>(), r.dt_s * 1.001);
    EXPECT_NEAR(m.d5_75_s, s.at("d5_75_s").get<double>(), r.dt_s * 1.001);
    EXPECT_NEAR(m.final_velocity_m_s, s.at("v_end_m_s").get<double>(), 1e-4 * m.pgv_m_s);
    // The sidecar integrates v by the trapezoid rule; the table integrates the piecewise-linear
    // acceleration exactly. The two displacements differ by O(dt^2) per step: 1 % of PGD.
    EXPECT_LT(testing::relative_error(m.pgd_m, s.at("pgd_m").get<double>()), 1e-2);
    EXPECT_NEAR(m.bracketed_duration_s, s.at("bracketed_0p05g_s").get<double>(), r.dt_s * 1.001);
}

INSTANTIATE_TEST_SUITE_P(
    Files, RealRecordMeasures,
    ::testing::Values(Case{"peer-at2/IELC180.AT2", "", 0}, Case{"peer-at2/RSN6_IMPVALL.I_I-ELC180.AT2", "", 0},
                      Case{"peer-at2/ARL360.at2", "", 0}, Case{"peer-at2/Rinaldi228.AT2", "", 0},
                      Case{"peer-at2/Rinaldi318.AT2", "", 0}, Case{"peer-at2/RinaldiUP.AT2", "", 0},
                      Case{"peer-at2/RSN763_LOMAP_GIL067.AT2", "", 0}, Case{"peer-at2/RSN763_LOMAP_GIL337.AT2", "", 0},
                      Case{"peer-at2/NIS090.AT2", "", 0}, Case{"plain-text/Northridge.dat", "", 0},
                      Case{"plain-text/elCentro.dat", "", 0.02},
                      Case{"cosmos-v2/us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c", "", 0},
                      Case{"synthetic/SYNTHETIC-knet-SYN0010001010000.NS", "", 0},
                      Case{"synthetic/SYNTHETIC-jma-style.csv", "NS", 0}, Case{"synthetic/SYNTHETIC-jma-style.csv", "EW", 0},
                      Case{"synthetic/SYNTHETIC-jma-style.csv", "UD", 0}));

TEST(IntensityMeasures, ConstantAccelerationClosedForm) {
    const std::vector<double> a(101, 2.0);  // 2 m/s^2 for 1 s
    const auto m = intensity_measures(a, 0.01);
    EXPECT_NEAR(m.final_velocity_m_s, 2.0, 1e-12);
    EXPECT_NEAR(m.final_displacement_m, 1.0, 1e-12);  // a t^2 / 2, exact for linear a
    EXPECT_NEAR(m.arias_m_s, 3.141592653589793 / (2 * 9.80665) * 4.0, 1e-12);
    EXPECT_NEAR(m.d5_95_s, 0.9, 0.0101);  // within one sample (no interpolation)
}

}  // namespace
}  // namespace blockdem
