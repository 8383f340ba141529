#pragma once
// Scenario keys for generated assemblies (docs/assemblies.md): each [[assemblies]] entry runs
// one generator of scenes/assemblies.hpp and appends its blocks to the model's bodies; the
// optional [settling] table asks for the settling stage (world/settling.hpp) before t = 0.
#include <set>
#include <string>

#include "io/toml_reader.hpp"
#include "world/model.hpp"

namespace blockdem {

/// Reads [[assemblies]] and [settling] from the scenario's top table into model (bodies are
/// appended after the [[bodies]] already read). Throws InputError naming the key.
void read_assemblies(TableReader& top, Model& model);

/// Refuses, at t's `name`, an assembly named "all" (the collapse summary's group of every block)
/// or named as an assembly before it (its collapse group would take both); adds it to seen
/// (both dimensions).
void check_assembly_name(const TableReader& t, const std::string& name, std::set<std::string>& seen);

/// [settling] (both dimensions): kinetic_ratio, window [s], max_time [s], friction.
SettlingSettings read_settling(TableReader t);

}  // namespace blockdem
