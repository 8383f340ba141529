#include "motion/records/record_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"

namespace blockdem::records {

namespace {

// What a binary file that arrived in place of a text record most likely is, for the fix.
std::string binary_kind_hint(std::string_view content) {
    if (content.starts_with("PK\x03\x04"))
        return "; it is a ZIP archive (as records are downloaded): unzip it and give the record file inside";
    if (content.starts_with("\x1f\x8b")) return "; it is gzip-compressed: gunzip it and give the record file inside";
    if (content.starts_with("\xff\xfe") || content.starts_with("\xfe\xff"))
        return "; it is UTF-16 text: save it as ASCII or UTF-8";
    return "";
}

// Record formats are text: a NUL or a control character other than white space (and the DOS
// end-of-file mark 0x1a some old files end with) means a binary file, which the readers would
// otherwise report as a file with no numbers or a malformed header.
void refuse_binary(const RecordText& text, std::string_view content) {
    for (std::size_t at = 0; at < content.size(); ++at) {
        const auto byte = static_cast<unsigned char>(content[at]);
        if (byte >= 0x20 || byte == '\t' || byte == '\n' || byte == '\r' || byte == '\v' || byte == '\f' || byte == 0x1a)
            continue;
        const std::string name = to_lower(std::filesystem::path(text.file).extension().string());
        const std::size_t line = static_cast<std::size_t>(std::count(content.begin(), content.begin() + at, '\n'));
        fail_file(text, fmt::format("a binary file, not a {} (byte 0x{:02x} at offset {}, line {}){}",
                                    name == ".at2" ? "PEER AT2 text record"
                                                   : "text record (PEER AT2, K-NET, COSMOS V2, JMA CSV or plain text)",
                                    byte, at, line + 1, binary_kind_hint(content)));
    }
}

}  // namespace

RecordText split_record_text(std::string file, std::string_view content) {
    RecordText text{std::move(file), {}};
    if (content.size() > max_record_file_bytes)
        fail_file(text, fmt::format("the file holds {} bytes; a record file may have at most {} bytes ({} MiB)", content.size(),
                                    max_record_file_bytes, max_record_file_bytes >> 20));
    refuse_binary(text, content);
    std::size_t begin = 0;
    while (begin < content.size()) {
        std::size_t end = content.find('\n', begin);
        if (end == std::string_view::npos) end = content.size();
        std::string_view line = content.substr(begin, end - begin);
        while (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF and CR CR LF
        if (text.lines.size() == max_record_lines)
            fail_at(text, text.lines.size(), fmt::format("a record file may have at most {} lines", max_record_lines));
        if (line.size() > max_record_line_chars)
            fail_at(text, text.lines.size(),
                    fmt::format("this line is {} characters long; a record line may have at most {} (real header and data "
                                "lines have fewer than 200)",
                                line.size(), max_record_line_chars));
        text.lines.emplace_back(line);
        begin = end + 1;
    }
    return text;
}

RecordText read_record_text(const std::filesystem::path& path) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error && size > max_record_file_bytes)  // refused before reading it into memory
        throw InputError({path.string(), "", 0, 0},
                         fmt::format("the file holds {} bytes; a record file may have at most {} bytes ({} MiB)", size,
                                     max_record_file_bytes, max_record_file_bytes >> 20));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError({path.string(), "", 0, 0}, "cannot open the record file");
    const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return split_record_text(path.string(), content);
}

void fail_at(const RecordText& text, std::size_t line_index, const std::string& problem, int column) {
    throw InputError({text.file, "", static_cast<int>(line_index + 1), column}, problem);
}

void fail_file(const RecordText& text, const std::string& problem) { throw InputError({text.file, "", 0, 0}, problem); }

