#include "io/run_budget.hpp"

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/vtk_writer.hpp"
#include "world/simulation.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

// A number as the writers print it ({:.9g} to {:.12g}) with its comma: about 16 characters.
constexpr double bytes_per_value = 16.0;
constexpr double history_values_per_body = 9.0;
constexpr double energy_values = 10.0;
// Besides the world: the writers' buffers, the monitor, the program itself.
constexpr double fixed_memory_bytes = 64.0e6;

// MemAvailable of /proc/meminfo (what can be had without swapping), else free pages.
double available_memory_bytes() {
    std::ifstream in("/proc/meminfo");
    for (std::string line; std::getline(in, line);) {
        if (!line.starts_with("MemAvailable:")) continue;
        std::istringstream fields(line.substr(13));
        double kib = 0.0;
        if (fields >> kib) return kib * 1024.0;
    }
    return static_cast<double>(sysconf(_SC_AVPHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// Free space where out_dir is or will be (its nearest existing ancestor).
double free_disk_bytes(const fs::path& out_dir) {
    fs::path at = fs::absolute(out_dir);
    while (!fs::exists(at) && at.has_parent_path() && at.parent_path() != at) at = at.parent_path();
    std::error_code ec;
    const fs::space_info space = fs::space(at, ec);
    return ec ? INFINITY : static_cast<double>(space.available);
}

std::int64_t recorded_bodies(const World& w) {
    std::int64_t n = 0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) n += w.bodies.record[i] ? 1 : 0;
    return n;
}

}  // namespace

std::string byte_text(double bytes) {
    if (bytes >= 1e12) return fmt::format("{:.3g} TB", bytes / 1e12);
    if (bytes >= 1e9) return fmt::format("{:.3g} GB", bytes / 1e9);
    if (bytes >= 1e6) return fmt::format("{:.3g} MB", bytes / 1e6);
    if (bytes >= 1e3) return fmt::format("{:.3g} kB", bytes / 1e3);
    return fmt::format("{:.0f} B", bytes);
}

RunBudget estimate_run_budget(const LoadedScenario& s, bool vtk) {
    const World& w = s.world;
    RunBudget b;
    b.steps = w.settings.duration_s / w.dt_s;
    const double steps_per_row = std::max(1.0, std::round(w.settings.output_interval_s / w.dt_s));
    b.rows = std::floor(b.steps / steps_per_row) + 2.0;
    b.history_bytes = b.rows * bytes_per_value * (1.0 + history_values_per_body * static_cast<double>(recorded_bodies(w)));
    b.energy_bytes = b.rows * bytes_per_value * energy_values;
    double frame_bytes = 0.0;
    if (vtk) {
        b.vtk_frames = std::floor(w.settings.duration_s / s.output.vtk_interval_s + 1e-9) + 1.0;
        frame_bytes = static_cast<double>(vtk_bodies_polydata(w).size());
        if (s.output.vtk_contacts) frame_bytes += static_cast<double>(vtk_contacts_polydata(w).size());
        b.vtk_bytes = b.vtk_frames * frame_bytes;
    }
    b.files = 6.0 + b.vtk_frames * (s.output.vtk_contacts ? 2.0 : 1.0);
    // The world, one frame's text at a time, and the time of every frame (for the .pvd).
    b.memory_bytes = static_cast<double>(memory_bytes(w)) + 2.0 * frame_bytes + 8.0 * b.vtk_frames + fixed_memory_bytes;
    return b;
}

void check_step_count(const LoadedScenario& s) {
    const World& w = s.world;
    const double steps = w.settings.duration_s / w.dt_s;
    if (!(steps <= max_steps))
        throw InputError({s.file.string(), "simulation.duration", 0, 0},
                         fmt::format("{:g} s is {:.3g} steps of dt = {:.3g} s, more than a run can count ({:.3g}); "
                                     "give a shorter duration", w.settings.duration_s, steps, w.dt_s, max_steps));
    const double frames = w.settings.duration_s / s.output.vtk_interval_s;
    if (s.output.vtk.value_or(true) && !(frames <= max_steps))
        throw InputError({s.file.string(), "output.vtk_interval", 0, 0},
                         fmt::format("{:g} s gives {:.3g} VTK frames, more than a run can count; give a longer "
                                     "interval", s.output.vtk_interval_s, frames));
}

std::vector<std::string> check_run_budget(const LoadedScenario& s, const RunBudget& b, const fs::path& out_dir) {
    const std::string file = s.file.string();
    const double memory = available_memory_bytes();
    if (b.memory_bytes > memory)
        throw InputError({file, b.vtk_frames > 1e6 ? "output.vtk_interval" : "simulation.duration", 0, 0},
                         fmt::format("the run would need about {} of memory ({:.3g} VTK frames), more than the {} "
                                     "available; shorten simulation.duration or raise output.vtk_interval",
                                     byte_text(b.memory_bytes), b.vtk_frames, byte_text(memory)));
    const std::string breakdown =
        fmt::format("history.csv {} ({:.3g} rows), energy.csv {}{}", byte_text(b.history_bytes), b.rows,
                    byte_text(b.energy_bytes),
                    b.vtk_frames > 0 ? fmt::format(", vtk/ {} ({:.3g} frames)", byte_text(b.vtk_bytes), b.vtk_frames) : "");
    const double disk = free_disk_bytes(out_dir);
    // Nothing free at all is the place, not the run's length (a full disk, /proc): named as such.
    if (disk <= 0.0)
        throw InputError({out_dir.string(), "", 0, 0},
                         "the output folder's disk has no free space (0 B): give --out a folder on a disk that can hold the run's files");
    if (b.output_bytes() > disk)
        throw InputError({file, "simulation.duration", 0, 0},
                         fmt::format("the run would write about {} ({}), more than the {} free where {} is; shorten "
                                     "simulation.duration or raise simulation.output_interval / output.vtk_interval",
                                     byte_text(b.output_bytes()), breakdown, byte_text(disk), out_dir.string()));
    std::vector<std::string> warnings;
    if (b.output_bytes() > large_output_bytes || b.files > static_cast<double>(large_output_files))
        warnings.push_back(fmt::format("this run will write about {} in {:.0f} files ({}); raise "
                                       "simulation.output_interval or output.vtk_interval, or set output.vtk = false, "
                                       "to write less",
                                       byte_text(b.output_bytes()), b.files, breakdown));
    return warnings;
}

}  // namespace blockdem
