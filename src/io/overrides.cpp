#include "io/overrides.hpp"

#include <charconv>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

std::vector<std::string> split_path(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = path.find('.', start);
        parts.push_back(path.substr(start, dot - start));
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return parts;
}

// The value as TOML reads it, held in a one-key table: {value = ...}.
toml::table parse_value(const std::string& text) {
    try {
        return toml::parse("value = " + text);
    } catch (const toml::parse_error&) {
        toml::table t;
        t.insert("value", text);
        return t;
    }
}

// The element of an array of tables named by segment: a "name" match first, else an index.
toml::table* select_element(toml::array& array, const std::string& segment) {
    for (auto& element : array)
        if (auto* t = element.as_table(); t && (*t)["name"].value<std::string>() == segment) return t;
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
    if (error == std::errc{} && end == segment.data() + segment.size() && index < array.size())
        return array[index].as_table();
    return nullptr;
}

void apply_one(toml::table& root, const std::string& assignment) {
    const std::size_t eq = assignment.find('=');
    const InputLocation where{"", "--set " + assignment, 0, 0};
    if (eq == std::string::npos || eq == 0) throw InputError(where, "expected key=value");
    const std::string path = assignment.substr(0, eq);
    const std::vector<std::string> parts = split_path(path);
    // The dimension is chosen from the file before its keys are read (the two dimensions read
    // their bodies apart: polygons or polyhedra); --set dimension was ignored, or refused as if
    // the file had said it.
    if (parts.size() == 1 && parts[0] == "dimension")
        throw InputError(where, "the dimension is the scenario file's own (its bodies are polygons in 2-D, polyhedra in "
                                "3-D) and cannot be set: write the scenario for the other dimension");
    toml::table* table = &root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        toml::node* next = table->get(parts[i]);
        if (!next) {
            table->insert(parts[i], toml::table{});
            next = table->get(parts[i]);
        }
        if (auto* sub = next->as_table()) {
            table = sub;
        } else if (auto* array = next->as_array()) {
            ++i;
            table = i + 1 < parts.size() ? select_element(*array, parts[i]) : nullptr;
            if (!table)
                throw InputError(where, fmt::format("'{}' has no element named or numbered '{}'", parts[i - 1],
                                                    i < parts.size() ? parts[i] : ""));
        } else {
            throw InputError(where, fmt::format("'{}' is a value, not a table", parts[i]));
        }
    }
    toml::table holder = parse_value(assignment.substr(eq + 1));
    holder.get("value")->visit([&](auto&& value) { table->insert_or_assign(parts.back(), std::move(value)); });
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& assignments) {
    for (const auto& a : assignments) apply_one(root, a);
}

void apply_overrides_to_scenario(toml::table& root, const std::vector<std::string>& assignments,
                                 const std::filesystem::path& file) {
    try {
        apply_overrides(root, assignments);
    } catch (const InputError& e) {
        InputLocation where = e.where();
        where.file = file.string();
        throw InputError(where, e.problem());
    }
}

}  // namespace blockdem
