#include "io/polygon_text_reader.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::string word;
    std::istringstream in(line.substr(0, line.find('#')));
    while (in >> word) out.push_back(word);
    return out;
}

double coordinate(const std::string& word, const std::string& file, int line) {
    double value = 0.0;
    const char* end = word.data() + word.size();
    const auto [stop, error] = std::from_chars(word.data(), end, value);
    if (error != std::errc{} || stop != end || !std::isfinite(value))
        throw InputError({file, "", line, 0}, fmt::format("'{}' is not a coordinate (a finite number)", word));
    return value;
}

}  // namespace

Drawing read_polygon_text(const std::string& text, const std::string& file) {
    Drawing drawing;
    std::istringstream in(text);
    std::string line_text;
    int line = 0;
    while (std::getline(in, line_text)) {
        ++line;
        const std::vector<std::string> w = words(line_text);
        if (w.empty()) continue;
        if (w.size() < 2)
            throw InputError({file, "", line, 0}, "a polygon line is: name layer x1 y1 x2 y2 x3 y3 ... (found only a name)");
        if (w.size() % 2 != 0)
            throw InputError({file, "", line, 0},
                             fmt::format("polygon '{}' has an odd count of coordinates ({}): give x y pairs", w[0], w.size() - 2));
        DrawingEntity e;
        e.name_suffix = w[0];
        e.layer = w[1];
        e.type = "polygon";
        e.id = fmt::format("'{}'", w[0]);
        e.line = line;
        e.closed = true;
        for (std::size_t k = 2; k < w.size(); k += 2)
            e.vertices.push_back({coordinate(w[k], file, line), coordinate(w[k + 1], file, line)});
        if (e.vertices.size() > 1 && e.vertices.front() == e.vertices.back()) e.vertices.pop_back();
        drawing.entities.push_back(std::move(e));
    }
    return drawing;
}

}  // namespace blockdem
