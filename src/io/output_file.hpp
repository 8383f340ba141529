#pragma once
// Every file a run writes goes through OutputFile, so that a full disk, a file-size limit
// (ulimit -f) or an I/O error stops the run with the file's path and the system's reason
// instead of leaving a silently truncated file behind. Rows are buffered and written whole:
// when a write fails part-way, the file is cut back to its last complete row, so what was
// written before the failure stays readable.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace blockdem {

/// An output file could not be written (disk full, file too large, permission, I/O error).
/// The CLI exits with status 4 (docs/outputs.md).
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class OutputFile {
public:
    /// replace: create or truncate; append: go on after what the file holds (a restarted run).
    enum class Mode { replace, append };
    /// Opens file; throws OutputError naming it when it cannot.
    explicit OutputFile(std::filesystem::path file, Mode mode = Mode::replace);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    /// Buffers whole records (rows); writes them once the buffer is large.
    void append(std::string_view records);
    /// Writes what is buffered. On failure the file is cut back to the last complete record and
    /// OutputError is thrown ("<path>: cannot write: <reason>").
    void flush();
    /// Flushes and closes, checking close() too. Further calls do nothing.
    void close();
    const std::filesystem::path& path() const { return file_; }

private:
    [[noreturn]] void fail(const char* what, int error_number);

    std::filesystem::path file_;
    int fd_ = -1;
    std::string buffer_;
    long long written_bytes_ = 0;   ///< bytes of complete records on disk
};

/// Writes a whole small file (JSON, TOML, a VTK frame) through OutputFile. On failure the
/// partial file is removed (a regular file only: a device or a link is left alone) and
/// OutputError is thrown.
void write_output_file(const std::filesystem::path& file, std::string_view text);

}  // namespace blockdem
