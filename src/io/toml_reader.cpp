#include "io/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace blockdem {
namespace {

std::string describe_node(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string: return fmt::format("the string \"{}\"", *node.value<std::string>());
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::array: return "a list";
        case toml::node_type::table: return "a table";
        default: return "a date or time";
    }
}

}  // namespace

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = std::numeric_limits<std::size_t>::max();
    for (const auto& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        // A likely typo: at most about a third of the shorter word changed (at least one edit).
        const std::size_t allowed = std::max<std::size_t>(1, (std::min(word.size(), c.size()) + 1) / 2);
        if (d <= allowed && d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

TableReader::TableReader(const toml::table& table, std::string file, std::string path)
    : table_(&table), file_(std::move(file)), path_(std::move(path)) {}

std::string TableReader::key_path(const std::string& key) const {
    if (key.empty()) return path_;
    return path_.empty() ? key : path_ + "." + key;
}

InputLocation TableReader::location(const std::string& key) const {
    InputLocation where{file_, key_path(key), 0, 0};
    const toml::node* node = key.empty() ? static_cast<const toml::node*>(table_) : table_->get(key);
    if (!node) node = table_;
    const auto& src = node->source();
    // A value given with --set was parsed from a one-line document: its position means nothing.
    if (src.begin && src.path && !src.path->empty()) {
        where.line = static_cast<int>(src.begin.line);
        where.column = static_cast<int>(src.begin.column);
    }
    return where;
}

void TableReader::fail(const std::string& key, const std::string& problem) const {
    throw InputError(location(key), problem);
}

void TableReader::fail_missing(const std::string& key, const std::string& what) const {
    // A missing key next to an unknown one is most likely a typo of it: point at the typo.
    for (const auto& [k, node] : *table_) {
        const std::string present(k.str());
        if (known_.count(present) || nearest(present, {key}).empty()) continue;
        fail(present, fmt::format("unknown key (did you mean '{}'?); '{}' is required{}", key, key_path(key), what));
    }
    fail("", fmt::format("missing required key '{}'{}", key_path(key), what));
}

const toml::node* TableReader::get(const std::string& key) {
    known_.insert(key);
    return table_->get(key);
}

bool TableReader::has(const std::string& key) { return get(key) != nullptr; }

void TableReader::allow(std::initializer_list<const char*> keys) {
    for (const char* k : keys) known_.insert(k);
}

std::optional<double> TableReader::optional_number(const std::string& key) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    if (auto v = node->value<double>()) {
        if (!std::isfinite(*v)) fail(key, "must be a finite number");
        return *v;
    }
    fail(key, fmt::format("must be a number, got {}", describe_node(*node)));
}

double TableReader::number(const std::string& key) {
    auto v = optional_number(key);
    if (!v) fail_missing(key);
    return *v;
}

double TableReader::number_or(const std::string& key, double fallback) { return optional_number(key).value_or(fallback); }

std::optional<double> TableReader::optional_positive(const std::string& key) {
    auto v = optional_number(key);
    if (v && !(*v > 0.0)) fail(key, fmt::format("must be > 0, got {}", *v));
    return v;
}

double TableReader::positive(const std::string& key) {
    auto v = optional_positive(key);
    if (!v) fail_missing(key);
    return *v;
}

std::optional<std::int64_t> TableReader::optional_whole_number(const std::string& key, std::int64_t min, std::int64_t max) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const std::string range = fmt::format("must be a whole number from {} to {}", min, max);
    if (const auto* integer = node->as_integer()) {
        const std::int64_t v = integer->get();
        if (v < min || v > max) fail(key, fmt::format("{}, got {}", range, v));
        return v;
    }
    if (const auto* real = node->as_floating_point()) {
        // Compared as doubles: min and max are exact in double up to 2^53, and a value outside
        // them is refused before the cast, where it would be undefined.
        const double v = real->get();
        const double largest_exact = 9007199254740992.0;  // 2^53
        if (!std::isfinite(v) || v != std::floor(v) || v < std::max(static_cast<double>(min), -largest_exact) ||
            v > std::min(static_cast<double>(max), largest_exact))
            fail(key, fmt::format("{}, got {}", range, v));
        return static_cast<std::int64_t>(v);
    }
    fail(key, fmt::format("{}, got {}", range, describe_node(*node)));
}

