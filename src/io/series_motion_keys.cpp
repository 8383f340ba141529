#include "io/series_motion_keys.hpp"

#include <stdexcept>

#include "io/scenario.hpp"

namespace blockdem {

AccelerationSeries read_series_motion_keys(TableReader& keys) {
    const double dt_s = keys.positive("dt");
    const double factor = acceleration_unit_factor(keys) * keys.number_or("scale", 1.0);
    std::vector<double> acceleration_m_s2 = keys.number_list("values");
    if (acceleration_m_s2.size() < 2) keys.fail("values", "needs at least 2 samples");
    std::vector<double> time_s(acceleration_m_s2.size());
    for (std::size_t i = 0; i < time_s.size(); ++i) {
        time_s[i] = static_cast<double>(i) * dt_s;
        acceleration_m_s2[i] *= factor;
    }
    keys.reject_unknown_keys();
    try {
        return make_acceleration_series(std::move(time_s), std::move(acceleration_m_s2), keys.path());
    } catch (const std::invalid_argument& e) {
        keys.fail("values", e.what());
    }
}

}  // namespace blockdem
