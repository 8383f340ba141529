#pragma once
// Text helpers shared by the record readers. Strong-motion files come with LF, CRLF and even
// CR CR LF line endings, without a final newline, with Fortran numbers (".1297983E-02",
// "1.0D-03") and with padded or partial last lines; these helpers absorb all of that once so
// that each reader only knows its own layout. Every error names the file and the 1-based line.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace blockdem::records {

/// A record file split into lines, every trailing '\r' removed.
struct RecordText {
    std::string file;                ///< path as given, for messages
    std::vector<std::string> lines;  ///< index i is line i + 1 of the file
};

/// Reads a file as bytes (no locale, no encoding) and splits it into lines.
RecordText read_record_text(const std::filesystem::path& path);
/// The same from text in memory (tests, and data already read).
RecordText split_record_text(std::string file, std::string_view content);

/// Throws InputError naming text.file and line line_index + 1 (column 0 = unknown).
[[noreturn]] void fail_at(const RecordText& text, std::size_t line_index, const std::string& problem, int column = 0);
/// Throws InputError naming the file only (problems of the whole file).
[[noreturn]] void fail_file(const RecordText& text, const std::string& problem);

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

}  // namespace blockdem::records
