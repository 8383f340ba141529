#pragma once
// Reads an ASCII DXF drawing (AutoCAD R12 to 2018) with dxflib (Debian libdxflib-dev) into the
// entities of io/drawing.hpp. Closed LWPOLYLINEs and POLYLINEs are block outlines; arcs (bulges),
// circles, ellipses, splines, lines, solids, hatches and block references are returned with the
// problem that keeps them from being blocks; text, dimensions and the like are left out
// (annotation). Entities of paper space and of block definitions are left out: only model
// space is the model.
#include <string>

#include "io/drawing.hpp"

namespace blockdem {

/// The entities of the DXF drawing in text (file: for messages). Throws InputError naming file
/// when the text is not an ASCII DXF drawing (a binary DXF, another file, a truncated one).
Drawing read_dxf(const std::string& text, const std::string& file);

}  // namespace blockdem
