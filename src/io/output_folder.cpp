#include "io/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
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

namespace {

std::string lock_holder(int fd) {
    char text[32] = {};
    const ssize_t got = pread(fd, text, sizeof text - 1, 0);
    const std::string pid = got > 0 ? std::string(text, static_cast<std::size_t>(got)) : std::string();
    if (pid.empty()) return "a run whose pid is not known";
    // A notebook cell run twice makes its new run while the old object still holds the folder.
    if (pid == std::to_string(getpid()))
        return "an earlier run of this process (not finished: finish() it or drop it first)";
    return "the run of pid " + pid;
}

// Whether the file at path is still the one open as fd: a holder that released the lock unlinks
// it, and a lock on the unlinked file would hold nothing.
bool same_file(int fd, const fs::path& path) {
    struct stat open_file {}, named {};
    return fstat(fd, &open_file) == 0 && stat(path.c_str(), &named) == 0 && open_file.st_dev == named.st_dev &&
           open_file.st_ino == named.st_ino;
}

}  // namespace

RunFolderLock RunFolderLock::take(const fs::path& dir) {
    const fs::path file = dir / run_lock_name;
    const InputLocation where{dir.string(), "", 0, 0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) throw InputError(where, fmt::format("cannot create the lock file {}: {}", run_lock_name, std::strerror(errno)));
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            // Only EWOULDBLOCK is a holder. A filesystem without locks (Lustre mounted without
            // flock, NFS without lockd: ENOSYS, ENOLCK, EOPNOTSUPP) refused every run into it
            // for good: the run goes on there unlocked, as runs did before the lock.
            if (errno != EWOULDBLOCK) {
                close(fd);
                std::error_code ignored;
                fs::remove(file, ignored);
                return RunFolderLock();
            }
            const std::string holder = lock_holder(fd);
            close(fd);
            throw InputError(where, fmt::format("{} is writing in this folder ({} is locked); wait for it or stop it, or "
                                                "give another --out (--force does not replace a live run)",
                                                holder, run_lock_name));
        }
        if (!same_file(fd, file)) {  // taken just as its holder let it go: take the new one
            close(fd);
            continue;
        }
        const std::string pid = std::to_string(getpid());
        if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
            close(fd);
            throw InputError(where, fmt::format("cannot write the lock file {}: {}", run_lock_name, std::strerror(errno)));
        }
        RunFolderLock lock;
        lock.fd_ = fd;
        lock.file_ = file;
        return lock;
    }
    throw InputError(where, fmt::format("cannot take the lock file {}: other runs keep taking it", run_lock_name));
}

void RunFolderLock::release() noexcept {
    if (fd_ < 0) return;
    // Unlinked while still held, so that no one locks the file about to go.
    std::error_code ignored;
    fs::remove(file_, ignored);
    close(fd_);
    fd_ = -1;
}

RunFolderLock::RunFolderLock(RunFolderLock&& other) noexcept : fd_(other.fd_), file_(std::move(other.file_)) { other.fd_ = -1; }

RunFolderLock& RunFolderLock::operator=(RunFolderLock&& other) noexcept {
    if (this != &other) {
        release();
        fd_ = other.fd_;
        file_ = std::move(other.file_);
        other.fd_ = -1;
    }
    return *this;
}

RunFolderLock::~RunFolderLock() { release(); }

RunFolderLock prepare_output_folder(const fs::path& dir, bool force) {
    const InputLocation where{dir.string(), "", 0, 0};
    std::error_code ec;
    if (!fs::exists(dir)) {
        fs::create_directories(dir, ec);
        if (ec) throw InputError(where, "cannot create the output folder: " + ec.message());
        return RunFolderLock::take(dir);
    }
    if (!fs::is_directory(dir)) throw InputError(where, "--out names a file, not a folder");
    if (fs::exists(dir / "sweep.json"))
        throw InputError(where, "the folder holds a sweep (sweep.json); give `blockdem run` another --out");
    // (Before anything is removed: a live run's files are its own.)
    RunFolderLock lock = RunFolderLock::take(dir);
    const std::vector<std::string> present = present_run_files(dir);
    if (holds_run(dir)) {
        if (!force)
            throw InputError(where, fmt::format("the folder holds an earlier run ({}); use --force to replace it, or "
                                                "another --out", fmt::join(present, ", ")));
        remove_run_files(dir);
        return lock;
    }
    // Not a run folder: blockdem's names there belong to someone else, and --force does not
    // remove files it did not write.
    if (!present.empty())
        throw InputError(where, fmt::format("the folder holds {}, not written by blockdem run; it would be overwritten: "
                                            "give another --out", fmt::join(present, ", ")));
    return lock;
}

}  // namespace blockdem
