#pragma once
// The --out folder of `blockdem run`. A folder that already holds a run is refused, so that a
// new run never mixes its files with the stale ones of another (VTK frames, report, summary);
// --force first removes blockdem's own files from it, and nothing else. A folder is a run
// folder when its summary.json is a run summary or its scenario.toml carries the line blockdem
// writes at its top (scenario_copy_marker). A folder that holds no run may hold anything else,
// as long as no file there has a name blockdem writes (that file would be overwritten).
#include <filesystem>
#include <string>

namespace blockdem {

/// The first line of the scenario.toml that `blockdem run` writes into its folder.
inline constexpr const char* scenario_copy_marker = "# written by blockdem run: the scenario as run";

/// The lock file of a folder a run (or a sweep) writes in.
inline constexpr const char* run_lock_name = "run.lock";

/// A folder held by this process while it writes there, so that a second run into it is refused
/// even with --force (its files would mix with this run's). The lock is flock(2) on
/// DIR/run.lock, which holds the pid: the kernel releases it when the process ends, however it
/// ends, so a killed run leaves no folder locked (only a stale run.lock, taken over by the next
/// run). The file is removed when the lock is released. Move-only; empty: holds nothing.
class RunFolderLock {
public:
    RunFolderLock() = default;
    RunFolderLock(RunFolderLock&& other) noexcept;
    RunFolderLock& operator=(RunFolderLock&& other) noexcept;
    RunFolderLock(const RunFolderLock&) = delete;
    RunFolderLock& operator=(const RunFolderLock&) = delete;
    ~RunFolderLock();

    /// Takes the lock of dir (which must exist). Throws InputError naming dir, and the pid of the
    /// live run when it is known, when another process (or another run of this one) holds it.
    /// On a filesystem that gives no locks (flock failing otherwise than EWOULDBLOCK: some NFS
    /// and Lustre mounts) it holds nothing, and the run goes on unlocked.
    static RunFolderLock take(const std::filesystem::path& dir);

private:
    void release() noexcept;
    int fd_ = -1;
    std::filesystem::path file_;
};

/// Creates dir, or makes an existing one ready for a new run (see above), and holds it for the
/// run. Throws InputError naming the folder and the file when it refuses, and naming the live
/// run when another run writes in the folder (--force or not).
[[nodiscard]] RunFolderLock prepare_output_folder(const std::filesystem::path& dir, bool force);

/// Whether dir holds a run of blockdem (its summary.json or scenario.toml).
bool holds_run(const std::filesystem::path& dir);

}  // namespace blockdem
