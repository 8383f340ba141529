#include "sweep/sweep_plan.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem::sweep {
namespace {

constexpr std::int64_t max_cases = 100'000'000;  // beyond this a typo is likelier than a plan

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

std::optional<double> to_number(const std::string& text) {
    const std::string t = trim(text);
    double v = 0.0;
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || error != std::errc{} || end != t.data() + t.size()) return std::nullopt;
    return v;
}

// Splits at `separator` outside [], {} and quotes, so that TOML arrays and strings stay whole.
std::vector<std::string> split_top_level(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string current;
    int depth = 0;
    char quote = 0;
    for (char ch : text) {
        if (quote) {
            if (ch == quote) quote = 0;
        } else if (ch == '"' || ch == '\'') {
            quote = ch;
        } else if (ch == '[' || ch == '{') {
            ++depth;
        } else if (ch == ']' || ch == '}') {
            --depth;
        } else if (ch == separator && depth == 0) {
            parts.push_back(trim(current));
            current.clear();
            continue;
        }
        current += ch;
    }
    parts.push_back(trim(current));
    return parts;
}

std::vector<std::string> range_values(double start, double stop, double step) {
    if (!std::isfinite(start) || !std::isfinite(stop) || !std::isfinite(step))
        throw std::invalid_argument(fmt::format("the range {}:{}:{} holds a value that is not a finite number", start, stop, step));
    if (step == 0.0) throw std::invalid_argument("the step of a range must not be 0");
    if ((stop - start) * step < 0.0)
        throw std::invalid_argument(fmt::format("the range {}:{}:{} never reaches its end", start, stop, step));
    // Inclusive of stop up to round-off: 0:1:0.1 has 11 values.
    const double count = std::floor((stop - start) / step + 1e-9) + 1.0;
    if (count > static_cast<double>(max_cases)) throw std::invalid_argument("the range has too many values");
    std::vector<std::string> values;
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(count); ++i)
        values.push_back(fmt::format("{:.12g}", start + static_cast<double>(i) * step));
    return values;
}

}  // namespace

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> fields;
    std::string current;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted) {
            if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                current += '"';
                ++i;
            } else if (ch == '"') {
                quoted = false;
            } else {
                current += ch;
            }
        } else if (ch == '"') {
            quoted = true;
        } else if (ch == ',') {
            fields.push_back(trim(current));
            current.clear();
        } else {
            current += ch;
        }
    }
    fields.push_back(trim(current));
    return fields;
}

namespace {

Assignment parse_assignment(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) throw std::invalid_argument(fmt::format("expected key=value, got '{}'", text));
    return {trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
}

RecordEntry list_entry(const std::string& line, const std::filesystem::path& base) {
    std::istringstream words(line);
    std::string path;
    words >> path;
    RecordEntry e;
    e.label = path;
    e.file = std::filesystem::absolute(base / path).lexically_normal();
    for (std::string word; words >> word;) e.keys.push_back(parse_assignment(word));
    return e;
}

bool is_record_file(const std::filesystem::directory_entry& entry) {
    const std::string name = entry.path().filename().string();
    const std::string ext = entry.path().extension().string();
    return entry.is_regular_file() && !name.starts_with('.') && ext != ".json" && ext != ".md";
}

std::string toml_literal(const std::string& text) {
    if (text.find('\'') == std::string::npos) return "'" + text + "'";
    std::string quoted = "\"";
    for (char ch : text) quoted += (ch == '"' || ch == '\\') ? std::string("\\") + ch : std::string(1, ch);
    return quoted + "\"";
}

}  // namespace

std::vector<std::string> parse_value_list(const std::string& text) {
    const std::vector<std::string> colon = split_top_level(text, ':');
    if (colon.size() == 3) {
        const auto a = to_number(colon[0]), b = to_number(colon[1]), step = to_number(colon[2]);
        if (a && b && step) return range_values(*a, *b, *step);
    }
    std::vector<std::string> values = split_top_level(text, ',');
    for (const auto& v : values)
        if (v.empty()) throw std::invalid_argument(fmt::format("empty value in the list '{}'", text));
    return values;
}

SweepAxis parse_vary(const std::string& spec) {
    const Assignment a = parse_assignment(spec);
    SweepAxis axis;
    axis.keys = {a.key};
    for (auto& v : parse_value_list(a.value)) axis.points.push_back({v});
    return axis;
}

SweepAxis read_case_list(const std::filesystem::path& file) {
    if (std::filesystem::is_directory(file))
        throw std::invalid_argument(fmt::format("{}: a folder, not a case list (a CSV file: a header of keys, a row a case)", file.string()));
    std::ifstream in(file);
    if (!in) throw std::invalid_argument(fmt::format("{}: cannot open the case list", file.string()));
    SweepAxis axis;
    std::string line;
    int line_number = 0;
    while (std::getline(in, line)) {
        ++line_number;
        if (trim(line).empty() || trim(line).starts_with('#')) continue;
        std::vector<std::string> fields = split_csv_line(line);
        if (axis.keys.empty()) {
            axis.keys = fields;
            continue;
        }
        if (fields.size() != axis.keys.size())
            throw std::invalid_argument(fmt::format("{}:{}: {} values for {} keys", file.string(), line_number,
                                                    fields.size(), axis.keys.size()));
        axis.points.push_back(std::move(fields));
    }
    if (axis.points.empty()) throw std::invalid_argument(fmt::format("{}: the case list has no cases", file.string()));
    return axis;
}

