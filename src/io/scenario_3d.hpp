#pragma once
// 3-D scenario files (`dimension = 3`, docs/scenario.md "Three dimensions"): read, overridden
// with --set, validated key by key with the 2-D reader's machinery and words (io/toml_reader.hpp,
// io/scenario_keys.hpp), and turned into a World3d whose time step is set and checked
// (world/world_3d_start.hpp). Every problem is an InputError naming the file, key and body.
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "dynamics/critical_time_step_3d.hpp"
#include "io/output_keys.hpp"
#include "world/outcome.hpp"
#include "world/world.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

/// The scenario's `dimension` key: 2 when absent. Throws InputError for a value other than 2 or 3.
int scenario_dimension(const toml::table& root, const std::string& file_for_messages);

/// Everything `blockdem run` needs of a 3-D scenario.
struct LoadedScenario3d {
    std::filesystem::path file;
    toml::table root;                 ///< after --set overrides
    World3d world;                    ///< at t = 0, dt set
    double duration_s = 0.0;          ///< [s]
    double output_interval_s = 1e-3;  ///< [s] between rows of history.csv and energy.csv
    double critical_dt_s = 0.0;       ///< [s] the highest contact mode's limit at the start (infinite: no contact)
    StartTimeStep3d start;            ///< the start's limits (world/world_3d_start.hpp), critical_dt_s among them
    double max_energy_error = 0.5;    ///< [-] stop when the balance error exceeds it (as 2-D)
    double max_overlap_ratio = 0.25;  ///< [-] stop when an overlap exceeds it of the thinner body's least width
    OutputSettings output;            ///< [output] vtk, vtk_interval
    std::vector<std::string> assembly_notes;  ///< what each generated assembly built (rock mass, packing)
    OutcomeThresholds outcomes;       ///< [outcomes], as in 2-D (world/outcome.hpp)
    std::optional<SettlingSettings> settling;  ///< [settling], as in 2-D (world/settling_3d.hpp)
    std::optional<SettlingRecord> settled;     ///< what settling did, when it ran (or a restart's state kept)
    std::filesystem::path initial_state;       ///< [simulation] initial_state (empty: none), as in 2-D
};

/// Loads, overrides, validates and builds. A model error (a non-convex or degenerate polyhedron,
/// overlap at start, dt above the stable bound) is an InputError naming the file and the body.
/// With settle and a [settling] table the world is settled (world/settling_3d.hpp) before t = 0;
/// a settling that fails is a SimulationError (the run's exit 3, as in 2-D), one that a stop
/// request (stop_requested) ended is a SettlingStopped.
LoadedScenario3d load_scenario_3d(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                                  bool settle = false, const std::atomic<bool>* stop_requested = nullptr);
/// The same for a scenario already parsed; `file` names it and its folder resolves file names.
LoadedScenario3d load_scenario_3d(toml::table root, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides, bool settle = false,
                                  const std::atomic<bool>* stop_requested = nullptr);

}  // namespace blockdem
