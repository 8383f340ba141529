#pragma once
// Text helpers shared by the record readers. Strong-motion files come with LF, CRLF and even
// CR CR LF line endings, without a final newline, with Fortran numbers (".1297983E-02",
// "1.0D-03") and with padded or partial last lines; these helpers absorb all of that once so
// that each reader only knows its own layout. Every error names the file and the 1-based line.
//
// Records come from anywhere, so nothing here trusts the file: its size, its line lengths and
// every count its header announces are checked against stated maxima (docs/records.md) before
// anything is allocated, and header phrases are read by LineScanner, which is linear in the line
// and never recurses (std::regex recurses once per character and overflows the stack on a
// 40,000-character line).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace blockdem::records {

/// The largest record file read [bytes]: a 1000 Hz record of a whole day as text is about 100 MB.
inline constexpr std::uintmax_t max_record_file_bytes = 256u << 20;
/// The most lines a record file may have (each costs memory beyond its text).
inline constexpr std::size_t max_record_lines = 10'000'000;
/// The longest line a record may have [characters]: real headers and data lines are under 200.
inline constexpr std::size_t max_record_line_chars = 64u << 10;

/// A record file split into lines, every trailing '\r' removed.
struct RecordText {
    std::string file;                ///< path as given, for messages
    std::vector<std::string> lines;  ///< index i is line i + 1 of the file
};

/// Reads a file as bytes (no locale, no encoding) and splits it into lines. A file over
/// max_record_file_bytes, with more than max_record_lines lines or a line longer than
/// max_record_line_chars is an InputError that gives the figure and the limit.
RecordText read_record_text(const std::filesystem::path& path);
/// The same from text in memory (tests, and data already read), with the same limits.
RecordText split_record_text(std::string file, std::string_view content);

/// Throws InputError naming text.file and line line_index + 1 (column 0 = unknown).
[[noreturn]] void fail_at(const RecordText& text, std::size_t line_index, const std::string& problem, int column = 0);
/// Throws InputError naming the file only (problems of the whole file).
[[noreturn]] void fail_file(const RecordText& text, const std::string& problem);

/// A count written in a header ("4000", "NPTS= 4000"): digits only, at most max_value. Anything
/// else is an InputError at the line that names what the count is and the text found.
std::size_t parse_count(const RecordText& text, std::size_t line, std::string_view digits, std::string_view what,
                        std::size_t max_value);

/// The most numbers that the lines from first_line on can hold: a free-format value takes at
/// least one character and a blank after it; a fixed-width one at least one character. (Loose
/// on purpose: a file a few values short is reported as truncated, where the values end.)
std::size_t free_values_capacity(const RecordText& text, std::size_t first_line);
std::size_t fixed_values_capacity(const RecordText& text, std::size_t first_line);
/// Refuses, at line `line`, a count that the rest of the file cannot hold (NPTS = 1e18 in a
/// 3 kB file) before any memory is reserved for it. `what` names the count ("NPTS").
void check_count_fits(const RecordText& text, std::size_t line, std::size_t count, std::size_t capacity,
                      std::string_view what);

/// A cursor over one line for the fixed phrases of headers ("NPTS= 4000, DT= .01 SEC"): each
/// call either consumes what it matches and says so, or leaves the position where it was.
/// Letters compare without case; "blanks" are spaces, tabs and other white space.
class LineScanner {
public:
    explicit LineScanner(std::string_view line, std::size_t at = 0) : line_(line), at_(at) {}
    std::size_t position() const { return at_; }
    bool at_end() const { return at_ >= line_.size(); }
    std::string_view rest() const { return line_.substr(std::min(at_, line_.size())); }
    /// Skips blanks; returns how many.
    std::size_t blanks();
    /// At least one blank.
    bool some_blanks() { return blanks() > 0; }
    /// The text `word` (case ignored).
    bool literal(std::string_view word);
    /// One character of `choices` (case ignored).
    bool one_of(std::string_view choices);
    /// A run of decimal digits (at least one).
    std::optional<std::string_view> digits();
    /// A run of the characters in `charset` (case ignored; at least one).
    std::optional<std::string_view> run_of(std::string_view charset);
    /// A run of letters, digits and '_' (at least one).
    std::optional<std::string_view> word();
    /// Everything up to (not including) the first character of `stops`, or to the end.
    std::string_view until_any(std::string_view stops);

private:
    std::string_view line_;
    std::size_t at_;
};

