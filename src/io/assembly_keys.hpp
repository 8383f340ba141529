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

/// Memory a generated block costs in a run [B]: in 2-D, 1.73 GB peak for the 1e6-brick wall
/// (docs/performance.md) is 1.7 kB a brick, and 2 kB leaves room for the contacts of a denser
/// packing; in 3-D, the start (the probe's points and the highest-mode estimate) is the peak:
/// 245 MB for `blockdem check` on a 1e4-brick wall and 2.37 GB at 1e5 bricks, 24 kB a brick.
inline constexpr double bytes_per_block_2d = 2000.0;
inline constexpr double bytes_per_block_3d = 25000.0;

/// Refuses, at t's `key`, an assembly whose estimated blocks would not fit in the machine's memory
/// (at bytes_per_block each) or exceed the most a run may have, before it is generated: "how"
/// says where the estimate comes from. Both dimensions.
void check_block_budget(TableReader& t, const std::string& key, double blocks, const std::string& how,
                        double bytes_per_block);

/// [settling] (both dimensions): kinetic_ratio, window [s], max_time [s], friction.
SettlingSettings read_settling(TableReader t);

}  // namespace blockdem
