// Fuzzes the scenario reader: the bytes are a scenario file, read as `blockdem check` reads it
// (load_toml_file, read_model with every motion, record, CSV and assembly key, [output], then
// build_world and the check command's motion figures). The run itself is not started, and an
// assembly's settling stage (a simulation) is left out so that each input takes milliseconds.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_workspace.hpp"
#include "io/output_keys.hpp"
#include "io/scenario.hpp"
#include "motion/table_motion.hpp"

namespace {

using namespace blockdem;

void check_scenario(const std::filesystem::path& file) {
    const toml::table root = load_toml_file(file);
    Model model = read_model(root, file.string(), file.parent_path());
    TableReader top(root, file.string(), "");
    if (auto output = top.optional_table("output")) (void)read_output_settings(*output);
    model.settling.reset();
    World world;
    try {
        world = build_world(model);
    } catch (const ModelError& e) {
        throw InputError({file.string(), "", 0, 0}, e.what());  // as load_scenario reports it
    }
    for (const ComponentMotion* m : {&world.table_motion.horizontal, &world.table_motion.vertical}) {
        (void)describe(*m);
        (void)peak_acceleration(*m);
        (void)sample(*m, world.settings.duration_s);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = fuzz::write_input("scenario.toml", data, size);
    fuzz::expect_input_errors([&] { check_scenario(file); });
    return 0;
}
