#include "world/model.hpp"

#include <algorithm>
#include <stdexcept>

namespace blockdem {

const char* to_string(BodyKind kind) {
    switch (kind) {
        case BodyKind::dynamic: return "dynamic";
        case BodyKind::fixed: return "fixed";
        case BodyKind::driven: return "driven";
    }
    return "?";
}

std::uint32_t MaterialPairs::id(const std::string& material) const {
    const auto it = std::find(materials.begin(), materials.end(), material);
    if (it == materials.end()) throw std::out_of_range("unknown material '" + material + "'");
    return static_cast<std::uint32_t>(it - materials.begin());
}

void MaterialPairs::set(std::uint32_t i, std::uint32_t j, const ContactParameters& p) {
    parameters[i * materials.size() + j] = p;
    parameters[j * materials.size() + i] = p;
    refresh_any_dilation();
}

void MaterialPairs::refresh_any_dilation() {
    any_dilation = std::any_of(parameters.begin(), parameters.end(), [](const ContactParameters& p) { return p.tan_dilation > 0.0; });
}

MaterialPairs MaterialPairs::uniform(const ContactParameters& p) {
    MaterialPairs pairs;
    pairs.materials = {"default"};
    pairs.parameters = {p};
    pairs.refresh_any_dilation();
    return pairs;
}

}  // namespace blockdem
