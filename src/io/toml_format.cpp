#include "io/toml_format.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace blockdem {
namespace {

bool is_bare_key(const std::string& key) {
    return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
}

// A key as it must be written: bare when it can be, else a basic string with escapes.
std::string key_text(const std::string& key) {
    if (is_bare_key(key)) return key;
    std::string out = "\"";
    for (const char c : key) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\')
            out += std::string("\\") + c;
        else if (byte < 0x20 || byte == 0x7f)
            out += fmt::format("\\u{:04X}", byte);
        else
            out += c;
    }
    return out + '"';
}

std::string path_text(const std::string& parent, const std::string& key) {
    return parent.empty() ? key_text(key) : parent + '.' + key_text(key);
}

// An array every element of which is a table: written as [[path]] sections.
bool is_array_of_tables(const toml::node& node) {
    const toml::array* array = node.as_array();
    return array && !array->empty() && array->is_array_of_tables();
}

std::string inline_value_text(const toml::node& node);

std::string inline_table_text(const toml::table& table) {
    std::string out = "{";
    bool first = true;
    for (const auto& [key, value] : table) {
        out += first ? " " : ", ";
        out += key_text(std::string(key.str())) + " = " + inline_value_text(value);
        first = false;
    }
    return out + (first ? "}" : " }");
}

std::string inline_value_text(const toml::node& node) {
    if (const auto* d = node.as_floating_point()) return toml_float_text(d->get());
    if (const auto* table = node.as_table()) return inline_table_text(*table);
    if (const auto* array = node.as_array()) {
        std::string out = "[";
        for (std::size_t i = 0; i < array->size(); ++i) out += (i == 0 ? " " : ", ") + inline_value_text((*array)[i]);
        return out + (array->empty() ? "]" : " ]");
    }
    std::ostringstream text;  // strings (quoted and escaped), integers, booleans, dates and times
    node.visit([&text](const auto& value) { text << toml::toml_formatter{value}; });
    return text.str();
}

void write_table(std::string& out, const toml::table& table, const std::string& path);

// A table that holds only tables needs no header of its own ([table_motion] above
// [table_motion.horizontal]); an empty one keeps it, or it would be lost.
void write_section(std::string& out, const toml::table& table, const std::string& path, bool array_element) {
    const bool only_tables = !table.empty() && std::all_of(table.begin(), table.end(), [](const auto& entry) {
        return entry.second.is_table() || is_array_of_tables(entry.second);
    });
    if (array_element || !only_tables)
        out += fmt::format("\n{}{}{}\n", array_element ? "[[" : "[", path, array_element ? "]]" : "]");
    write_table(out, table, path);
}

// The key/value lines first (once a [header] follows, later lines would belong to it), then the
// sub-tables, then the arrays of tables.
void write_table(std::string& out, const toml::table& table, const std::string& path) {
    for (const auto& [key, value] : table)
        if (!value.is_table() && !is_array_of_tables(value))
            out += key_text(std::string(key.str())) + " = " + inline_value_text(value) + '\n';
    for (const auto& [key, value] : table)
        if (const auto* sub = value.as_table()) write_section(out, *sub, path_text(path, std::string(key.str())), false);
    for (const auto& [key, value] : table)
        if (is_array_of_tables(value))
            for (const toml::node& element : *value.as_array())
                write_section(out, *element.as_table(), path_text(path, std::string(key.str())), true);
}

}  // namespace

std::string toml_float_text(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    std::string text = fmt::format("{}", value);
    // fmt writes a whole number without a point ("3"), which TOML would read as an integer.
    if (text.find_first_of(".eE") == std::string::npos) text += ".0";
    return text;
}

std::string toml_text(const toml::table& root) {
    std::string out;
    write_table(out, root, "");
    return out;
}

}  // namespace blockdem