std::int64_t TableReader::whole_number(const std::string& key, std::int64_t min, std::int64_t max) {
    auto v = optional_whole_number(key, min, max);
    if (!v) fail_missing(key);
    return *v;
}

std::int64_t TableReader::whole_number_or(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max) {
    return optional_whole_number(key, min, max).value_or(fallback);
}

std::optional<std::string> TableReader::optional_string(const std::string& key) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    if (auto v = node->value<std::string>()) return *v;
    fail(key, "must be a string (in quotes)");
}

std::string TableReader::string(const std::string& key) {
    auto v = optional_string(key);
    if (!v) fail_missing(key);
    return *v;
}

std::string TableReader::choice(const std::string& key, const std::vector<std::string>& choices,
                                const std::string& fallback) {
    auto v = optional_string(key);
    if (!v) {
        if (fallback.empty()) fail_missing(key, fmt::format(" (one of: {})", fmt::join(choices, ", ")));
        return fallback;
    }
    if (std::find(choices.begin(), choices.end(), *v) != choices.end()) return *v;
    const std::string guess = nearest(*v, choices);
    fail(key, fmt::format("'{}' is not one of: {}{}", *v, fmt::join(choices, ", "),
                          guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
}

bool TableReader::boolean_or(const std::string& key, bool fallback) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    // (value<bool>() would read an integer as a flag: vtk_contacts = 3 is a slip, not true.)
    if (node->is_boolean()) return *node->value<bool>();
    fail(key, "must be true or false");
}

std::optional<Vec2> TableReader::optional_vec2(const std::string& key) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const toml::array* arr = node->as_array();
    if (!arr || arr->size() != 2) fail(key, "must be a pair of numbers [x, y]");
    auto x = (*arr)[0].value<double>();
    auto y = (*arr)[1].value<double>();
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) fail(key, "must be a pair of finite numbers [x, y]");
    return Vec2{*x, *y};
}

std::vector<Vec2> TableReader::vec2_list(const std::string& key) {
    const toml::node* node = get(key);
    if (!node) fail_missing(key);
    const toml::array* arr = node->as_array();
    if (!arr) fail(key, "must be a list of [x, y] pairs");
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const toml::array* pair = (*arr)[i].as_array();
        std::optional<double> x, y;
        if (pair && pair->size() == 2) {
            x = (*pair)[0].value<double>();
            y = (*pair)[1].value<double>();
        }
        if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
            fail(key, fmt::format("element {} must be a pair of finite numbers [x, y]", i));
        out.push_back({*x, *y});
    }
    return out;
}

std::vector<double> TableReader::number_list(const std::string& key) {
    const toml::node* node = get(key);
    if (!node) fail_missing(key);
    const toml::array* arr = node->as_array();
    if (!arr) fail(key, "must be a list of numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < arr->size(); ++i) {
        auto v = (*arr)[i].value<double>();
        if (!v || !std::isfinite(*v)) fail(key, fmt::format("element {} must be a finite number", i));
        out.push_back(*v);
    }
    return out;
}

std::optional<TableReader> TableReader::optional_table(const std::string& key) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const toml::table* t = node->as_table();
    if (!t) fail(key, "must be a table");
    return TableReader(*t, file_, key_path(key));
}

TableReader TableReader::table(const std::string& key) {
    auto t = optional_table(key);
    if (!t) fail("", fmt::format("missing required table [{}]", key_path(key)));
    return *t;
}

std::vector<TableReader> TableReader::table_array(const std::string& key) {
    const toml::node* node = get(key);
    std::vector<TableReader> out;
    if (!node) return out;
    const toml::array* arr = node->as_array();
    if (!arr || !arr->is_array_of_tables()) fail(key, fmt::format("must be an array of tables ([[{}]])", key));
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const toml::table& t = *(*arr)[i].as_table();
        std::string element = key_path(key);
        if (auto name = t["name"].value<std::string>())
            element += "." + *name;
        else
            element += fmt::format("[{}]", i);
        out.emplace_back(t, file_, element);
    }
    return out;
}

void TableReader::reject_unknown_keys() const {
    std::vector<std::string> valid(known_.begin(), known_.end());
    for (const auto& [k, node] : *table_) {
        const std::string key(k.str());
        if (known_.count(key)) continue;
        const std::string guess = nearest(key, valid);
        fail(key, fmt::format("unknown key{}; valid keys here: {}",
                              guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess), fmt::join(valid, ", ")));
    }
}

}  // namespace blockdem
