#pragma once
// Scratch of the stable-time-step bound (dynamics/critical_time_step.hpp): the absolute row sums
// of the mass-normalised stiffness and damping matrices, 3 rows a body (x, y, rotation),
// accumulated contact point by contact point. The world keeps one so that the run's periodic
// check allocates nothing.
#include <cstddef>
#include <vector>

namespace blockdem {

struct Bodies;
struct StiffnessPoint;
struct CriticalTimeStep;

struct StabilityRows {
    std::vector<double> stiffness_1_s2;  ///< [1/s^2]
    std::vector<double> damping_1_s;     ///< [1/s]

    void reset(std::size_t bodies);
    void add(const Bodies& bodies, const StiffnessPoint& p);
    CriticalTimeStep limit(const Bodies& bodies) const;
};

}  // namespace blockdem
