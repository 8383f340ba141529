#pragma once
// A run that cannot go on: unstable, non-finite state, runaway energy. Names the time, step and
// body, so that a user can find the cause.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace blockdem {

class SimulationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The body of largest speed(i) [m/s] of bodies 0 .. n - 1, for the message of an unstable run: a
/// body whose speed is not finite first, as it is the one that blew up (compared as numbers, a nan
/// or inf speed lost to the table's 9e-6 m/s and the table was named).
template <class Speed>
std::size_t fastest_body(std::size_t n, Speed speed) {
    std::size_t fastest = 0;
    for (std::size_t i = 1; i < n; ++i) {
        const double s = speed(i), f = speed(fastest);
        if (std::isfinite(f) && (!std::isfinite(s) || s > f)) fastest = i;
    }
    return fastest;
}

}  // namespace blockdem
