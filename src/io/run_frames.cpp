#include "io/run_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "io/state_file.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError({file.string(), "", 0, 0}, "cannot open the file");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The frames vtk/bodies.pvd lists: <DataSet timestep="T" ... file="bodies_NNNNNN.vtp"/>.
std::vector<RunFrame> vtk_frames(const fs::path& run_dir) {
    const fs::path pvd = run_dir / "vtk" / "bodies.pvd";
    if (!fs::is_regular_file(pvd)) return {};
    const std::string text = file_text(pvd);
    static const std::regex data_set(R"re(<DataSet timestep="([^"]+)"[^>]*file="([^"]+)")re");
    std::vector<RunFrame> frames;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), data_set); it != std::sregex_iterator(); ++it) {
        RunFrame f;
        f.time_s = std::strtod((*it)[1].str().c_str(), nullptr);
        f.file = run_dir / "vtk" / (*it)[2].str();
        frames.push_back(f);
    }
    return frames;
}

// The state files state/t_<time>s.h5 (io/state_file.hpp: state_file_name).
std::vector<RunFrame> state_frames(const fs::path& run_dir) {
    std::vector<RunFrame> frames;
    std::error_code error;
    if (!fs::is_directory(run_dir / "state", error)) return frames;
    static const std::regex name(R"(t_([0-9.eE+-]+)s\.h5)");
    for (const auto& entry : fs::directory_iterator(run_dir / "state", error)) {
        std::smatch m;
        const std::string file_name = entry.path().filename().string();
        if (!entry.is_regular_file() || !std::regex_match(file_name, m, name)) continue;
        frames.push_back({std::strtod(m[1].str().c_str(), nullptr), entry.path(), true});
    }
    return frames;
}

// The numbers between the opening tag of the DataArray named name and its end.
std::vector<double> data_array(const std::string& text, const std::string& name, const fs::path& file) {
    const std::size_t at = text.find(fmt::format("Name=\"{}\"", name));
    const std::size_t begin = at == std::string::npos ? at : text.find('>', at);
    const std::size_t end = begin == std::string::npos ? begin : text.find("</DataArray>", begin);
    if (end == std::string::npos) throw InputError({file.string(), "", 0, 0}, fmt::format("no DataArray '{}' in the frame", name));
    std::vector<double> values;
    const char* p = text.data() + begin + 1;
    const char* stop = text.data() + end;
    while (true) {
        char* next = nullptr;
        const double v = std::strtod(p, &next);
        if (next == p || next > stop) break;
        values.push_back(v);
        p = next;
    }
    return values;
}

// A body as bodies.json gives it: its name, its layer, its centroid at t = 0 and its corners
// about the centroid at rotation 0.
struct BodyLabel {
    std::string name;
    std::string layer;
    Vec2 initial_centroid_m;          ///< [m]
    std::vector<Vec2> corners_m;      ///< [m]
};

std::vector<BodyLabel> body_labels(const fs::path& run_dir) {
    const fs::path file = run_dir / "bodies.json";
    if (!fs::is_regular_file(file)) {
        // A 3-D run writes no bodies.json: say that, not that the folder is no run's.
        const fs::path summary = run_dir / "summary.json";
        const nlohmann::json s = fs::is_regular_file(summary) ? nlohmann::json::parse(file_text(summary), nullptr, false) : nlohmann::json();
        if (s.is_object() && s.value("dimension", 2) == 3)
            throw InputError({run_dir.string(), "", 0, 0},
                             "a 3-D run: its drawings are 2-D (polylines of each block's outline); its bodies are in the "
                             "VTK frames (vtk/bodies.pvd) for ParaView");
        throw InputError({file.string(), "", 0, 0}, "no bodies.json: is this the output folder of a blockdem run?");
    }
    std::vector<BodyLabel> labels;
    try {
        const nlohmann::json j = nlohmann::json::parse(file_text(file));
        for (const nlohmann::json& b : j.at("bodies")) {
            const std::string assembly = b.value("assembly", "");
            BodyLabel label{b.at("name").get<std::string>(), assembly.empty() ? b.at("kind").get<std::string>() : assembly,
                            {b.at("initial_centroid_m").at(0).get<double>(), b.at("initial_centroid_m").at(1).get<double>()},
                            {}};
            for (const nlohmann::json& c : b.at("corners_m")) label.corners_m.push_back({c.at(0).get<double>(), c.at(1).get<double>()});
            labels.push_back(std::move(label));
        }
    } catch (const nlohmann::json::exception& e) {
        throw InputError({file.string(), "", 0, 0}, fmt::format("not a bodies.json written by blockdem: {}", e.what()));
    }
    return labels;
}

