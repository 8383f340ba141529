#pragma once
// bodies.json: what the figures and the report need to draw the bodies at any output time
// from history.csv alone (no VTK needed): per body its id, name, kind, assembly ("" for
// [[bodies]]; a drawn block's layer), material, whether it is
// in history.csv, its centroid at t = 0 and its corners relative to the centroid at rotation
// 0 [m]. A corner at time t is then x(t) + R(rot(t)) * corner, with x and rot from history.csv.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "world/world.hpp"

namespace blockdem {

nlohmann::json bodies_json(const World& w);
void write_bodies_json(const std::filesystem::path& file, const World& w);

}  // namespace blockdem
