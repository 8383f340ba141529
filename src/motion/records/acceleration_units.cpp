#include "motion/records/acceleration_units.hpp"

#include <array>
#include <string>

#include "motion/records/record_text.hpp"

namespace blockdem {

std::optional<double> acceleration_unit_factor(std::string_view unit) {
    struct Spelling {
        std::string_view name;
        double factor;  // [m/s^2 per unit]
    };
    static constexpr std::array spellings{
        Spelling{"m/s^2", 1.0},     Spelling{"m/s2", 1.0},       Spelling{"m/s/s", 1.0},
        Spelling{"m/sec2", 1.0},    Spelling{"m/sec^2", 1.0},    Spelling{"m/sec/sec", 1.0},
        Spelling{"gal", 0.01},      Spelling{"cm/s^2", 0.01},    Spelling{"cm/s2", 0.01},
        Spelling{"cm/s/s", 0.01},   Spelling{"cm/sec2", 0.01},   Spelling{"cm/sec^2", 0.01},
        Spelling{"cm/sec/sec", 0.01}, Spelling{"g", standard_gravity_m_s2}, Spelling{"mg", 1e-3 * standard_gravity_m_s2},
    };
    const std::string key = records::to_lower(records::trim(unit));
    for (const auto& s : spellings)
        if (s.name == key) return s.factor;
    return std::nullopt;
}

}  // namespace blockdem
