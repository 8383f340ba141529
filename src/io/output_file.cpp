#include "io/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace blockdem {
namespace {

// Large enough that a row costs no system call, small enough that a killed run loses little.
constexpr std::size_t flush_threshold_bytes = 64 * 1024;

}  // namespace

OutputFile::OutputFile(std::filesystem::path file, Mode mode) : file_(std::move(file)) {
    const int truncate = mode == Mode::replace ? O_TRUNC : 0;
    fd_ = ::open(file_.c_str(), O_WRONLY | O_CREAT | truncate | O_CLOEXEC, 0644);
    if (fd_ < 0) fail(mode == Mode::replace ? "cannot create" : "cannot open", errno);
    if (mode == Mode::append) {
        // What is there already counts as complete: a failed write cuts back to it, never into it.
        const off_t end = ::lseek(fd_, 0, SEEK_END);
        if (end < 0) fail("cannot open", errno);
        written_bytes_ = end;
    }
}

OutputFile::~OutputFile() {
    if (fd_ >= 0) ::close(fd_);  // only after an error: close() reports its own
}

void OutputFile::fail(const char* what, int error_number) {
    throw OutputError(fmt::format("{}: {}: {}", file_.string(), what, std::strerror(error_number)));
}

void OutputFile::append(std::string_view records) {
    buffer_.append(records);
    if (buffer_.size() >= flush_threshold_bytes) flush();
}

void OutputFile::flush() {
    if (fd_ < 0 || buffer_.empty()) return;
    std::size_t done = 0;
    while (done < buffer_.size()) {
        const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error_number = n < 0 ? errno : EIO;
            // A torn row would make the whole file unreadable for a CSV reader: cut it off.
            if (::ftruncate(fd_, static_cast<off_t>(written_bytes_)) == 0) ::lseek(fd_, written_bytes_, SEEK_SET);
            buffer_.clear();
            fail("cannot write", error_number);
        }
        done += static_cast<std::size_t>(n);
    }
    written_bytes_ += static_cast<long long>(buffer_.size());
    buffer_.clear();
}

void OutputFile::close() {
    if (fd_ < 0) return;
    flush();
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("cannot close", errno);
}

void write_output_file(const std::filesystem::path& file, std::string_view text) {
    try {
        OutputFile out(file);
        out.append(text);
        out.close();
    } catch (const OutputError&) {
        // Half a JSON or VTK file is worse than none; but a device, a pipe or a link named as the
        // output is the user's, not a half-written file: removing /dev/full once made it a plain
        // file that the next write filled without an error.
        std::error_code ignored;
        if (std::filesystem::symlink_status(file, ignored).type() == std::filesystem::file_type::regular)
            std::filesystem::remove(file, ignored);
        throw;
    }
}

}  // namespace blockdem
