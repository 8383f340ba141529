// Fuzzes `--set key=value`: each line of the input is one assignment, applied with
// apply_overrides to each example scenario of examples/paper and the synthetic-record example,
// which is then read and built as `blockdem check --set ...` does (settling left out).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_workspace.hpp"
#include "io/overrides.hpp"
#include "io/scenario.hpp"

namespace {

using namespace blockdem;
namespace fs = std::filesystem;

struct Base {
    fs::path file;
    toml::table root;
};

// Parsed once: the harness measures the overrides, not the TOML parser (fuzz_scenario does that).
const std::vector<Base>& bases() {
    static const std::vector<Base> loaded = [] {
        const fs::path examples = fs::path(BLOCKDEM_SOURCE_DIR) / "examples";
        std::vector<Base> b;
        for (const char* name : {"paper/rocking.toml", "paper/sliding.toml", "paper/collision.toml",
                                 "records/block_synthetic.toml"})
            b.push_back({examples / name, load_toml_file(examples / name)});
        return b;
    }();
    return loaded;
}

std::vector<std::string> split_lines(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> lines;
    std::string line;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\n') {
            lines.push_back(std::move(line));
            line.clear();
        } else {
            line += static_cast<char>(data[i]);
        }
    }
    if (!line.empty()) lines.push_back(std::move(line));
    return lines;
}

void check_with_overrides(const Base& base, const std::vector<std::string>& assignments) {
    toml::table root = base.root;
    apply_overrides(root, assignments);
    Model model = read_model(root, base.file.string(), base.file.parent_path());
    model.settling.reset();
    try {
        (void)build_world(model);
    } catch (const ModelError& e) {
        throw InputError({base.file.string(), "", 0, 0}, e.what());  // as load_scenario reports it
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<std::string> assignments = split_lines(data, size);
    for (const Base& base : bases()) fuzz::expect_input_errors([&] { check_with_overrides(base, assignments); });
    return 0;
}
