#pragma once
// A run that cannot go on: unstable, non-finite state, runaway energy. Names the time, step and
// body, so that a user can find the cause.
#include <stdexcept>
#include <string>

namespace blockdem {

class SimulationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace blockdem
