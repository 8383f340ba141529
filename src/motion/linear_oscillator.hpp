#pragma once
// Exact time stepping of a damped linear oscillator
//     x'' + 2 zeta omega x' + omega^2 x = f(t)
// under a force f that is linear within each step. The step map is the exponential of the
// augmented 4x4 system [x, x', f, f'] (f' constant over the step), computed once per step size.
// It is exact for any damping (also zeta >= 1) and any step, which is what the response spectrum
// (Nigam-Jennings' piecewise-linear idea) and the Kanai-Tajimi filter both need.
#include <array>

namespace blockdem {

/// Displacement and velocity of the oscillator (units of f times s^2 and s).
struct OscillatorState {
    double x = 0.0;
    double v = 0.0;
};

class OscillatorStep {
public:
    /// omega [rad/s] > 0, zeta >= 0 (fraction of critical), h [s] > 0: the step.
    OscillatorStep(double omega_rad_s, double zeta, double h_s);
    /// The state after one step, the force going linearly from f0 to f1.
    OscillatorState advance(OscillatorState s, double f0, double f1) const;
    /// The acceleration x'' of state s under force f.
    double acceleration(OscillatorState s, double f) const { return f - 2.0 * zeta_ * omega_ * s.v - omega_ * omega_ * s.x; }

private:
    double omega_;
    double zeta_;
    double h_;
    std::array<std::array<double, 4>, 2> map_{};  // first two rows of exp(M h)
};

}  // namespace blockdem
