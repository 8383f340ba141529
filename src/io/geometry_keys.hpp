#pragma once
// Scenario keys for drawn blocks (docs/drawings.md): each [[geometry]] entry reads a drawing
// (DXF, io/dxf_reader.hpp, or the plain text format, io/polygon_text_reader.hpp) and appends one
// body per closed outline, with the settings of its layer from [geometry.layers]:
//   [[geometry]]
//   file = "slope.dxf"          # relative to the scenario's folder
//   units = "mm"                # m, cm or mm: required
//   [geometry.layers]
//   GROUND = { kind = "fixed" }
//   BLOCKS = { density = 2600.0, material = "stone" }
// A block is named LAYER_ID (the layer with characters other than letters, digits, '_' and
// '-' made '_'; ID: the DXF handle, or the polyline's number in a file without handles), or by
// its name in a text file; its assembly is its layer (the collapse summary's group, and the
// layer `blockdem export --dxf` writes it on).
#include <filesystem>

#include "io/toml_reader.hpp"
#include "world/model.hpp"

namespace blockdem {

/// Reads [[geometry]] from the scenario's top table into model (bodies appended after those
/// already read). Relative file names are resolved against scenario_dir. Throws InputError
/// naming the key, or the drawing's file, entity and layer.
void read_geometry(TableReader& top, Model& model, const std::filesystem::path& scenario_dir);

}  // namespace blockdem
