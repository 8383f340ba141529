#pragma once
// Shared by the record tests: where the real records and the project's own samples are, the
// sidecar JSON of a real record, and temporary files for malformed inputs.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace blockdem::testing {

/// The real records (not shipped): ../shared/data/ground-motions next to the repository.
inline std::filesystem::path ground_motions_dir() {
    return std::filesystem::path(BLOCKDEM_SOURCE_DIR) / ".." / "shared" / "data" / "ground-motions";
}

/// The small samples the project writes itself.
inline std::filesystem::path record_samples_dir() { return std::filesystem::path(BLOCKDEM_SOURCE_DIR) / "tests" / "data" / "records"; }

inline nlohmann::json sidecar(const std::filesystem::path& record) {
    std::ifstream in(record.string() + ".json");
    return nlohmann::json::parse(in);
}

/// A file with exactly this content in a fresh temporary folder.
inline std::filesystem::path write_temp_file(const std::string& name, const std::string& content) {
    const auto dir = std::filesystem::temp_directory_path() / "blockdem_record_tests";
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

inline double relative_error(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

/// The largest |a| of a record and its first index, found here rather than with the library's
/// intensity measures, so that a reader test does not lean on the code it is compared with.
struct AbsolutePeak {
    double value = 0.0;
    std::size_t index = 0;
};
inline AbsolutePeak absolute_peak(const std::vector<double>& values) {
    AbsolutePeak peak;
    for (std::size_t k = 0; k < values.size(); ++k)
        if (std::abs(values[k]) > peak.value) peak = {std::abs(values[k]), k};
    return peak;
}

}  // namespace blockdem::testing

/// Skips the test when the real records are not next to the repository.
#define BLOCKDEM_REQUIRE_GROUND_MOTIONS()                                                          \
    if (!std::filesystem::is_directory(blockdem::testing::ground_motions_dir()))                   \
    GTEST_SKIP() << "no " << blockdem::testing::ground_motions_dir() << " (real records are not shipped)"
