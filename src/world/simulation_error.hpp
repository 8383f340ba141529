#pragma once
// A run that cannot go on: unstable, non-finite state, runaway energy. Names the time, step and
// body, so that a user can find the cause.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

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

/// The clause of an unstable run's message that names its body: one of the bodies that left the
/// model (left: the domain's records, with body, time_s and velocity_m_s) whose kinetic energy was
/// beyond the range of a number (thrown at 1e200 m/s: it made the ledger nan and was then frozen
/// at rest, so the fastest body named was the table), else the fastest. mass_kg(i), name(i),
/// speed(i): body i's.
template <class Left, class Mass, class Name, class Speed>
std::string unstable_body_clause(const Left& left, std::size_t bodies, Mass mass_kg, Name name, Speed speed) {
    for (const auto& l : left) {
        const double v = std::sqrt(dot(l.velocity_m_s, l.velocity_m_s));
        if (std::isfinite(0.5 * mass_kg(l.body) * v * v)) continue;
        return fmt::format("body '{}' left the model at t = {:.6g} s with a kinetic energy beyond the range of a number "
                           "(check its initial velocity)",
                           name(l.body), l.time_s);
    }
    const std::size_t fastest = fastest_body(bodies, speed);
    return fmt::format("fastest body '{}' at {:.4g} m/s", name(fastest), speed(fastest));
}

}  // namespace blockdem
