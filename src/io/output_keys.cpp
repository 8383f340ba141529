#include "io/output_keys.hpp"

#include <algorithm>
#include <cmath>

namespace blockdem {

OutputSettings read_output_settings(TableReader& keys) {
    OutputSettings s;
    // vtk takes a boolean or the string "auto", so it is read from the node directly.
    if (keys.has("vtk")) {
        const toml::node* node = keys.raw().get("vtk");
        if (auto b = node->value<bool>()) {
            s.vtk = *b;
        } else if (auto text = node->value<std::string>(); !text || *text != "auto") {
            keys.fail("vtk", "must be true, false or \"auto\"");
        }
    }
    s.vtk_interval_s = keys.optional_positive("vtk_interval").value_or(s.vtk_interval_s);
    s.vtk_contacts = keys.boolean_or("vtk_contacts", s.vtk_contacts);
    s.report = keys.boolean_or("report", s.report);
    keys.reject_unknown_keys();
    return s;
}

std::int64_t vtk_frame_count(const OutputSettings& s, double duration_s) {
    // Clamped as a double before the cast: vtk_interval = 1e-300 s counts as 1e18 frames.
    return 1 + static_cast<std::int64_t>(std::min(std::floor(duration_s / s.vtk_interval_s + 1e-9), 1e18));
}

bool vtk_enabled(const OutputSettings& s, std::size_t body_count, double duration_s) {
    if (s.vtk) return *s.vtk;
    return static_cast<std::int64_t>(body_count) * vtk_frame_count(s, duration_s) <= vtk_auto_max_body_frames;
}

}  // namespace blockdem
