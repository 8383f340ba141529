#pragma once
// Errors that name where the problem is: the file, the key (dotted path), the line, the body.
// The physics never throws these; io/ and apps/ do. The CLI prints what() and exits non-zero.
#include <stdexcept>
#include <string>

namespace blockdem {

/// Where in the input a problem was found. Empty fields are left out of the message.
struct InputLocation {
    std::string file;   ///< scenario or data file path
    std::string key;    ///< dotted key path, e.g. "bodies.block.width"
    int line = 0;       ///< 1-based line in file, 0 if unknown
    int column = 0;     ///< 1-based column in file, 0 if unknown
};

/// Bad input: the message says what is wrong, the location says where.
class InputError : public std::runtime_error {
public:
    InputError(InputLocation where, std::string problem);
    const InputLocation& where() const { return where_; }
    const std::string& problem() const { return problem_; }

private:
    InputLocation where_;
    std::string problem_;
};

/// Formats "file:line:column: key 'a.b': problem" with the parts that are known.
std::string format_input_error(const InputLocation& where, const std::string& problem);

}  // namespace blockdem
