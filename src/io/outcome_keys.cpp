#include "io/outcome_keys.hpp"

#include <fmt/format.h>

namespace blockdem {

std::optional<DomainBox> read_domain(TableReader& simulation) {
    if (!simulation.has("domain")) return std::nullopt;
    const std::vector<Vec2> corners = simulation.vec2_list("domain");
    if (corners.size() != 2)
        simulation.fail("domain", fmt::format("must be two corners [[x_min, y_min], [x_max, y_max]] in m, got {} points",
                                              corners.size()));
    const DomainBox box{corners[0], corners[1]};
    if (!(box.lo_m.x < box.hi_m.x && box.lo_m.y < box.hi_m.y))
        simulation.fail("domain", fmt::format("the first corner must be below and left of the second, got [[{:g}, {:g}], [{:g}, {:g}]]",
                                              box.lo_m.x, box.lo_m.y, box.hi_m.x, box.hi_m.y));
    return box;
}

void check_domain_contains_bodies(TableReader simulation, const Model& model) {
    const std::optional<DomainBox>& box = model.settings.domain;
    if (!box) return;
    for (const BodyDef& body : model.bodies)
        for (const Vec2& v : body.vertices_m)
            if (v.x < box->lo_m.x || v.x > box->hi_m.x || v.y < box->lo_m.y || v.y > box->hi_m.y)
                simulation.fail("domain", fmt::format("[[{:g}, {:g}], [{:g}, {:g}]] m does not contain body '{}' at t = 0 "
                                                      "(its corner ({:g}, {:g}) m is outside)",
                                                      box->lo_m.x, box->lo_m.y, box->hi_m.x, box->hi_m.y, body.name, v.x, v.y));
}

OutcomeThresholds read_outcome_thresholds(TableReader t) {
    OutcomeThresholds o;
    auto non_negative = [&](const char* key, double fallback) {
        const double v = t.number_or(key, fallback);  // (a value that is not a finite number fails here)
        if (v < 0.0) t.fail(key, fmt::format("must be >= 0, got {}", v));
        return v;
    };
    o.rocking_ratio = non_negative("rocking_ratio", o.rocking_ratio);
    o.slip_ratio = non_negative("slip_ratio", o.slip_ratio);
    o.fall_drop_ratio = non_negative("fall_drop_ratio", o.fall_drop_ratio);
    o.displaced_ratio = non_negative("displaced_ratio", o.displaced_ratio);
    o.rest_speed_m_s = non_negative("rest_speed", o.rest_speed_m_s);
    o.support_window_s = non_negative("support_window", o.support_window_s);
    t.reject_unknown_keys();
    return o;
}

}  // namespace blockdem
