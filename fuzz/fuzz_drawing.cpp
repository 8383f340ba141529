// Fuzzes the drawing readers (docs/drawings.md): the bytes as a DXF drawing (the structure check,
// then dxflib and the entity collector) and as the text format, and every closed outline they
// return through the outline checks and the mass properties, as [[geometry]] takes them.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_workspace.hpp"
#include "geometry/polygon.hpp"
#include "io/drawn_outline.hpp"
#include "io/dxf_reader.hpp"
#include "io/polygon_text_reader.hpp"

namespace {

using namespace blockdem;

void check_outlines(const Drawing& drawing) {
    for (const DrawingEntity& e : drawing.entities) {
        if (!e.closed || !e.problem.empty()) continue;
        bool finite = true;
        for (const Vec2& p : e.vertices) finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
        if (!finite) continue;  // refused before the checks by io/geometry_keys.cpp
        const std::vector<Vec2> corners = without_repeated_vertices(e.vertices);
        if (drawn_outline_problem(corners, "m")) continue;
        (void)polygon_properties(counter_clockwise(corners));
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fuzz::expect_input_errors([&] { check_outlines(read_dxf(text, "drawing.dxf")); });
    fuzz::expect_input_errors([&] { check_outlines(read_polygon_text(text, "drawing.txt")); });
    return 0;
}
