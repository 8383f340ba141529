#pragma once
// Checks of the subcommands' number options. CLI11's PositiveNumber and NonNegativeNumber let nan
// and inf through (every comparison with nan is false) and, refusing 0, printed their range as a
// 300-digit number; these refuse what is not a finite number and say what is expected.
#include <cmath>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "run/run_request.hpp"

namespace blockdem::cli {

namespace detail {
// The option's text as a finite number, or nan (an empty or partly numeric text is not one).
inline double finite_number(const std::string& text) {
    std::size_t used = 0;
    double value = NAN;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        return NAN;
    }
    return used == text.size() && std::isfinite(value) ? value : NAN;
}
}  // namespace detail

/// A finite number above 0.
inline CLI::Validator finite_positive() {
    return CLI::Validator(
        [](std::string& text) {
            const double v = detail::finite_number(text);
            return v > 0.0 ? std::string() : fmt::format("'{}' is not a finite number above 0", text);
        },
        "NUMBER > 0");
}

/// A finite number at least 0.
inline CLI::Validator finite_non_negative() {
    return CLI::Validator(
        [](std::string& text) {
            const double v = detail::finite_number(text);
            return v >= 0.0 ? std::string() : fmt::format("'{}' is not a finite number of at least 0", text);
        },
        "NUMBER >= 0");
}

/// A finite number from lo to hi.
inline CLI::Validator finite_in(double lo, double hi) {
    return CLI::Validator(
        [=](std::string& text) {
            const double v = detail::finite_number(text);
            return v >= lo && v <= hi ? std::string() : fmt::format("'{}' is not a finite number from {:g} to {:g}", text, lo, hi);
        },
        fmt::format("NUMBER in [{:g} - {:g}]", lo, hi));
}

/// The most copies converge --ensemble runs. (The most threads, max_threads, is the library's:
/// run/run_request.hpp, shared with the Python module.)
inline constexpr long long max_ensemble = 1000;

/// A whole number from lo to hi; why_most says what the upper bound is for.
inline CLI::Validator whole_number_in(long long lo, long long hi, const std::string& why_most = "") {
    return CLI::Validator(
        [=](std::string& text) {
            // Digits only (after a sign): "2.0" or "1e0" would pass as numbers, then fail CLI11's
            // conversion to an integer with a vaguer message.
            const bool digits = text.find_first_not_of("0123456789", text[0] == '-' || text[0] == '+' ? 1 : 0) == std::string::npos;
            const double v = detail::finite_number(text);
            if (digits && v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) return std::string();
            return fmt::format("'{}' is not a whole number from {} to {}{}", text, lo, hi,
                               why_most.empty() ? "" : " (" + why_most + ")");
        },
        fmt::format("INT in [{} - {}]", lo, hi));
}

/// An output folder: a path that is not empty and not an existing file (refused before the work
/// that would then be lost; `--out ""` wrote its results nowhere and said it had).
inline CLI::Validator output_folder() {
    return CLI::Validator(
        [](std::string& text) {
            if (text.find_first_not_of(" \t") == std::string::npos) return std::string("an output folder must be named");
            std::error_code ec;
            if (std::filesystem::exists(text, ec) && !std::filesystem::is_directory(text, ec))
                return fmt::format("'{}' is a file, not a folder", text);
            return std::string();
        },
        "FOLDER");
}

/// An output file: a path that is not empty and not a folder, in a folder that exists (refused
/// before the work, not after it).
inline CLI::Validator output_file() {
    return CLI::Validator(
        [](std::string& text) {
            if (text.find_first_not_of(" \t") == std::string::npos) return std::string("an output file must be named");
            std::error_code ec;
            const std::filesystem::path path(text);
            if (std::filesystem::is_directory(path, ec)) return fmt::format("'{}' is a folder, not a file", text);
            const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
            if (!std::filesystem::is_directory(folder, ec))
                return fmt::format("'{}': its folder '{}' does not exist", text, folder.string());
            return std::string();
        },
        "FILE");
}

}  // namespace blockdem::cli
