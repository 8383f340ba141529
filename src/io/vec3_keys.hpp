#pragma once
// Three-component keys of a 3-D scenario ([x, y, z] points and lists of them), read with the
// messages every other key gets (io/toml_reader.hpp). Shared by io/scenario_3d.cpp and the
// generated assemblies (io/assembly_3d_keys.cpp).
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec3.hpp"
#include "io/toml_reader.hpp"

namespace blockdem {

/// A list of three numbers ([x, y, z]); nullopt when the key is absent.
std::optional<Vec3> optional_vec3(TableReader& t, const std::string& key);

/// The same, required; `what` completes the message when it is missing.
Vec3 vec3(TableReader& t, const std::string& key, const std::string& what);

/// A list of [x, y, z] points [m].
std::vector<Vec3> vec3_list(TableReader& t, const std::string& key);

}  // namespace blockdem
