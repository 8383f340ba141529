// RunFolderLock (io/output_folder.hpp): a folder held by one run is refused to a second, also
// within one process (two Python Simulations into one out_dir), naming the folder and the pid;
// released, the folder can be taken again and run.lock is gone.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

struct TemporaryFolder {
    fs::path path = fs::temp_directory_path() / ("blockdem-lock-" + std::to_string(::getpid()));
    TemporaryFolder() { fs::create_directories(path); }
    ~TemporaryFolder() { fs::remove_all(path); }
};

// Taken twice in one process (a notebook cell run again while its first Simulation holds the
// folder): told that this process holds it. Another process's pid: cli/test_run_faults.sh.
TEST(RunFolderLock, SecondTakerInTheSameProcessIsToldSo) {
    TemporaryFolder dir;
    RunFolderLock held = RunFolderLock::take(dir.path);
    try {
        RunFolderLock second = RunFolderLock::take(dir.path);
        FAIL() << "a held folder was taken twice";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(dir.path.string()), std::string::npos) << message;
        EXPECT_NE(message.find("an earlier run of this process (not finished: finish() it or drop it first) is writing "
                               "in this folder"),
                  std::string::npos) << message;
    }
}

TEST(RunFolderLock, ReleasedFolderCanBeTakenAgainAndTheFileIsGone) {
    TemporaryFolder dir;
    { RunFolderLock held = RunFolderLock::take(dir.path); EXPECT_TRUE(fs::exists(dir.path / run_lock_name)); }
    EXPECT_FALSE(fs::exists(dir.path / run_lock_name));
    RunFolderLock again = RunFolderLock::take(dir.path);
    RunFolderLock moved = std::move(again);  // (the moved-from lock releases nothing)
    EXPECT_THROW(RunFolderLock::take(dir.path), InputError);
}

TEST(RunFolderLock, ForceDoesNotReplaceALiveRun) {
    TemporaryFolder dir;
    const fs::path out = dir.path / "out";
    RunFolderLock held = prepare_output_folder(out, false);
    EXPECT_THROW((void)prepare_output_folder(out, true), InputError);
}

}  // namespace
}  // namespace blockdem
