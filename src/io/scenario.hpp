#pragma once
// Scenario files (TOML, docs/scenario.md): read, overridden with --set, validated key by key,
// and turned into a Model. Every problem is an InputError naming file, key and line.
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "io/output_keys.hpp"
#include "io/sensor_keys.hpp"
#include "io/toml_reader.hpp"
#include "motion/records/acceleration_units.hpp"  // standard_gravity_m_s2, for the keys given in g
#include "world/model.hpp"
#include "world/world.hpp"

namespace blockdem {

/// Parses a TOML file. Throws InputError for a missing file or a syntax error (with its line).
toml::table load_toml_file(const std::filesystem::path& file);

/// Reads and validates a whole scenario. scenario_dir resolves relative file names.
Model read_model(const toml::table& root, const std::string& file_for_messages,
                 const std::filesystem::path& scenario_dir);

/// The factor that turns a value in the unit named by key "unit" (m/s^2, gal, g) into m/s^2.
double acceleration_unit_factor(TableReader& keys, const std::string& key = "unit");

/// Everything a command needs: the file, the overridden TOML, the model and the world.
struct LoadedScenario {
    std::filesystem::path file;
    toml::table root;   ///< after --set overrides
    Model model;
    World world;
    OutputSettings output;   ///< [output]: files besides history.csv and summary.json (io only)
    /// [simulation] initial_state: a state file to start from (io/state_file.hpp), relative
    /// names resolved against the scenario's folder; empty: none. The world is built from the
    /// scenario alone: run_scenario and the sweeps apply the state.
    std::filesystem::path initial_state;
    MeasurementSettings measurements;   ///< [[sensors]] and [output] interfaces (io/sensor_keys.hpp)
};

/// Loads, overrides, validates and builds. A model error (overlap at start, unstable dt) is
/// reported as an InputError naming the file. settle = false skips [settling] (a restart
/// takes the settled state from its state file). A stop request while settling throws
/// SettlingStopped (world/settling.hpp).
LoadedScenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                             bool settle = true, const std::atomic<bool>* stop_requested = nullptr);
/// The same for a scenario already parsed (the Python module's from_toml and from_dict): `file`
/// names it in messages, and its folder resolves relative file names.
LoadedScenario load_scenario(toml::table root, const std::filesystem::path& file, const std::vector<std::string>& overrides,
                             bool settle = true, const std::atomic<bool>* stop_requested = nullptr);

}  // namespace blockdem
