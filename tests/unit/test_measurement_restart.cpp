// What a restart needs of the measurements (io/measurement_state_parts.hpp): a Butterworth
// channel restored from its saved state goes on bit for bit as the one that never stopped, a
// state of another filter is refused, and a CSV with comment lines is cut back after its header
// (io/run_restart.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/input_error.hpp"
#include "io/run_restart.hpp"
#include "signal/butterworth.hpp"

namespace blockdem {
namespace {

double sample(int k) { return std::sin(0.01 * k) + 0.3 * std::sin(1.7 * k) + 2.0; }

TEST(MeasurementRestart, ARestoredFilterGoesOnBitForBit) {
    const ButterworthDesign d = design_butterworth_lowpass(40.0, 3, 10000.0);
    ButterworthChannel straight(d), first_half(d);
    for (int k = 0; k < 500; ++k) EXPECT_EQ(straight.filter(sample(k)), first_half.filter(sample(k)));
    ButterworthChannel resumed(d);
    resumed.restore(first_half.state(), first_half.started());
    for (int k = 500; k < 1000; ++k) ASSERT_EQ(straight.filter(sample(k)), resumed.filter(sample(k))) << "sample " << k;
    // Without the state, the resumed filter starts from the steady state of its first sample.
    ButterworthChannel afresh(d);
    ButterworthChannel straight2(d);
    for (int k = 0; k < 500; ++k) straight2.filter(sample(k));
    EXPECT_NE(straight2.filter(sample(500)), afresh.filter(sample(500)));
}

TEST(MeasurementRestart, AStateOfAnotherOrderIsRefused) {
    ButterworthChannel order2(design_butterworth_lowpass(40.0, 2, 10000.0));
    const ButterworthChannel order4(design_butterworth_lowpass(40.0, 4, 10000.0));
    EXPECT_THROW(order2.restore(order4.state(), true), std::invalid_argument);
}

TEST(MeasurementRestart, CommentLinesAndHeaderAreKeptBeforeTheRows) {
    const auto dir = std::filesystem::temp_directory_path() / "blockdem_measurement_restart";
    std::filesystem::create_directories(dir);
    const auto from = dir / "interfaces.csv", to = dir / "copy.csv";
    std::ofstream(from) << "# one\n# two\nt,a\n0,x\n0,y\n0.5,x\n1,x\n";
    keep_rows_after_comments(from, to, 3);
    std::ostringstream text;
    text << std::ifstream(to).rdbuf();
    EXPECT_EQ(text.str(), "# one\n# two\nt,a\n0,x\n0,y\n0.5,x\n");
    keep_rows_after_comments(from, from, 0);   // in place
    std::ostringstream cut;
    cut << std::ifstream(from).rdbuf();
    EXPECT_EQ(cut.str(), "# one\n# two\nt,a\n");
    EXPECT_THROW(keep_rows_after_comments(from, to, 1), InputError);   // fewer rows than the state counts
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace blockdem
