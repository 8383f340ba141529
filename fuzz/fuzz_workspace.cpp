#include "fuzz/fuzz_workspace.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace blockdem::fuzz {
namespace {

namespace fs = std::filesystem;

void link_if_present(const fs::path& target, const fs::path& link) {
    std::error_code ec;
    if (fs::exists(target, ec)) fs::create_directory_symlink(target, link);
}

Workspace make_workspace() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = (tmp && *tmp ? fs::path(tmp) : fs::temp_directory_path()).string() + "/blockdem-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a scratch folder under " + pattern);
    Workspace w;
    w.root = pattern;
    const fs::path source = BLOCKDEM_SOURCE_DIR;
    const fs::path repo = w.root / "repo";
    w.input_dir = repo / "examples" / "records";
    fs::create_directories(w.input_dir);
    for (const char* folder : {"paper", "assemblies", "dxf"}) link_if_present(source / "examples" / folder, repo / "examples" / folder);
    link_if_present(source / "tests", repo / "tests");
    link_if_present(source.parent_path() / "shared", w.root / "shared");
    return w;
}

void remove_workspace() {
    std::error_code ec;
    fs::remove_all(workspace().root, ec);  // links are removed, never followed
}

}  // namespace

const Workspace& workspace() {
    static const Workspace w = [] {
        Workspace made = make_workspace();
        return made;
    }();
    static const bool cleanup_registered = (std::atexit(remove_workspace), true);
    (void)cleanup_registered;
    return w;
}

std::filesystem::path write_input(std::string_view name, const std::uint8_t* data, std::size_t size) {
    const fs::path path = workspace().input_dir / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("cannot write " + path.string());
    return path;
}

}  // namespace blockdem::fuzz
