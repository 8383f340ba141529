#pragma once
// The plain text format for drawings made by scripts (docs/drawings.md): one block a line,
//   name layer x1 y1 x2 y2 x3 y3 ...
// separated by spaces or tabs, in the units the scenario gives; '#' starts a comment that runs
// to the end of the line; empty lines are skipped. A last point equal to the first is dropped.
#include <string>

#include "io/drawing.hpp"

namespace blockdem {

/// The polygons of text (file: for messages), each with its line. Throws InputError naming
/// file:line for a line that is not a name, a layer and pairs of numbers.
Drawing read_polygon_text(const std::string& text, const std::string& file);

}  // namespace blockdem
