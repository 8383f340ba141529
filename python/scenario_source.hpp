#pragma once
// What blockdem.Scenario holds: the scenario's TOML text and the name it goes by. It stays
// TOML, edited by the setters, so that every check and message is the CLI's own
// (io/scenario.hpp); a Simulation loads it as `blockdem run` loads a file.
#include <atomic>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include <toml++/toml.h>

#include "io/input_error.hpp"
#include "io/scenario.hpp"

namespace blockdem::python {

struct ScenarioSource {
    /// The TOML text: as read, or as the last edit left it (toml_text of the edited tree). It is
    /// kept as text and parsed afresh for each use because a copied toml::table loses its source
    /// lines, which the messages name.
    std::string text;
    /// The scenario file, or "<toml>" / "<dict>" for one given in Python (in base_dir when
    /// given): messages name it, and its folder resolves relative file names (records, CSV).
    std::filesystem::path file;

    toml::table parse() const {
        try {
            return toml::parse(text, file.string());
        } catch (const toml::parse_error& e) {
            throw InputError({file.string(), "", static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)},
                             fmt::format("TOML syntax error: {}", e.description()));
        }
    }
    /// Loads it as the CLI does (settle = false: only the checks; a Simulation settles).
    /// A stop request (stop_requested set) ends settling with SettlingStopped.
    LoadedScenario load(bool settle, const std::atomic<bool>* stop_requested = nullptr) const {
        return load_scenario(parse(), file, {}, settle, stop_requested);
    }
};

}  // namespace blockdem::python
