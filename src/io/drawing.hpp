#pragma once
// A drawing as the readers of CAD and script files return it (docs/drawings.md): every entity
// that could be or could be mistaken for a block outline, in the file's own units, with its
// layer and an id that the user can find in the file (a DXF handle, a line number). What to do
// with each entity (a block, an error, nothing) is decided by the scenario keys
// (io/geometry_keys.hpp), which know which layers hold blocks.
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// One entity of a drawing.
struct DrawingEntity {
    std::string layer;              ///< the layer (DXF) or the layer column (text)
    std::string id;                 ///< for messages, after the type: "(handle 2F)", "#3", "'A1'"
    std::string name_suffix;        ///< what the block's name ends with: "2F", "3", or the whole given name
    std::string type;               ///< "polyline", "circle", ..., "polygon" (text)
    std::vector<Vec2> vertices;     ///< [drawing units] as drawn, closing vertex removed
    /// Empty when the entity is a closed outline of straight segments (a block candidate);
    /// otherwise why it cannot be a block ("an open polyline", "a circle", ...).
    std::string problem;
    bool closed = false;            ///< a closed polyline or a text polygon: a block on a block layer
    int line = 0;                   ///< 1-based line in a text file (0 for DXF: entities have handles)
};

struct Drawing {
    std::vector<DrawingEntity> entities;
    /// The length unit the file declares ("m", "mm", "in", ...; DXF $INSUNITS), if it declares one.
    std::optional<std::string> declared_units;
};

}  // namespace blockdem
