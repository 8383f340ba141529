#pragma once
// Writes blocks as a DXF drawing (AutoCAD 2000, ASCII) with dxflib's writer: every block one
// closed LWPOLYLINE on its layer, coordinates in metres ($INSUNITS = 6), so that a deformed
// model goes back into CAD and can be read again through [[geometry]] (docs/drawings.md).
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// One block of a drawing to write.
struct LayerPolygon {
    std::string layer;
    std::vector<Vec2> vertices_m;   ///< [m]
};

/// A layer name DXF accepts: the characters < > / \ " : ; ? * | = ` become '_', "" becomes "0".
std::string dxf_layer_name(const std::string& name);

/// Writes blocks to file (replacing it). Throws OutputError naming the file when it cannot.
void write_dxf(const std::filesystem::path& file, const std::vector<LayerPolygon>& blocks);

}  // namespace blockdem
