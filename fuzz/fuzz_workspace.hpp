#pragma once
// What every fuzz harness shares (docs/checks.md): a private scratch folder to write each input
// into, laid out like the repository so that a scenario's relative file names resolve as they do
// for the examples, and the rule that separates an expected rejection from a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace blockdem::fuzz {

/// A folder made once per process and removed at exit:
///   <root>/repo/examples/records/   inputs are written here (a scenario's own folder)
///   <root>/repo/examples/<other>    links to the source tree's example folders
///   <root>/repo/tests               link to the source tree's tests/ (tests/data/records)
///   <root>/shared                   link to ../shared beside the source tree, when present
/// so "../../tests/data/records/x.AT2", "../dxf/stone_wall.dxf" and the examples'
/// "../../../shared/data/..." resolve.
struct Workspace {
    std::filesystem::path root;
    std::filesystem::path input_dir;
};

/// The process's workspace. libFuzzer calls a plain C function with no context, so the one
/// workspace is kept in a function-local static (made on first use).
const Workspace& workspace();

/// Writes the fuzzer's bytes to input_dir/name (replacing it) and returns the path.
std::filesystem::path write_input(std::string_view name, const std::uint8_t* data, std::size_t size);

/// Runs check. A blockdem::InputError is the expected answer to bad input and is swallowed;
/// anything else (another exception, a crash, a sanitizer report) escapes and is a finding.
template <class Check>
void expect_input_errors(Check&& check);

}  // namespace blockdem::fuzz

#include "io/input_error.hpp"

template <class Check>
void blockdem::fuzz::expect_input_errors(Check&& check) {
    try {
        check();
    } catch (const blockdem::InputError&) {
        // The reader said what is wrong and where: the outcome the CLI turns into exit code 2.
    }
}