// Corners at t from the body's position and rotation at t (a body's corners as the writers keep
// them are those of the last contact detection, a step behind).
std::vector<Vec2> corners_at(const std::vector<Vec2>& local_m, Vec2 position_m, double rotation_rad) {
    const Rotation r = Rotation::from_angle(rotation_rad);
    std::vector<Vec2> out;
    for (const Vec2& c : local_m) out.push_back(position_m + r.apply(c));
    return out;
}

// A VTK frame's cell data: each body's displacement since t = 0 and rotation, to 9 digits.
std::vector<std::vector<Vec2>> vtk_corners(const RunFrame& frame, const std::vector<BodyLabel>& labels) {
    const std::string text = file_text(frame.file);
    const std::vector<double> displacement = data_array(text, "displacement_m", frame.file);
    const std::vector<double> rotation = data_array(text, "rotation_rad", frame.file);
    if (rotation.size() != labels.size() || displacement.size() != 3 * labels.size())
        throw InputError({frame.file.string(), "", 0, 0},
                         fmt::format("the frame has {} bodies, bodies.json {}", rotation.size(), labels.size()));
    std::vector<std::vector<Vec2>> corners;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const Vec2 position = labels[i].initial_centroid_m + Vec2{displacement[3 * i], displacement[3 * i + 1]};
        corners.push_back(corners_at(labels[i].corners_m, position, rotation[i]));
    }
    return corners;
}

// A state file's positions and rotations (exact) with its own corners about the centroid.
std::vector<std::vector<Vec2>> state_corners(const RunFrame& frame, const std::vector<BodyLabel>& labels) {
    const StateFile state(frame.file);
    const WorldState& w = state.world();
    if (w.name.size() != labels.size())
        throw InputError({frame.file.string(), "", 0, 0},
                         fmt::format("the state file has {} bodies, bodies.json {}", w.name.size(), labels.size()));
    std::vector<std::vector<Vec2>> corners;
    std::size_t k = 0;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        if (w.name[i] != labels[i].name)
            throw InputError({frame.file.string(), "", 0, 0},
                             fmt::format("body {} is '{}' here but '{}' in bodies.json: not the same run", i, w.name[i], labels[i].name));
        const std::vector<Vec2> local(w.local_vertices_m.begin() + static_cast<std::ptrdiff_t>(k),
                                      w.local_vertices_m.begin() + static_cast<std::ptrdiff_t>(k + w.vertex_count[i]));
        k += w.vertex_count[i];
        corners.push_back(corners_at(local, w.position_m[i], w.rotation_rad[i]));
    }
    return corners;
}

}  // namespace

std::vector<RunFrame> run_frames(const fs::path& run_dir) {
    if (!fs::is_directory(run_dir)) throw InputError({run_dir.string(), "", 0, 0}, "no such run folder");
    std::vector<RunFrame> frames = vtk_frames(run_dir);
    for (RunFrame& f : state_frames(run_dir)) frames.push_back(f);
    if (frames.empty())
        throw InputError({run_dir.string(), "", 0, 0},
                         "the run saved no blocks to export: no VTK frames (vtk/bodies.pvd) and no state files "
                         "(state/*.h5); run with [output] vtk or --save-state");
    std::stable_sort(frames.begin(), frames.end(), [](const RunFrame& a, const RunFrame& b) {
        return a.time_s < b.time_s || (a.time_s == b.time_s && !a.state_file && b.state_file);
    });
    return frames;
}

const RunFrame& nearest_frame(const std::vector<RunFrame>& frames, std::optional<double> t_s) {
    if (!t_s) return frames.back();
    const RunFrame* best = &frames.front();
    for (const RunFrame& f : frames)
        if (std::abs(f.time_s - *t_s) < std::abs(best->time_s - *t_s) ||
            (std::abs(f.time_s - *t_s) == std::abs(best->time_s - *t_s) && f.state_file))
            best = &f;
    return *best;
}

std::vector<LayerPolygon> frame_blocks(const fs::path& run_dir, const RunFrame& frame) {
    const std::vector<BodyLabel> labels = body_labels(run_dir);
    const std::vector<std::vector<Vec2>> corners =
        frame.state_file ? state_corners(frame, labels) : vtk_corners(frame, labels);
    std::vector<LayerPolygon> blocks;
    for (std::size_t i = 0; i < labels.size(); ++i) blocks.push_back({labels[i].layer, corners[i]});
    return blocks;
}

}  // namespace blockdem
