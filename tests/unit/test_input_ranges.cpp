// Scenario keys and command-line values out of range (issue 11, section 2): a value that would
// wrap in a cast (start = 1e19, courses = 1e20, seed = -1), allocate without end (pad = 1e300, a
// wall 1e9 m long), read out of bounds (column = "-1") or loop forever (a spectrum period of
// 1e-200 s) is an InputError naming the scenario, the key and the range or the figures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "motion/linear_oscillator.hpp"
#include "motion/record_processing.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/synthetic_motion.hpp"
#include "records_test_support.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem {
namespace {

const std::string base = R"(
[simulation]
duration = 0.01
dt = 1.0e-4

[contact]
kn = 1.0e7
ks = 1.0e7
mu = 0.6
e = 0.4

[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]
density = 2400.0
)";

std::filesystem::path folder() {
    const auto dir = std::filesystem::temp_directory_path() / "blockdem_input_ranges";
    std::filesystem::create_directories(dir);
    return dir;
}

// The InputError of a scenario made of base + extra, written next to the test's data files.
InputError error_of(const std::string& name, const std::string& extra) {
    const auto path = folder() / (name + ".toml");
    std::ofstream(path) << base << extra;
    try {
        load_scenario(path, {});
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << name << ": loads without an error";
    return InputError({}, "");
}

void expect_error(const std::string& name, const std::string& extra, const std::string& key, const std::string& words) {
    const InputError e = error_of(name, extra);
    EXPECT_EQ(e.where().key, key) << e.what();
    EXPECT_NE(e.where().file.find(name + ".toml"), std::string::npos) << e.what();
    EXPECT_GT(e.where().line, 0) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
}

void copy_sample(const std::string& name) {
    std::filesystem::copy_file(testing::record_samples_dir() / name, folder() / name,
                               std::filesystem::copy_options::overwrite_existing);
}

TEST(InputRanges, CsvColumnThatIsNotAnIndexNorAName) {
    copy_sample("two_columns.csv");
    const std::string csv = "[table_motion.horizontal]\ntype = \"csv\"\nfile = \"two_columns.csv\"\nunit = \"g\"\n";
    // "-1" read out of bounds (exit 139); "1e30" silently read the time column.
    expect_error("csv_minus_one", csv + "column = \"-1\"\n", "table_motion.horizontal.column",
                 "\"-1\" is neither a column name of");
    expect_error("csv_1e30", csv + "column = \"1e30\"\n", "table_motion.horizontal.column",
                 "\"1e30\" is neither a column name of");
    expect_error("csv_float", csv + "column = 1e30\n", "table_motion.horizontal.column", "must be a whole number from 0 to 9999");
    expect_error("csv_digits", csv + "column = \"99999999999999999999999\"\n", "table_motion.horizontal.column",
                 "is beyond the 10000 columns a CSV file may have");
    // An index the file does not have names the key, the file and the line.
    const InputError e = error_of("csv_missing", csv + "column = \"7\"\n");
    EXPECT_NE(std::string(e.what()).find("two_columns.csv:3: column = 7 asks for column 7 (0-based) but this line has 2 columns"),
              std::string::npos)
        << e.what();
}

TEST(InputRanges, RecordWindowAndPaddingAreCheckedBeforeAnyCast) {
    copy_sample("legacy_pea.AT2");
    const std::string record = "[table_motion.horizontal]\ntype = \"record\"\nfile = \"legacy_pea.AT2\"\n";
    // start = 1e19 s wrapped to sample 0 and ran the whole record.
    expect_error("start_1e19", record + "start = 1e19\n", "table_motion.horizontal.start",
                 "the window 1e+19 s + 0 s leaves fewer than 2 samples of a 0.11 s record");
    expect_error("pad_1e300", record + "pad = 1e300\n", "table_motion.horizontal.pad",
                 "1e+300 s of padding at dt = 0.01 s adds 1e+302 samples to 12; a motion may have at most 20000000 samples");
    expect_error("record_dt", record + "dt = 1e-200\n", "table_motion.horizontal.dt",
                 "the sample interval 1e-200 s is outside the accepted 1e-05 s to 1 s");
    expect_error("delay_1e19", record + "delay = 1e19\n", "table_motion.horizontal.delay",
                 "a delay of 1e+19 s is more than 1e+12 samples of 0.01 s");
    expect_error("baseline_order", record + "baseline = \"polynomial\"\nbaseline_order = 1e20\n",
                 "table_motion.horizontal.baseline_order", "must be a whole number from 2 to 6, got 1e+20");
}

// A record finite in its file that `scale` takes beyond the range of a number named neither the
// file nor the key ("sample 1 is not finite").
TEST(InputRanges, RecordScaledBeyondTheRangeOfANumberNamesTheKey) {
    std::ofstream(folder() / "big_record.csv") << "time,acc[m/s^2]\n0.00,0.0\n0.01,1e300\n0.02,0.0\n";
    expect_error("record_scale", "[table_motion.horizontal]\ntype = \"record\"\nfile = \"big_record.csv\"\nscale = 1e10\n",
                 "table_motion.horizontal.scale", "big_record.csv: sample 1 is not finite");
}

TEST(InputRanges, SyntheticMotionRefusesCountsAndFrequenciesOutOfRange) {
    const std::string synthetic = "[table_motion.horizontal]\ntype = \"synthetic\"\ntarget_pga = 1.0\n";
    expect_error("synthetic_duration", synthetic + "duration = 1e300\n", "table_motion.horizontal.duration",
                 "duration 1e+300 s at dt = 0.01 s is 1e+302 samples; a motion may have at most 20000000");
    // 1e200 Hz made the oscillator's matrix infinite: its exponential never ended.
    expect_error("synthetic_frequency", synthetic + "ground_frequency = 1e200\n", "table_motion.horizontal.ground_frequency",
                 "1e+200 Hz must be below the Nyquist frequency 1 / (2 dt) = 50 Hz");
    expect_error("synthetic_pad", synthetic + "pad = 1e300\n", "table_motion.horizontal.pad", "a motion may have at most 20000000");
    expect_error("synthetic_seed", synthetic + "seed = -1\n", "table_motion.horizontal.seed",
                 "must be a whole number from 0 to 2000000000, got -1");
}

const std::string wall = "[[assemblies]]\ntype = \"wall\"\nname = \"b\"\ndensity = 2000.0\n";

TEST(InputRanges, AssemblyWholeNumbersAreRangeChecked) {
    expect_error("courses_1e20", wall + "length = 2.0\ncourses = 1e20\n", "assemblies.b.courses",
                 "must be a whole number from 1 to 100000000, got 1e+20");
    expect_error("courses_fraction", wall + "length = 2.0\ncourses = 2.5\n", "assemblies.b.courses", "got 2.5");
    expect_error("column_count", "[[assemblies]]\ntype = \"column\"\nname = \"c\"\ndensity = 2000.0\ncount = -3\nwidth = 1\nheight = 1\n",
                 "assemblies.c.count", "must be a whole number from 1 to 100000000, got -3");
    const std::string voronoi = "[[assemblies]]\ntype = \"voronoi\"\nname = \"v\"\ndensity = 2000.0\n"
                                "region = [[0, 0], [1, 0], [1, 1], [0, 1]]\ncell_size = 0.2\n";
    expect_error("seed_minus_one", voronoi + "seed = -1\n", "assemblies.v.seed", "must be a whole number from 0 to 9007199254740992, got -1");
}

TEST(InputRanges, SteppedWallTooShortForItsOddCoursesIsRefused) {
    // A wall one brick long with stepped ends had empty odd courses: the courses above floated.
    expect_error("stepped_one_brick", wall + "length = 0.2\ncourses = 3\nstepped_ends = true\n", "assemblies.b.stepped_ends",
                 "is true with a length of 0.2 m, not more than brick_length 0.2 m: the odd courses, half a brick shorter at "
                 "each end, would hold no brick and the courses above would float");
    expect_error("stepped_sliver", wall + "length = 0.21\ncourses = 2\nstepped_ends = true\n", "assemblies.b.stepped_ends",
                 "would be one piece 0.01 m long, less than min_piece_fraction x brick_length = 0.05 m; give a length of at least 0.25 m");
    // Flat ends put two half bricks on a brick; one course has no odd course (bodies: the table and the bricks).
    const auto bodies = [](const std::string& name, const std::string& extra) {
        const auto path = folder() / (name + ".toml");
        std::ofstream(path) << base << wall << extra;
        return load_scenario(path, {}).model.bodies.size();
    };
    EXPECT_EQ(bodies("flat_one_brick", "length = 0.2\ncourses = 3\n"), 1u + 1 + 2 + 1);
    EXPECT_EQ(bodies("stepped_one_course", "length = 0.2\ncourses = 1\nstepped_ends = true\n"), 1u + 1);
    EXPECT_EQ(bodies("stepped_long_enough", "length = 0.3\ncourses = 3\nstepped_ends = true\n"), 1u + 2 + 1 + 2);
}

TEST(InputRanges, AssemblyTooLargeForTheMachineIsRefusedBeforeGenerating) {
    // A wall 1e9 m long tried to allocate 16.8 GB.
    expect_error("wall_1e9", wall + "length = 1e9\ncourses = 2\n", "assemblies.b.length",
                 "the assembly would have about 1e+10 blocks (2 courses x 5e+09 a course, from length / brick_length = 1e+09 m / 0.2 m), "
                 "needing about 20.0 TB at 2.0 kB a block; the limit is");
    expect_error("voronoi_fine", "[[assemblies]]\ntype = \"voronoi\"\nname = \"v\"\ndensity = 2000.0\n"
                                 "region = [[0, 0], [1, 0], [1, 1], [0, 1]]\ncell_size = 1e-6\n",
                 "assemblies.v.cell_size", "the assembly would have about 1e+12 blocks");
    expect_error("rock_fine", "[[assemblies]]\ntype = \"rock_mass\"\nname = \"r\"\ndensity = 2600.0\n"
                              "region = [[0, 0], [10, 0], [10, 10], [0, 10]]\n"
                              "[[assemblies.joint_sets]]\ndip_deg = 0\nspacing = 1e-5\n"
                              "[[assemblies.joint_sets]]\ndip_deg = 90\nspacing = 1e-5\n",
                 "assemblies.r.joint_sets", "blocks (2 joint sets across the region at their spacings)");
}

TEST(InputRanges, BlockEstimatesBoundWhatTheGeneratorsMake) {
    scenes::WallSpec w;
    w.length_m = 2.0;
    w.courses = 14;
    w.openings.push_back({0.3, 0.5, 0.4, 0.4, 0.1});
    EXPECT_GE(scenes::estimated_block_count(w), static_cast<double>(scenes::masonry_wall(w).size()));
    scenes::RockMassSpec r;
    r.region_m = scenes::slope_region(2.0, 8.0, 60.0, 3.0, 4.0);
    r.joint_sets = {{-20.0, 0.5, 0.2, 2.0, {}}, {80.0, 0.7, 0.2, 2.0, {}}};
    const double rock_estimate = scenes::estimated_block_count(r);
    const auto rock = scenes::jointed_rock_mass(r);
    EXPECT_GE(rock_estimate, static_cast<double>(rock.polygons.size() + rock.dropped));
    EXPECT_LT(rock_estimate, 20.0 * static_cast<double>(rock.polygons.size())) << "an estimate, not a wild bound";
    scenes::VoronoiSpec v;
    v.region_m = {{0, 0}, {3, 0}, {3, 2}, {0, 2}};
    v.cell_size_m = 0.1;
    EXPECT_GE(scenes::estimated_block_count(v), static_cast<double>(scenes::voronoi_packing(v).polygons.size()));
}

TEST(InputRanges, SpectrumPeriodsOutsideThePhysicalRangeAreRefused) {
    const std::vector<double> a{0.0, 1.0, -1.0, 0.5, 0.0};
    for (double period : {1e-200, -1.0, 1e-4, 1e3, 1e300}) {
        SpectrumOptions o;
        o.periods_s = {0.1, period};
        try {
            response_spectrum(a, 0.01, o);
            ADD_FAILURE() << period << " s accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("is outside 0.001 s to 100 s (0 gives the PGA)"), std::string::npos) << e.what();
        }
    }
    SpectrumOptions ends;
    ends.periods_s = {0.0, min_spectrum_period_s, max_spectrum_period_s};
    EXPECT_EQ(response_spectrum(a, 0.01, ends).size(), 3u);
}

TEST(InputRanges, OscillatorStepOfAnOverflowingSystemIsRefusedNotLoopedOn) {
    // omega = 2 pi / 1e-200 s: omega^2 h overflows; the scaling loop halved infinity for ever.
    EXPECT_THROW(OscillatorStep(6.28e200, 0.05, 1e-3), std::invalid_argument);
    // Finite but huge: more than 64 halvings would be needed.
    EXPECT_THROW(OscillatorStep(1e12, 0.05, 1.0), std::invalid_argument);
    EXPECT_NO_THROW(OscillatorStep(2.0 * 3.141592653589793 / 0.01, 0.05, 1e-4));
}

TEST(InputRanges, ProcessingFunctionsDoNotCastHugeValues) {
    const std::vector<double> a{0.0, 1.0, -1.0, 0.5, 0.0};
    EXPECT_THROW(time_window(a, 0.01, 1e19, 0.0), std::invalid_argument);
    EXPECT_EQ(time_window(a, 0.01, 0.0, 1e300).size(), a.size());
    std::vector<double> tapered(a);
    apply_cosine_taper(tapered, 0.01, 1e300);  // the whole half of the record, no cast of 1e302
    EXPECT_EQ(tapered.size(), a.size());
    std::vector<double> padded(a);
    EXPECT_THROW(pad_with_zeros(padded, 0.01, 1e300), std::invalid_argument);
    pad_with_zeros(padded, 0.01, 0.02);
    EXPECT_EQ(padded.size(), a.size() + 2);
}

}  // namespace
}  // namespace blockdem
