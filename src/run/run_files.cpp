#include "run/run_files.hpp"

#include <sstream>
#include <system_error>

#include <toml++/toml.h>

#include "io/output_file.hpp"

namespace blockdem {

namespace fs = std::filesystem;

nlohmann::json run_info_json(const std::string& status, const RunInvocation& run) {
    const auto absolute_or_null = [](const fs::path& p) { return p.empty() ? nlohmann::json(nullptr) : nlohmann::json(fs::absolute(p).string()); };
    return nlohmann::json{{"status", status},
                          {"wall_time_s", run.wall_s},
                          {"started_at_time_s", run.started_at_time_s},
                          {"restarted_from", absolute_or_null(run.restarted_from)},
                          {"initial_state", absolute_or_null(run.initial_state)},
                          {"state_files", run.state_files}};
}

std::string without_duration(const std::string& scenario_toml) {
    try {
        toml::table root = toml::parse(scenario_toml);
        if (auto* simulation = root["simulation"].as_table()) simulation->erase("duration");
        std::ostringstream text;
        text << root;
        return text.str();
    } catch (const toml::parse_error&) {
        return scenario_toml;  // (not a scenario: it differs from any)
    }
}

void copy_vtk_frames(const fs::path& from, const fs::path& to, std::int64_t frames, const std::vector<std::string>& kinds) {
    for (std::int64_t i = 0; i < frames; ++i)
        for (const std::string& kind : kinds) {
            const fs::path file = from / fmt::format("{}_{:06d}.vtp", kind, i);
            if (!fs::exists(file)) continue;  // (contacts = false)
            std::error_code ec;
            fs::copy_file(file, to / file.filename(), fs::copy_options::overwrite_existing, ec);
            if (ec) throw OutputError(fmt::format("{}: cannot copy it to {}: {}", file.string(), to.string(), ec.message()));
        }
}

void check_state_dimension(const StateFile& state, int dimension) {
    if (state.dimension() == dimension) return;
    const char* python_class = state.dimension() == 3 ? "blockdem.Simulation3d" : "blockdem.Simulation";
    throw InputError({state.path().string(), "", 0, 0},
                     fmt::format("a {0}-D state: a {1}-D run cannot go on from it (`blockdem run --restart` goes on in "
                                 "{0}-D; in Python, {2}.from_state)",
                                 state.dimension(), dimension, python_class));
}

}  // namespace blockdem
