#include "io/geometry_keys.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "geometry/polygon.hpp"
#include "io/drawn_outline.hpp"
#include "io/dxf_reader.hpp"
#include "io/polygon_text_reader.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

// A drawing larger than this is refused before it is read (a drawing of a million blocks is
// about 100 MB of DXF; a bigger file is more likely a wrong one).
constexpr std::uintmax_t max_drawing_bytes = 256u << 20;

/// The settings of a layer's blocks: the keys of [[bodies]] that apply to drawn blocks.
struct LayerSettings {
    bool skip = false;                    ///< leave the layer's entities out
    BodyKind kind = BodyKind::dynamic;
    std::optional<double> density_kg_m3;  ///< [kg/m^3]
    std::string material = "default";
    double thickness_m = 1.0;             ///< [m] out of plane
    bool record = false;                  ///< in history.csv (as generated blocks: a drawing may have thousands)
};

LayerSettings read_layer(TableReader t, const std::string& layer) {
    LayerSettings s;
    s.skip = t.boolean_or("skip", false);
    if (s.skip) {
        if (t.raw().size() > 1) t.fail("skip", "a skipped layer takes no other key");
        return s;
    }
    const std::string kind = t.choice("kind", {"dynamic", "fixed", "driven"}, "dynamic");
    s.kind = kind == "dynamic" ? BodyKind::dynamic : kind == "fixed" ? BodyKind::fixed : BodyKind::driven;
    s.density_kg_m3 = t.optional_positive("density");
    s.material = t.optional_string("material").value_or("default");
    s.thickness_m = t.optional_positive("thickness").value_or(1.0);
    s.record = t.boolean_or("record", false);
    if (s.kind == BodyKind::dynamic && !s.density_kg_m3)
        t.fail_missing("density", fmt::format(" [kg/m^3]: the dynamic blocks of layer '{}' need it (or kind = \"fixed\" or "
                                              "\"driven\", or skip = true)",
                                              layer));
    t.reject_unknown_keys();
    return s;
}

std::string read_file_text(TableReader& t, const fs::path& file) {
    if (!fs::is_regular_file(file)) t.fail("file", fmt::format("no drawing file '{}'", file.string()));
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(file, error);
    if (!error && bytes > max_drawing_bytes)
        t.fail("file", fmt::format("'{}' has {} bytes, more than the {} MiB a drawing may have", file.string(), bytes,
                                   max_drawing_bytes >> 20));
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) t.fail("file", fmt::format("cannot read '{}'", file.string()));
    return text.str();
}

// A body name made of a layer name: characters a body name may not hold become '_'.
std::string name_part(const std::string& layer) {
    std::string out = layer;
    for (char& c : out)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) c = '_';
    return out;
}

bool valid_body_name(const std::string& name) {
    return !name.empty() && name.find_first_of(",.;\"' \t\r\n") == std::string::npos;
}

[[noreturn]] void fail_entity(const std::string& file, const DrawingEntity& e, const std::string& problem) {
    throw InputError({file, "", e.line, 0}, fmt::format("{} {} on layer '{}' {}", e.type, e.id, e.layer, problem));
}

// The drawing's blocks on block layers as bodies, in the drawing's order.
std::vector<BodyDef> drawing_bodies(const Drawing& drawing, const std::string& file, const std::string& unit,
                                    const std::string& prefix, bool text_format,
                                    const std::map<std::string, LayerSettings>& layers) {
    const double metres_per_unit = unit == "mm" ? 1e-3 : unit == "cm" ? 1e-2 : 1.0;
    std::vector<BodyDef> bodies;
    std::map<std::string, const DrawingEntity*> named;  // a name given twice in a text file
    for (const DrawingEntity& e : drawing.entities) {
        const auto layer = layers.find(e.layer);
        if (layer == layers.end() || layer->second.skip) continue;
        if (!e.problem.empty()) fail_entity(file, e, e.problem);
        for (const Vec2& p : e.vertices)
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail_entity(file, e, "has a corner that is not a finite number");
        const std::vector<Vec2> corners = without_repeated_vertices(e.vertices);
        if (auto problem = drawn_outline_problem(corners, unit)) fail_entity(file, e, *problem);
        const LayerSettings& s = layer->second;
        BodyDef b;
        b.name = prefix + (text_format ? e.name_suffix : name_part(e.layer) + "_" + e.name_suffix);
        if (!valid_body_name(b.name))
            fail_entity(file, e, fmt::format("makes the block name '{}', which is not valid: use letters, digits, '_' or '-'",
                                             b.name));
        if (const auto [first, added] = named.emplace(b.name, &e); !added)
            fail_entity(file, e, fmt::format("has the name of {} {}{}: every block needs its own name", first->second->type,
                                             first->second->id,
                                             first->second->line > 0 ? fmt::format(" (line {})", first->second->line) : ""));
        b.kind = s.kind;
        b.material = s.material;
        b.density_kg_m3 = s.density_kg_m3.value_or(0.0);
        b.thickness_m = s.thickness_m;
        b.record = s.record;
        b.assembly = e.layer;
        for (const Vec2& p : corners) b.vertices_m.push_back({p.x * metres_per_unit, p.y * metres_per_unit});
        b.vertices_m = counter_clockwise(std::move(b.vertices_m));
        bodies.push_back(std::move(b));
    }
    return bodies;
}