std::vector<RecordEntry> read_record_suite(const std::filesystem::path& path) {
    std::vector<RecordEntry> suite;
    if (std::filesystem::is_directory(path)) {
        for (const auto& entry : std::filesystem::directory_iterator(path))
            if (is_record_file(entry))
                suite.push_back({std::filesystem::absolute(entry.path()), entry.path().filename().string(), {}});
        std::sort(suite.begin(), suite.end(), [](const auto& a, const auto& b) { return a.label < b.label; });
    } else {
        std::ifstream in(path);
        if (!in) throw std::invalid_argument(fmt::format("{}: no such record folder or list file", path.string()));
        std::string line;
        int line_number = 0;
        while (std::getline(in, line)) {
            ++line_number;
            const std::string text = trim(line.substr(0, line.find('#')));
            if (text.empty()) continue;
            try {
                suite.push_back(list_entry(text, path.parent_path()));
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument(fmt::format("{}:{}: {}", path.string(), line_number, e.what()));
            }
        }
    }
    if (suite.empty()) throw std::invalid_argument(fmt::format("{}: no records found", path.string()));
    return suite;
}

std::int64_t SweepPlan::case_count() const {
    std::int64_t n = 1;
    for (const auto& axis : axes) n *= static_cast<std::int64_t>(axis.points.size());
    if (!suite.records.empty()) n *= static_cast<std::int64_t>(suite.records.size() * suite.levels.size());
    if (n > max_cases) throw std::invalid_argument(fmt::format("{} cases is more than the limit of {}", n, max_cases));
    return n;
}

void SweepPlan::check_keys_distinct() const {
    std::set<std::string> seen;
    for (const auto& axis : axes)
        for (const auto& key : axis.keys)
            if (!seen.insert(key).second)
                throw std::invalid_argument(fmt::format("the key '{}' is varied twice (by --vary or a --cases column): "
                                                        "give all its values in one place",
                                                        key));
}

std::vector<std::string> SweepPlan::value_columns() const {
    std::vector<std::string> columns;
    for (const auto& axis : axes) columns.insert(columns.end(), axis.keys.begin(), axis.keys.end());
    if (!suite.records.empty()) {
        columns.push_back("record");
        columns.push_back(suite.scaling == RecordScaling::factor ? "scale" : "target_pga_" + suite.pga_unit);
    }
    return columns;
}

void check_target_pga_unit(const std::string& levels, const std::string& unit) {
    if (!levels.empty() && unit.empty())
        throw std::invalid_argument(
            "--target-pga needs --target-pga-unit (m/s^2, gal or g), e.g. --target-pga 0.1:0.8:0.1 --target-pga-unit g: "
            "a target PGA is read in the unit given with it (blockdem sweep used to take g without saying so, "
            "while a scenario's target_pga is in m/s^2 unless target_pga_unit says otherwise)");
}

SweepCase make_case(const SweepPlan& plan, std::int64_t id) {
    SweepCase c;
    c.id = id;
    // Mixed radix, the last axis fastest: the suite's levels, then its records, then the axes.
    std::int64_t rest = id;
    std::size_t level = 0, record = 0;
    if (!plan.suite.records.empty()) {
        const auto levels = static_cast<std::int64_t>(plan.suite.levels.size());
        const auto records = static_cast<std::int64_t>(plan.suite.records.size());
        level = static_cast<std::size_t>(rest % levels);
        rest /= levels;
        record = static_cast<std::size_t>(rest % records);
        rest /= records;
    }
    std::vector<std::size_t> point(plan.axes.size());
    for (std::size_t k = plan.axes.size(); k-- > 0;) {
        const auto n = static_cast<std::int64_t>(plan.axes[k].points.size());
        point[k] = static_cast<std::size_t>(rest % n);
        rest /= n;
    }
    for (std::size_t k = 0; k < plan.axes.size(); ++k) {
        const SweepAxis& axis = plan.axes[k];
        for (std::size_t j = 0; j < axis.keys.size(); ++j) {
            c.assignments.push_back({axis.keys[j], axis.points[point[k]][j]});
            c.column_values.push_back(axis.points[point[k]][j]);
        }
    }
    if (!plan.suite.records.empty()) {
        c.record = &plan.suite.records[record];
        c.level = plan.suite.levels[level];
        c.column_values.push_back(c.record->label);
        c.column_values.push_back(c.level);
    }
    return c;
}

std::vector<Assignment> record_assignments(const RecordSuite& suite, const SweepCase& c) {
    const std::string prefix = "table_motion.horizontal.";
    std::vector<Assignment> out{{prefix + "type", "\"record\""}, {prefix + "file", toml_literal(c.record->file.string())}};
    for (const auto& k : suite.common_keys) out.push_back({prefix + k.key, k.value});
    for (const auto& k : c.record->keys) out.push_back({prefix + k.key, k.value});
    if (suite.scaling == RecordScaling::factor) {
        out.push_back({prefix + "scale", c.level});
    } else {
        out.push_back({prefix + "target_pga", c.level});
        out.push_back({prefix + "target_pga_unit", "\"" + suite.pga_unit + "\""});
    }
    return out;
}

}  // namespace blockdem::sweep
