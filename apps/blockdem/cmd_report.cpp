// `blockdem report DIR`: the figures (DIR/figures/) and the self-contained DIR/report.html of a
// run folder. They are made by the Python tools (tools/blockdem_report.py, Debian's matplotlib),
// run as a child process, so that neither this tool's build nor the library needs them.
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"

extern char** environ;

namespace blockdem::cli {
namespace {

namespace fs = std::filesystem;

std::string from_env(const char* name, const std::string& fallback) {
    const char* value = std::getenv(name);
    return value && *value ? std::string(value) : fallback;
}

// Where tools/ is: $BLOCKDEM_TOOLS_DIR, else the source tree this binary was built from.
fs::path tools_dir() {
#ifdef BLOCKDEM_TOOLS_DIR
    return from_env("BLOCKDEM_TOOLS_DIR", BLOCKDEM_TOOLS_DIR);
#else
    return from_env("BLOCKDEM_TOOLS_DIR", "tools");
#endif
}

// Runs argv[0] with the arguments and waits; returns its exit status.
int run_child(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (const int err = posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ); err != 0)
        throw std::runtime_error(fmt::format("cannot start {}: {} (install the view packages: make deps-view)", args[0],
                                             std::strerror(err)));
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) throw std::runtime_error("lost the report process");
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

void write_report(const std::string& out_dir, bool animation_file, const std::string& formats) {
    const fs::path script = tools_dir() / "blockdem_report.py";
    if (!fs::is_regular_file(script))
        throw std::runtime_error(fmt::format("{} not found (set BLOCKDEM_TOOLS_DIR to the tools/ folder)", script.string()));
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    // Debian's python3 (with python3-matplotlib), not whichever python3 comes first on PATH.
    std::vector<std::string> args = {from_env("BLOCKDEM_PYTHON", "/usr/bin/python3"), script.string(), out_dir};
    if (!ec) args.insert(args.end(), {"--blockdem", self.string()});
    if (!animation_file) args.push_back("--no-animation");
    args.insert(args.end(), {"--formats", formats});
    const int status = run_child(args);
    if (status == 2) throw InputError({out_dir, "", 0, 0}, "no report for this folder (see the message above)");
    if (status == 4) throw OutputError(fmt::format("{}: the report could not be written (see the message above)", out_dir));
    if (status != 0)
        throw std::runtime_error(fmt::format("the report was not written ({} exited with status {})", script.string(), status));
}

void add_report_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("report", "Write DIR/report.html and the figures of a run folder");
    auto dir = std::make_shared<std::string>();
    auto no_animation = std::make_shared<bool>(false);
    auto formats = std::make_shared<std::string>(default_figure_formats);
    cmd->add_option("dir", *dir, "output folder of `blockdem run`")->required();
    cmd->add_flag("--no-animation", *no_animation, "skip the MP4/GIF file (the report animates anyway)");
    cmd->add_option("--formats", *formats,
                    "figure files written beside the report, comma-separated from png, svg, pdf (png always; "
                    "--formats png skips the vector copies, about a third of the report's time)")
        ->check(CLI::Validator(
            [](const std::string& value) -> std::string {
                std::size_t start = 0;
                while (start <= value.size()) {
                    const std::size_t end = std::min(value.find(',', start), value.size());
                    const std::string format = value.substr(start, end - start);
                    if (format != "png" && format != "svg" && format != "pdf")
                        return fmt::format("unknown figure format '{}' (png, svg, pdf)", format);
                    start = end + 1;
                }
                return {};
            },
            "FORMAT[,FORMAT...]"))
        ->capture_default_str();
    cmd->callback([=] { write_report(*dir, !*no_animation, *formats); });
}

}  // namespace blockdem::cli
