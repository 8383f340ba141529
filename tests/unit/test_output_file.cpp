// OutputFile: every write and close is checked, the error names the file and the system's
// reason, and a write that fails part-way leaves only whole records (rows) in the file.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <string>

#include "io/output_file.hpp"

namespace blockdem {
namespace {

namespace fs = std::filesystem;

fs::path temporary(const std::string& name) {
    return fs::temp_directory_path() / ("blockdem-output-" + std::to_string(::getpid()) + "-" + name);
}

// A file-size limit (ulimit -f) for the scope, with SIGXFSZ ignored as blockdem's main does,
// so that write() fails with EFBIG instead of the process being killed.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        rlimit limited = saved_;
        limited.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limited);
        saved_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, saved_handler_);
    }

private:
    rlimit saved_{};
    void (*saved_handler_)(int) = SIG_DFL;
};

TEST(OutputFile, FullDiskNamesTheFileAndTheReason) {
    OutputFile out("/dev/full");
    out.append("t,x\n0,1\n");
    try {
        out.close();
        FAIL() << "writing to /dev/full succeeded";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()), std::string("/dev/full: cannot write: ") + std::strerror(ENOSPC));
    }
}

TEST(OutputFile, FailedWriteLeavesWholeRows) {
    const fs::path file = temporary("rows.csv");
    const std::string row(99, '7');  // 100 bytes with its newline: the limit falls inside a row
    bool failed = false;
    {
        FileSizeLimit limit(4050);
        OutputFile out(file);
        try {
            for (int k = 0; k < 100; ++k) {
                out.append(row + "\n");
                if (k % 7 == 6) out.flush();  // batches of 700 bytes: the 6th crosses the limit
            }
            out.close();
        } catch (const OutputError& e) {
            failed = true;
            EXPECT_NE(std::string(e.what()).find(file.string() + ": cannot write: " + std::strerror(EFBIG)), std::string::npos)
                << e.what();
        }
    }
    EXPECT_TRUE(failed);
    EXPECT_EQ(fs::file_size(file), 3500u);  // five whole batches; the torn sixth is cut off
    fs::remove(file);
}

TEST(OutputFile, WholeFileThatFailsIsRemoved) {
    const fs::path file = temporary("summary.json");
    {
        FileSizeLimit limit(1000);
        EXPECT_THROW(write_output_file(file, std::string(5000, 'x')), OutputError);
    }
    EXPECT_FALSE(fs::exists(file));
    write_output_file(file, "{}\n");
    EXPECT_EQ(fs::file_size(file), 3u);
    fs::remove(file);
}

TEST(OutputFile, AFailedWriteToADeviceLeavesTheDevice) {
    // `limit --json /dev/full` removed /dev/full (run as root), and every later writer made a plain
    // file there. A link to it stands for it here, so that the test cannot harm the machine.
    const fs::path link = temporary("full_link");
    fs::remove(link);
    fs::create_symlink("/dev/full", link);
    EXPECT_THROW(write_output_file(link, "{}\n"), OutputError);
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
    fs::remove(link);
}

// A device named as the output is the user's: a failed write to a full device (made here as
// /dev/full is, so that the test does not depend on the system's) leaves it a device. Removing it
// once turned /dev/full into a plain file that later writes filled without an error.
TEST(OutputFile, FailedWriteToADeviceKeepsTheDevice) {
    const fs::path device = temporary("full");
    if (::mknod(device.c_str(), S_IFCHR | 0666, ::makedev(1, 7)) != 0) GTEST_SKIP() << "cannot make a device node here";
    try {
        write_output_file(device, "{}\n");
        ADD_FAILURE() << "writing to a full device succeeded";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()), device.string() + ": cannot write: " + std::strerror(ENOSPC));
    }
    EXPECT_EQ(fs::symlink_status(device).type(), fs::file_type::character) << "the device was removed";
    fs::remove(device);
}

TEST(OutputFile, CannotCreateNamesTheFile) {
    try {
        OutputFile out("/nonexistent-folder/history.csv");
        FAIL() << "created a file in a folder that does not exist";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()), std::string("/nonexistent-folder/history.csv: cannot create: ") + std::strerror(ENOENT));
    }
}

}  // namespace
}  // namespace blockdem
