#include "io/vec3_keys.hpp"

#include <cmath>

#include <fmt/format.h>

namespace blockdem {

std::optional<Vec3> optional_vec3(TableReader& t, const std::string& key) {
    if (!t.has(key)) return std::nullopt;
    const std::vector<double> v = t.number_list(key);
    if (v.size() != 3) t.fail(key, fmt::format("must be a list of three numbers [x, y, z], got {}", v.size()));
    return Vec3{v[0], v[1], v[2]};
}

Vec3 vec3(TableReader& t, const std::string& key, const std::string& what) {
    if (auto v = optional_vec3(t, key)) return *v;
    t.fail_missing(key, what);
}

std::vector<Vec3> vec3_list(TableReader& t, const std::string& key) {
    const bool given = t.has(key);
    const toml::array* rows = t.raw().get_as<toml::array>(key);
    if (!rows && given) t.fail(key, "must be a list of [x, y, z] points in m");
    if (!rows) t.fail_missing(key, " (a list of [x, y, z] in m)");
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < rows->size(); ++i) {
        const toml::array* row = (*rows)[i].as_array();
        const auto number = [&](std::size_t k) { return row ? (*row)[k].value<double>() : std::nullopt; };
        if (!row || row->size() != 3 || !number(0) || !number(1) || !number(2))
            t.fail(key, fmt::format("point {} must be three numbers [x, y, z] in m", i));
        // (nan or inf made the hull's tests fail, and the message said the points were flat.)
        if (!std::isfinite(*number(0)) || !std::isfinite(*number(1)) || !std::isfinite(*number(2)))
            t.fail(key, fmt::format("point {} holds a value that is not a finite number: [{}, {}, {}]", i, *number(0),
                                    *number(1), *number(2)));
        points.push_back({*number(0), *number(1), *number(2)});
    }
    return points;
}

}  // namespace blockdem
