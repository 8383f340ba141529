#pragma once
// Helpers for tests that load scenarios written as text: write one to the temporary folder,
// load it, and read the error it gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "io/scenario.hpp"

namespace blockdem::testing {

/// Writes text to <temp>/blockdem-<prefix>-<name>.toml (a prefix per test file, so that test
/// files run in parallel never share a file).
inline std::filesystem::path write_scenario(const std::string& prefix, const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("blockdem-" + prefix + "-" + name + ".toml");
    std::ofstream(path) << text;
    return path;
}

/// The InputError message of loading the scenario text with overrides ("" if it loads).
inline std::string scenario_error(const std::string& prefix, const std::string& name, const std::string& text,
                                  const std::vector<std::string>& overrides = {}) {
    try {
        load_scenario(write_scenario(prefix, name, text), overrides);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// text with the first `from` replaced by `to` (a test failure when `from` is absent).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

inline void expect_contains(const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nexpected to contain: " << part;
}

}  // namespace blockdem::testing