// Every block layer of the table has blocks in the drawing, and every layer with closed
// outlines is in the table: a misspelt layer name would otherwise drop blocks silently.
void check_layers(TableReader& t, TableReader& layer_table, const Drawing& drawing, const std::string& file,
                  const std::map<std::string, LayerSettings>& layers) {
    std::map<std::string, int> outlines;   // closed outlines per layer of the drawing
    std::vector<std::string> drawing_layers;
    for (const DrawingEntity& e : drawing.entities) {
        if (std::find(drawing_layers.begin(), drawing_layers.end(), e.layer) == drawing_layers.end())
            drawing_layers.push_back(e.layer);
        if (e.closed) ++outlines[e.layer];
    }
    std::vector<std::string> unmapped;
    for (const auto& [layer, count] : outlines)
        if (!layers.contains(layer)) unmapped.push_back(fmt::format("'{}' ({} block{})", layer, count, count == 1 ? "" : "s"));
    if (!unmapped.empty())
        t.fail("layers", fmt::format("the drawing has closed outlines on layers not in [geometry.layers]: {}; give each "
                                     "layer its settings, or LAYER = {{ skip = true }} to leave it out",
                                     fmt::join(unmapped, ", ")));
    for (const auto& [layer, s] : layers) {
        if (s.skip || outlines.contains(layer)) continue;
        // The layer's entities are there but none is a closed outline: what is wrong with the
        // first (an open polyline: close it) is the message, not a missing layer.
        const auto drawn = std::find_if(drawing.entities.begin(), drawing.entities.end(),
                                        [&name = layer](const DrawingEntity& e) { return e.layer == name && !e.problem.empty(); });
        if (drawn != drawing.entities.end()) fail_entity(file, *drawn, drawn->problem);
        std::vector<std::string> others = drawing_layers;
        std::erase(others, layer);
        const std::string guess = nearest(layer, others);
        layer_table.fail(layer, fmt::format("the drawing has no closed outline on layer '{}'{}; its layers: {}", layer,
                                            guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess),
                                            drawing_layers.empty() ? "(none)" : fmt::format("{}", fmt::join(drawing_layers, ", "))));
    }
}

std::vector<BodyDef> read_geometry_entry(TableReader t, const fs::path& scenario_dir) {
    const std::string file_name = t.string("file");
    if (file_name.empty()) t.fail("file", "is empty: give a drawing file (.dxf or .txt)");
    const fs::path file = fs::path(file_name).is_absolute() ? fs::path(file_name) : scenario_dir / file_name;
    const std::string extension = file.extension().string();
    const std::string by_extension = extension == ".dxf" || extension == ".DXF" ? "dxf" : extension == ".txt" ? "text" : "";
    if (by_extension.empty() && !t.has("format"))
        t.fail_missing("format", fmt::format(" (\"dxf\" or \"text\": the extension '{}' does not say)", extension));
    const std::string format = t.choice("format", {"dxf", "text"}, by_extension);
    const std::string unit = t.choice("units", {"m", "cm", "mm"}, "");
    const std::string prefix = t.optional_string("prefix").value_or("");
    if (!prefix.empty() && !valid_body_name(prefix))
        t.fail("prefix", fmt::format("'{}' cannot start a body name: use letters, digits, '_' or '-'", prefix));
    TableReader layer_table = t.table("layers");
    std::map<std::string, LayerSettings> layers;
    for (const auto& [key, node] : layer_table.raw()) {
        const std::string layer(key.str());
        if (!node.is_table()) layer_table.fail(layer, "must be a table of the layer's settings, e.g. { kind = \"fixed\" }");
        layers[layer] = read_layer(layer_table.table(layer), layer);
    }
    if (layers.empty()) t.fail("layers", "names no layer: give each layer of blocks its settings");
    t.reject_unknown_keys();

    const std::string text = read_file_text(t, file);
    const Drawing drawing = format == "dxf" ? read_dxf(text, file.string()) : read_polygon_text(text, file.string());
    if (drawing.declared_units && *drawing.declared_units != unit)
        t.fail("units", fmt::format("is \"{}\", but the drawing '{}' declares its units as {} ($INSUNITS); give the "
                                    "drawing's units (m, cm or mm), or scale the drawing",
                                    unit, file.string(), *drawing.declared_units));
    check_layers(t, layer_table, drawing, file.string(), layers);
    return drawing_bodies(drawing, file.string(), unit, prefix, format == "text", layers);
}

}  // namespace

void read_geometry(TableReader& top, Model& model, const std::filesystem::path& scenario_dir) {
    std::set<std::string> names;
    for (const BodyDef& b : model.bodies) names.insert(b.name);
    for (const TableReader& t : top.table_array("geometry")) {
        for (BodyDef& b : read_geometry_entry(t, scenario_dir)) {
            if (!names.insert(b.name).second)
                t.fail("prefix", fmt::format("the drawn block '{}' has the name of another body; give this drawing a "
                                             "prefix (prefix = \"A_\")",
                                             b.name));
            model.bodies.push_back(std::move(b));
        }
    }
}

}  // namespace blockdem
