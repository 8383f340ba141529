#include "io/run_restart.hpp"

#include <algorithm>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/output_file.hpp"

namespace blockdem {

namespace fs = std::filesystem;

RestartFolders restart_folders(const fs::path& state_file, const StateFileInfo& info, const fs::path& scenario,
                               const fs::path& out_dir) {
    const fs::path dir = fs::absolute(state_file).lexically_normal().parent_path();
    const bool in_run_folder = dir.filename() == "state";
    RestartFolders f;
    f.run_folder = in_run_folder ? dir.parent_path() : fs::path(info.run_folder);
    f.scenario = scenario.empty() ? f.run_folder / "scenario.toml" : scenario;
    f.out_dir = out_dir.empty() && in_run_folder ? f.run_folder : out_dir;
    if (f.out_dir.empty())
        throw InputError({state_file.string(), "", 0, 0},
                         fmt::format("the state is not in a run folder's state/ folder, so it has no folder to go on in: "
                                     "give --out (the rows before the state are read from {}, where it was written)",
                                     f.run_folder.string()));
    if (scenario.empty() && !fs::exists(f.scenario))
        throw InputError({f.scenario.string(), "", 0, 0},
                         fmt::format("missing: the run folder of state {} has no scenario.toml (the scenario as run); "
                                     "give the scenario on the command line",
                                     state_file.string()));
    return f;
}

namespace {

std::ifstream open_to_continue(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError({file.string(), "", 0, 0}, "cannot open it to continue the run (the state's run folder "
                                                         "must still hold it)");
    return in;
}

// The lines before the first row: the comment lines ('#') and the header.
std::int64_t header_lines(const fs::path& file) {
    std::ifstream in = open_to_continue(file);
    std::int64_t lines = 1;
    std::string line;
    while (std::getline(in, line) && line.starts_with('#')) ++lines;
    return lines;
}

// Bytes of the header and the first `rows` rows, or -1 with *found rows when the file has fewer.
std::int64_t bytes_of_rows(const fs::path& file, std::int64_t header, std::int64_t rows, std::int64_t* found) {
    std::ifstream in = open_to_continue(file);
    const std::int64_t lines = header + rows;
    std::int64_t seen = 0, bytes = 0;
    std::vector<char> chunk(1 << 16);
    while (seen < lines && in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const std::streamsize got = in.gcount();
        for (std::streamsize i = 0; i < got; ++i) {
            if (chunk[static_cast<std::size_t>(i)] != '\n') continue;
            if (++seen == lines) {
                bytes += i + 1;
                return bytes;
            }
        }
        bytes += got;
    }
    *found = std::max<std::int64_t>(0, seen - header);
    return -1;
}

void keep_bytes(const fs::path& from, const fs::path& to, std::int64_t header, std::int64_t rows) {
    std::int64_t found = 0;
    const std::int64_t bytes = bytes_of_rows(from, header, rows, &found);
    if (bytes < 0)
        throw InputError({from.string(), "", 0, 0},
                         fmt::format("has {} rows, the state file counts {} before its time: these are not the files "
                                     "of the run the state was saved in", found, rows));
    std::error_code ec;
    if (fs::exists(to) && fs::equivalent(from, to, ec)) {
        fs::resize_file(from, static_cast<std::uintmax_t>(bytes), ec);
        if (ec) throw OutputError(fmt::format("{}: cannot cut it back to the state's time: {}", from.string(), ec.message()));
        return;
    }
    std::ifstream in(from, std::ios::binary);
    OutputFile out(to);
    std::vector<char> chunk(1 << 16);
    std::int64_t left = bytes;
    while (left > 0 && in) {
        in.read(chunk.data(), static_cast<std::streamsize>(std::min<std::int64_t>(left, static_cast<std::int64_t>(chunk.size()))));
        out.append(std::string_view(chunk.data(), static_cast<std::size_t>(in.gcount())));
        left -= in.gcount();
    }
    out.close();
}

}  // namespace

void keep_first_rows(const fs::path& from, const fs::path& to, std::int64_t rows) { keep_bytes(from, to, 1, rows); }

void keep_rows_after_comments(const fs::path& from, const fs::path& to, std::int64_t rows) {
    keep_bytes(from, to, header_lines(from), rows);
}

}  // namespace blockdem