/// Where part first occurs in s at or after from, ignoring case; npos when it does not.
std::size_t find_nocase(std::string_view s, std::string_view part, std::size_t from = 0);

/// A number written by Fortran or C: "-.64E-02", "0.00630", "1.0D-03", "+5", "3.4e-04".
/// nullopt when the whole token is not a finite number. Independent of the C++ locale.
std::optional<double> parse_fortran_number(std::string_view token);

/// Fields of a line split on blanks, tabs, commas and semicolons; empty fields are dropped.
std::vector<std::string_view> split_fields(std::string_view line);
/// The blank-separated tokens of a line together with their 1-based columns.
struct Token {
    std::string_view text;
    int column = 0;
};
std::vector<Token> blank_tokens(std::string_view line);

std::string trim(std::string_view s);
/// Text from a file as a message shows it: whole when short, else its first 40 characters,
/// "..." and its length (a 40,000-character field must not become a 40,000-character message).
std::string excerpt(std::string_view s);
std::string to_lower(std::string_view s);
/// Collapses runs of blanks into one and trims.
std::string squeeze_blanks(std::string_view s);
bool starts_with_nocase(std::string_view s, std::string_view prefix);
bool contains_nocase(std::string_view s, std::string_view part);

/// Numbers read from a data section, and where the section ended.
struct ValueBlock {
    std::vector<double> values;
    std::size_t next_line = 0;         ///< first line after the values
    std::size_t extra_values = 0;      ///< numbers found after the expected count (not used)
    std::size_t extra_line = 0;        ///< line of the first of them
};

/// Reads exactly count blank-separated numbers starting at line first_line (free format, any
/// number per line). A non-number before count values is an error naming its line and column;
/// the end of the file before count values is an error naming the last line. After the count,
/// numbers up to the first non-numeric line are counted as extra_values; a trailer is fine.
ValueBlock read_free_values(const RecordText& text, std::size_t first_line, std::size_t count);

/// Reads exactly count numbers laid out in fixed-width fields, per_line fields of width
/// characters per line (Fortran "(5E15.7)"): fields may touch, so the line is cut by column.
ValueBlock read_fixed_values(const RecordText& text, std::size_t first_line, std::size_t count, std::size_t per_line,
                             std::size_t width);

/// The line of value `index` (0-based) of a block that read_free_values read from first_line,
/// and of one that read_fixed_values read with per_line fields of width characters: for
/// messages about a value found bad after reading.
std::size_t free_value_line(const RecordText& text, std::size_t first_line, std::size_t index);
std::size_t fixed_value_line(const RecordText& text, std::size_t first_line, std::size_t index, std::size_t per_line,
                             std::size_t width);

/// Rows of numbers (a table or a list of values), as found after a free-text header.
struct NumericRows {
    std::size_t first_line = 0;                ///< line of the first row
    std::vector<std::vector<double>> rows;     ///< the numbers of each data line (blank lines skipped)
    std::vector<std::size_t> row_lines;        ///< the line of each row
    std::size_t trailer_line = 0;              ///< first line of a non-numeric trailer, 0 when none
};

/// Finds the first line, at or after `from`, made only of numbers (fields split on blanks, tabs,
/// commas, semicolons), and reads rows from there to the end. A non-numeric line is accepted as
/// the end of data only when nothing numeric follows it ("*** End Data ***"); otherwise it is an
/// error naming its line. Throws when no numeric line exists.
NumericRows read_numeric_rows(const RecordText& text, std::size_t from);

/// The line of value `index` (0-based) of rows read one after another (a values-only file).
std::size_t row_value_line(const NumericRows& rows, std::size_t index);

}  // namespace blockdem::records
