// The paper's Fig. 5 sliding case through a 3-D scenario file and `blockdem run`'s path
// (run/run_scenario.hpp dispatching on dimension = 3): a 1 kg box on a driven table, mu = 0.3,
// shaken 3.5 cos(2 pi t) m/s^2 along x, against Newmark's rigid-plastic sliding
// (analysis/rigid_plastic_sliding.hpp), read back from history.csv and summary.json. The C++
// counterpart is tests/validation/test_world_3d.cpp (SlidingOnADrivenBoxMatchesNewmark).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/rigid_plastic_sliding.hpp"
#include "run/run_scenario.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

// history.csv as a header and rows of numbers.
struct Csv {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    std::size_t column(const std::string& name) const {
        for (std::size_t k = 0; k < header.size(); ++k)
            if (header[k] == name) return k;
        ADD_FAILURE() << "no column " << name;
        return 0;
    }
};

Csv read_csv(const fs::path& file) {
    Csv csv;
    std::ifstream in(file);
    std::string line, cell;
    std::getline(in, line);
    for (std::stringstream head(line); std::getline(head, cell, ',');) csv.header.push_back(cell);
    while (std::getline(in, line)) {
        std::vector<double> row;
        for (std::stringstream values(line); std::getline(values, cell, ',');) row.push_back(std::stod(cell));
        csv.rows.push_back(row);
    }
    return csv;
}

TEST(Scenario3dSliding, BoxOnAShakenTableFollowsNewmarkThroughTheFilePath) {
    const fs::path dir = fs::temp_directory_path() / "blockdem-scenario3d-sliding";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // The box 0.5 x 0.2 x 0.2 m of 1 kg (density 50 kg/m^3), four points of kn = ks = 1e4 N/m,
    // e = 0.4 (paper), h_s = 1, dt = 1e-4 s: test_world_3d.cpp's setting.
    std::ofstream(dir / "sliding.toml") << R"(dimension = 3
[simulation]
duration = 5.0
dt = 1e-4
output_interval = 0.01
[contact]
kn = 1e4
ks = 1e4
mu = 0.3
e = 0.4
h_s = 1.0
[[bodies]]
name = "table"
kind = "driven"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "box"
shape = "box"
size = [0.5, 0.2, 0.2]
position = [0.0, 0.0, 0.1]
density = 50.0
[table_motion.x]
type = "sine"
amplitude = 3.5
period = 1.0
phase_deg = 90
[output]
vtk = false
)";
    RunRequest request;
    request.scenario = dir / "sliding.toml";
    request.out_dir = dir / "out";
    const nlohmann::json summary = run_scenario(request);
    ASSERT_EQ(summary["status"], "completed");

    const double g = 9.81;
    const auto reference = rigid_plastic_sliding(SineMotion{3.5, 1.0, std::numbers::pi / 2.0, 0.0, 0.0}, 0.3, g, 5.0, 1e-5);
    // Tolerance as in 2-D and in test_world_3d.cpp: 2% of the slip plus the elastic shear
    // u_e = mu m g / (2 x 2e4) (four points of 1e4 N/m: the springs' lag).
    const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
    const Csv history = read_csv(dir / "out/history.csv");
    const std::size_t box_x = history.column("box.x_m"), table_x = history.column("table.x_m");
    const std::size_t box_y = history.column("box.y_m"), tilt = history.column("box.tilt_rad");
    ASSERT_EQ(history.rows.size(), 501u);
    // At whole cycles, where the block sticks between its slides (the paper's per-cycle slip):
    // mid-slide the springs' lag in time adds a slip rate times that lag, which u_e does not bound.
    for (double cycles : {1.0, 2.0, 3.0, 4.0, 5.0}) {
        const auto& row = history.rows[static_cast<std::size_t>(std::llround(cycles / 0.01))];
        ASSERT_NEAR(row[0], cycles, 1e-9);
        // The table's centroid starts at x = 0, the box's too: the slip is their difference.
        const double slip = row[box_x] - row[table_x];
        const double ref = reference[static_cast<std::size_t>(std::llround(cycles / 1e-5))].relative_displacement_m;
        EXPECT_NEAR(slip, ref, 0.02 * std::abs(ref) + u_e) << "after " << cycles << " cycles";
        // Along x only: no sideways walk nor a tilt to speak of.
        EXPECT_LT(std::abs(row[box_y]), 1e-9);
        EXPECT_LT(row[tilt], 1e-3);
        std::printf("Fig. 5 sliding through the scenario file, after %.1f cycle(s): slip %.4f mm, Newmark %.4f mm "
                    "(%.2f%%)\n",
                    cycles, 1e3 * slip, 1e3 * ref, 100.0 * (slip - ref) / ref);
    }
    // summary.json's slip vector is the last row's.
    const auto& last = history.rows.back();
    EXPECT_NEAR(summary["bodies"][1]["slip_m"][0].get<double>(), last[box_x] - last[table_x], 1e-9);
    EXPECT_FALSE(summary["bodies"][1]["overturned"].get<bool>());
    // The C++ run closes to 1.9e-7; the same bound.
    EXPECT_LT(summary["energy_j"]["balance_error_relative"].get<double>(), 1e-5);
    std::printf("Fig. 5 sliding through the scenario file: energy balance error %.2e\n",
                summary["energy_j"]["balance_error_relative"].get<double>());
    fs::remove_all(dir);
}

}  // namespace
}  // namespace blockdem