std::size_t parse_count(const RecordText& text, std::size_t line, std::string_view digits, std::string_view what,
                        std::size_t max_value) {
    std::uint64_t value = 0;
    const char* first = digits.data();
    const char* last = first + digits.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (digits.empty() || error == std::errc::invalid_argument || end != last)
        fail_at(text, line, fmt::format("{} '{}' is not a whole number", what, excerpt(digits)));
    if (error == std::errc::result_out_of_range || value > max_value)
        fail_at(text, line, fmt::format("{} = {} exceeds the limit of {}", what, excerpt(digits), max_value));
    return static_cast<std::size_t>(value);
}

std::size_t free_values_capacity(const RecordText& text, std::size_t first_line) {
    std::size_t capacity = 0;
    for (std::size_t i = first_line; i < text.lines.size(); ++i) capacity += (text.lines[i].size() + 1) / 2;
    return capacity;
}

std::size_t fixed_values_capacity(const RecordText& text, std::size_t first_line) {
    std::size_t capacity = 0;
    for (std::size_t i = first_line; i < text.lines.size(); ++i) capacity += text.lines[i].size();
    return capacity;
}

void check_count_fits(const RecordText& text, std::size_t line, std::size_t count, std::size_t capacity,
                      std::string_view what) {
    if (count > capacity)
        fail_at(text, line,
                fmt::format("{} = {} values are announced, but the {} line(s) after it can hold at most {}", what, count,
                            text.lines.size() > line ? text.lines.size() - line - 1 : 0, capacity));
}

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }
bool in_set(char c, std::string_view set) { return set.find(lower(c)) != std::string_view::npos || set.find(c) != std::string_view::npos; }

}  // namespace

std::size_t LineScanner::blanks() {
    const std::size_t from = at_;
    while (at_ < line_.size() && is_blank(line_[at_])) ++at_;
    return at_ - from;
}

