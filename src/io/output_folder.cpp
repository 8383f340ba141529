#include "io/output_folder.hpp"

#include <array>
#include <fstream>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

// The files and folders a run and its report write at the top of the folder.
constexpr std::array<const char*, 9> run_files = {"scenario.toml", "history.csv",   "energy.csv",
                                                  "summary.json",  "bodies.json",   "report.html",
                                                  "run_info.json", "sensors.csv",   "interfaces.csv"};
constexpr std::array<const char*, 3> run_subfolders = {"vtk", "figures", "state"};

bool is_run_summary(const fs::path& file) {
    std::ifstream in(file);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    return !j.is_discarded() && j.is_object() && j.contains("status") && j.contains("scenario");
}

bool is_scenario_copy(const fs::path& file) {
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    return first.starts_with(scenario_copy_marker);
}

bool has_extension(const fs::path& file, std::initializer_list<std::string_view> extensions) {
    const std::string ext = file.extension().string();
    for (std::string_view e : extensions)
        if (ext == e) return true;
    return false;
}

// vtk/: the frames and collections of VtkWriter; figures/: the report's images and animation;
// state/: the state files (io/state_file.hpp).
bool written_by_blockdem(const fs::path& subfolder, const fs::path& file) {
    const std::string name = file.filename().string();
    if (subfolder.filename() == "state")
        return name.starts_with("t_") && (name.ends_with("s.h5") || name.ends_with("s.h5.partial"));
    if (subfolder.filename() == "vtk")
        return ((name.starts_with("bodies_") || name.starts_with("contacts_")) && file.extension() == ".vtp") ||
               name == "bodies.pvd" || name == "contacts.pvd";
    return has_extension(file, {".png", ".svg", ".pdf", ".mp4", ".gif"});
}

void remove_or_fail(const fs::path& path) {
    std::error_code ec;
    fs::remove(path, ec);
    if (ec) throw InputError({path.string(), "", 0, 0}, "--force could not remove it: " + ec.message());
}

void remove_run_files(const fs::path& dir) {
    for (const char* name : run_files) remove_or_fail(dir / name);
    for (const char* name : run_subfolders) {
        const fs::path sub = dir / name;
        if (!fs::is_directory(sub)) continue;
        std::vector<fs::path> own;
        for (const auto& entry : fs::directory_iterator(sub))
            if (entry.is_regular_file() && written_by_blockdem(sub, entry.path())) own.push_back(entry.path());
        for (const fs::path& file : own) remove_or_fail(file);
        std::error_code ignored;
        if (fs::is_empty(sub, ignored)) fs::remove(sub, ignored);  // else it holds the user's files: kept
    }
}

std::vector<std::string> present_run_files(const fs::path& dir) {
    std::vector<std::string> present;
    for (const char* name : run_files)
        if (fs::exists(dir / name)) present.push_back(name);
    for (const char* name : run_subfolders)
        if (fs::exists(dir / name)) present.push_back(std::string(name) + "/");
    return present;
}

}  // namespace

bool holds_run(const fs::path& dir) {
    return (fs::is_regular_file(dir / "summary.json") && is_run_summary(dir / "summary.json")) ||
           (fs::is_regular_file(dir / "scenario.toml") && is_scenario_copy(dir / "scenario.toml"));
}

void prepare_output_folder(const fs::path& dir, bool force) {
    const InputLocation where{dir.string(), "", 0, 0};
    std::error_code ec;
    if (!fs::exists(dir)) {
        fs::create_directories(dir, ec);
        if (ec) throw InputError(where, "cannot create the output folder: " + ec.message());
        return;
    }
    if (!fs::is_directory(dir)) throw InputError(where, "--out names a file, not a folder");
    if (fs::exists(dir / "sweep.json"))
        throw InputError(where, "the folder holds a sweep (sweep.json); give `blockdem run` another --out");
    const std::vector<std::string> present = present_run_files(dir);
    if (holds_run(dir)) {
        if (!force)
            throw InputError(where, fmt::format("the folder holds an earlier run ({}); use --force to replace it, or "
                                                "another --out", fmt::join(present, ", ")));
        remove_run_files(dir);
        return;
    }
    // Not a run folder: blockdem's names there belong to someone else, and --force does not
    // remove files it did not write.
    if (!present.empty())
        throw InputError(where, fmt::format("the folder holds {}, not written by blockdem run; it would be overwritten: "
                                            "give another --out", fmt::join(present, ", ")));
}

}  // namespace blockdem
