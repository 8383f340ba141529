#pragma once
// Reads one TOML table key by key, remembering which keys were asked for, so that a key the
// program never asked for (a misspelling) is reported with the nearest valid key. Every error
// names the file, the dotted key path and the line.
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "geometry/vec2.hpp"
#include "io/input_error.hpp"

namespace blockdem {

class TableReader {
public:
    /// file: for messages; path: dotted path of this table ("" for the root).
    TableReader(const toml::table& table, std::string file, std::string path);

    bool has(const std::string& key);
    double number(const std::string& key);
    std::optional<double> optional_number(const std::string& key);
    double number_or(const std::string& key, double fallback);
    /// A number that must be > 0.
    double positive(const std::string& key);
    std::optional<double> optional_positive(const std::string& key);
    /// A whole number within [min, max], given as a TOML integer or as a float with no fraction
    /// (courses = 10.0). The range is checked before any conversion, so 1e20 or -1 is an error
    /// that names the key and the range, never a wrapped or undefined cast.
    std::optional<std::int64_t> optional_whole_number(const std::string& key, std::int64_t min, std::int64_t max);
    std::int64_t whole_number(const std::string& key, std::int64_t min, std::int64_t max);
    std::int64_t whole_number_or(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max);
    std::string string(const std::string& key);
    std::optional<std::string> optional_string(const std::string& key);
    /// A string that must be one of choices.
    std::string choice(const std::string& key, const std::vector<std::string>& choices, const std::string& fallback);
    bool boolean_or(const std::string& key, bool fallback);
    std::optional<Vec2> optional_vec2(const std::string& key);
    std::vector<Vec2> vec2_list(const std::string& key);
    std::vector<double> number_list(const std::string& key);

    TableReader table(const std::string& key);
    std::optional<TableReader> optional_table(const std::string& key);
    /// An array of tables ([[key]]); each element's path is key.<name> when it has a "name", else key[i].
    std::vector<TableReader> table_array(const std::string& key);

    /// Declares keys that are valid here even though this code path did not read them.
    void allow(std::initializer_list<const char*> keys);
    /// Throws InputError for the first key that was never asked for, naming the nearest valid key.
    void reject_unknown_keys() const;

    /// An error at this table or at one of its keys.
    [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
    /// A required key is missing; names a present unknown key that looks like a typo of it.
    [[noreturn]] void fail_missing(const std::string& key, const std::string& what = "") const;
    InputLocation location(const std::string& key) const;
    const std::string& path() const { return path_; }
    const std::string& file() const { return file_; }
    const toml::table& raw() const { return *table_; }

private:
    const toml::node* get(const std::string& key);
    std::string key_path(const std::string& key) const;

    const toml::table* table_;
    std::string file_;
    std::string path_;
    std::set<std::string> known_;
};

/// Levenshtein edit distance, for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b);
/// The candidate nearest to word, or "" when none is close enough to be a likely typo.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace blockdem