bool LineScanner::literal(std::string_view word) {
    if (line_.size() - std::min(at_, line_.size()) < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (lower(line_[at_ + i]) != lower(word[i])) return false;
    at_ += word.size();
    return true;
}

bool LineScanner::one_of(std::string_view choices) {
    if (at_end() || !in_set(line_[at_], to_lower(choices))) return false;
    ++at_;
    return true;
}

std::optional<std::string_view> LineScanner::run_of(std::string_view charset) {
    const std::string set = to_lower(charset);
    const std::size_t from = at_;
    while (at_ < line_.size() && in_set(line_[at_], set)) ++at_;
    if (at_ == from) return std::nullopt;
    return line_.substr(from, at_ - from);
}

std::optional<std::string_view> LineScanner::digits() { return run_of("0123456789"); }

std::optional<std::string_view> LineScanner::word() {
    const std::size_t from = at_;
    while (at_ < line_.size() && (std::isalnum(static_cast<unsigned char>(line_[at_])) || line_[at_] == '_')) ++at_;
    if (at_ == from) return std::nullopt;
    return line_.substr(from, at_ - from);
}

std::string_view LineScanner::until_any(std::string_view stops) {
    const std::size_t from = std::min(at_, line_.size());
    at_ = std::min(line_.find_first_of(stops, from), line_.size());
    return line_.substr(from, at_ - from);
}

std::size_t find_nocase(std::string_view s, std::string_view part, std::size_t from) {
    if (part.empty()) return from <= s.size() ? from : std::string_view::npos;
    for (std::size_t i = from; i + part.size() <= s.size(); ++i) {
        std::size_t k = 0;
        while (k < part.size() && lower(s[i + k]) == lower(part[k])) ++k;
        if (k == part.size()) return i;
    }
    return std::string_view::npos;
}

std::optional<double> parse_fortran_number(std::string_view token) {
    if (token.empty() || token.size() > 64) return std::nullopt;
    std::string buffer(token);
    if (buffer.front() == '+') buffer.erase(0, 1);  // from_chars rejects a leading '+'
    for (char& c : buffer)
        if (c == 'D' || c == 'd') c = 'E';  // Fortran double-precision exponent
    double value = 0.0;
    const char* first = buffer.data();
    const char* last = first + buffer.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc{} || end != last || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    auto is_separator = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == ';'; };
    while (i < line.size()) {
        while (i < line.size() && is_separator(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_separator(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

std::vector<Token> blank_tokens(std::string_view line) {
    std::vector<Token> out;
    std::size_t i = 0;
    auto is_blank = [](char c) { return c == ' ' || c == '\t'; };
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i > start) out.push_back({line.substr(start, i - start), static_cast<int>(start + 1)});
    }
    return out;
}

std::string trim(std::string_view s) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return std::string(s);
}

std::string excerpt(std::string_view s) {
    constexpr std::size_t shown = 40;
    if (s.size() <= 2 * shown) return std::string(s);
    return fmt::format("{}... ({} characters)", s.substr(0, shown), s.size());
}

std::string to_lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string squeeze_blanks(std::string_view s) {
    std::string out;
    for (const Token& t : blank_tokens(s)) {
        if (!out.empty()) out += ' ';
        out += t.text;
    }
    return out;
}

bool starts_with_nocase(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && to_lower(s.substr(0, prefix.size())) == to_lower(prefix);
}

bool contains_nocase(std::string_view s, std::string_view part) { return find_nocase(s, part) != std::string_view::npos; }

namespace {

// Counts the numbers that follow the expected ones, up to the first line that is not all numbers
// (a trailer such as "End-of-data" or "*** End Data ***").
std::size_t count_extra_values(const RecordText& text, std::size_t line, const std::vector<Token>& rest) {
    std::size_t extra = 0;
    for (const Token& t : rest) {
        if (!parse_fortran_number(t.text)) return extra;
        ++extra;
    }
    for (++line; line < text.lines.size(); ++line) {
        const auto tokens = blank_tokens(text.lines[line]);
        const bool all_numbers = std::all_of(tokens.begin(), tokens.end(),
                                             [](const Token& t) { return parse_fortran_number(t.text).has_value(); });
        if (!all_numbers) break;
        extra += tokens.size();
    }
    return extra;
}

[[noreturn]] void fail_truncated(const RecordText& text, std::size_t first_line, std::size_t read, std::size_t count) {
    const std::size_t last = text.lines.empty() ? 0 : text.lines.size() - 1;
    fail_at(text, std::max(first_line, last),
            fmt::format("the record is truncated: the file ends after {} of the {} values its header announces", read,
                        count));
}

}  // namespace

ValueBlock read_free_values(const RecordText& text, std::size_t first_line, std::size_t count) {
    ValueBlock block;
    block.values.reserve(std::min(count, free_values_capacity(text, first_line)));
    std::size_t line = first_line;
    for (; line < text.lines.size() && block.values.size() < count; ++line) {
        const auto tokens = blank_tokens(text.lines[line]);
        for (std::size_t k = 0; k < tokens.size(); ++k) {
            if (block.values.size() == count) {
                block.extra_values = count_extra_values(text, line, {tokens.begin() + k, tokens.end()});
                block.extra_line = line;
                block.next_line = line + 1;
                return block;
            }
            const auto value = parse_fortran_number(tokens[k].text);
            if (!value)
                fail_at(text, line,
                        fmt::format("'{}' is not a number (value {} of {})", excerpt(tokens[k].text), block.values.size() + 1, count),
                        tokens[k].column);
            block.values.push_back(*value);
        }
    }
    if (block.values.size() < count) fail_truncated(text, first_line, block.values.size(), count);
    block.next_line = line;
    block.extra_values = count_extra_values(text, line - 1, {});
    block.extra_line = line;
    return block;
}

ValueBlock read_fixed_values(const RecordText& text, std::size_t first_line, std::size_t count, std::size_t per_line,
                             std::size_t width) {
    ValueBlock block;
    block.values.reserve(std::min(count, fixed_values_capacity(text, first_line)));
    std::size_t line = first_line;
    for (; line < text.lines.size() && block.values.size() < count; ++line) {
        const std::string_view row = text.lines[line];
        for (std::size_t k = 0; k < per_line && block.values.size() < count; ++k) {
            const std::size_t start = k * width;
            if (start >= row.size()) break;  // a short last line
            const std::string field = trim(row.substr(start, width));
            if (field.empty()) break;
            const auto value = parse_fortran_number(field);
            if (!value)
                fail_at(text, line,
                        fmt::format("'{}' is not a number (value {} of {})", excerpt(field), block.values.size() + 1, count),
                        static_cast<int>(start + 1));
            block.values.push_back(*value);
        }
    }
    if (block.values.size() < count) fail_truncated(text, first_line, block.values.size(), count);
    block.next_line = line;
    return block;
}

std::size_t free_value_line(const RecordText& text, std::size_t first_line, std::size_t index) {
    std::size_t line = first_line;
    for (; line + 1 < text.lines.size(); ++line) {
        const std::size_t on_line = blank_tokens(text.lines[line]).size();
        if (index < on_line) break;
        index -= on_line;
    }
    return line;
}

std::size_t fixed_value_line(const RecordText& text, std::size_t first_line, std::size_t index, std::size_t per_line,
                             std::size_t width) {
    std::size_t line = first_line;
    for (; line + 1 < text.lines.size(); ++line) {
        const std::string_view row = text.lines[line];
        std::size_t on_line = 0;  // as read_fixed_values reads them: up to a short end or an empty field
        while (on_line < per_line && on_line * width < row.size() && !trim(row.substr(on_line * width, width)).empty())
            ++on_line;
        if (index < on_line) break;
        index -= on_line;
    }
    return line;
}

namespace {

// The numbers of a line when every field is one; nullopt otherwise (and for blank lines).
std::optional<std::vector<double>> numeric_line(std::string_view line) {
    const auto fields = split_fields(line);
    if (fields.empty()) return std::nullopt;
    std::vector<double> out;
    for (auto f : fields) {
        const auto v = parse_fortran_number(f);
        if (!v) return std::nullopt;
        out.push_back(*v);
    }
    return out;
}

bool nothing_numeric_after(const RecordText& text, std::size_t line) {
    for (std::size_t i = line; i < text.lines.size(); ++i)
        for (auto f : split_fields(text.lines[i]))
            if (parse_fortran_number(f)) return false;
    return true;
}

}  // namespace

NumericRows read_numeric_rows(const RecordText& text, std::size_t from) {
    NumericRows out;
    std::size_t line = from;
    while (line < text.lines.size() && !numeric_line(text.lines[line])) ++line;
    if (line == text.lines.size()) fail_file(text, "no line of numbers found: the file holds no data");
    out.first_line = line;
    constexpr std::size_t max_table_numbers = 4 * max_record_samples;
    std::size_t numbers_read = 0;
    for (; line < text.lines.size(); ++line) {
        if (trim(text.lines[line]).empty()) continue;
        auto numbers = numeric_line(text.lines[line]);
        if (numbers) {
            numbers_read += numbers->size();
            if (numbers_read > max_table_numbers)
                fail_at(text, line, fmt::format("the table holds more than {} numbers (4 columns of the {} samples a record may have)",
                                                max_table_numbers, max_record_samples));
            out.rows.push_back(std::move(*numbers));
            out.row_lines.push_back(line);
            continue;
        }
        if (nothing_numeric_after(text, line)) {
            out.trailer_line = line;
            break;
        }
        for (const Token& t : blank_tokens(text.lines[line]))
            for (auto f : split_fields(t.text))
                if (!parse_fortran_number(f))
                    fail_at(text, line, fmt::format("'{}' is not a number", excerpt(f)), t.column);
        fail_at(text, line, "this line is not a row of numbers");
    }
    return out;
}

std::size_t row_value_line(const NumericRows& rows, std::size_t index) {
    for (std::size_t k = 0; k < rows.rows.size(); ++k) {
        if (index < rows.rows[k].size()) return rows.row_lines[k];
        index -= rows.rows[k].size();
    }
    return rows.row_lines.empty() ? rows.first_line : rows.row_lines.back();
}

}  // namespace blockdem::records
