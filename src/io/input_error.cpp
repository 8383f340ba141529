#include "io/input_error.hpp"

#include <fmt/format.h>

namespace blockdem {

std::string format_input_error(const InputLocation& where, const std::string& problem) {
    std::string out;
    if (!where.file.empty()) {
        out += where.file;
        if (where.line > 0) out += fmt::format(":{}", where.line);
        if (where.column > 0) out += fmt::format(":{}", where.column);
        out += ": ";
    }
    if (!where.key.empty()) out += fmt::format("key '{}': ", where.key);
    out += problem;
    return out;
}

InputError::InputError(InputLocation where, std::string problem)
    : std::runtime_error(format_input_error(where, problem)), where_(std::move(where)), problem_(std::move(problem)) {}

}  // namespace blockdem
