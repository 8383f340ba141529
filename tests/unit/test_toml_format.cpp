// The scenario copy's TOML text (io/toml_format.hpp): floats in their shortest round-trip form,
// and a text that parses back to the same table for every scenario the project ships.
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "io/toml_format.hpp"

namespace blockdem {
namespace {

TEST(TomlFloatText, ShortestFormThatReadsBack) {
    EXPECT_EQ(toml_float_text(0.3), "0.3");
    EXPECT_EQ(toml_float_text(0.1 + 0.2), "0.30000000000000004");  // a different double: all its digits
    EXPECT_EQ(toml_float_text(3.0), "3.0");                          // still a float when read back
    EXPECT_EQ(toml_float_text(-2.0), "-2.0");
    EXPECT_EQ(toml_float_text(1e-4), "0.0001");
    EXPECT_EQ(toml_float_text(9.81), "9.81");
    EXPECT_EQ(toml_float_text(2.0e9), "2000000000.0");
    EXPECT_EQ(toml_float_text(1e300), "1e+300");
    EXPECT_EQ(toml_float_text(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(toml_float_text(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(toml_float_text(std::nan("")), "nan");
    for (const double x : {0.3, 1.0 / 3.0, 6.02214076e23, 5e-324, 0.1 + 0.2, 123456.789e-3}) {
        const toml::table t = toml::parse("x = " + toml_float_text(x));
        EXPECT_EQ(t["x"].value<double>().value(), x) << toml_float_text(x);
    }
}

TEST(TomlText, WritesTheValuesAsTyped) {
    const toml::table root = toml::parse(R"(title = "a \"quoted\" title"
[contact]
mu = 0.3
e = 0.4
kn = 2.0e4
[[bodies]]
name = "block"
center = [0.0, 0.1]
vertices = [[0.0, 0.0], [1.0, 0.0], [0.5, 0.7]]
[simulation]
gravity = 9.81
)");
    const std::string text = toml_text(root);
    EXPECT_NE(text.find("mu = 0.3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("e = 0.4\n"), std::string::npos) << text;
    EXPECT_NE(text.find("kn = 20000.0\n"), std::string::npos) << text;
    EXPECT_NE(text.find("gravity = 9.81\n"), std::string::npos) << text;
    EXPECT_NE(text.find("center = [ 0.0, 0.1 ]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("[ [ 0.0, 0.0 ], [ 1.0, 0.0 ], [ 0.5, 0.7 ] ]"), std::string::npos) << text;
    EXPECT_EQ(text.find("0000000"), std::string::npos) << text;
    EXPECT_EQ(text.find("9999999"), std::string::npos) << text;
    EXPECT_EQ(toml::parse(text), root) << text;
}

TEST(TomlText, KeepsStructureTypesAndOddKeys) {
    const toml::table root = toml::parse(R"(top = 1
"key with space" = true
when = 1979-05-27T07:32:00Z
text = """two
lines"""
[a.b]
x = 3.0
n = 3
[[a.list]]
v = 1.5
[a.list.sub]
w = "in the first element"
[[a.list]]
v = 2.5
mixed = [1, "two", { inner = 0.25, deeper = { z = [0.5] } }]
[empty]
)");
    const std::string text = toml_text(root);
    const toml::table back = toml::parse(text);
    EXPECT_EQ(back, root) << text;
    EXPECT_TRUE(back["a"]["b"]["x"].is_floating_point()) << text;
    EXPECT_TRUE(back["a"]["b"]["n"].is_integer()) << text;
    EXPECT_TRUE(back["empty"].is_table()) << text;
    EXPECT_EQ(back["a"]["list"][0]["sub"]["w"].value<std::string>(), "in the first element") << text;
}

// Every scenario the project ships (examples, studies, test data) survives the round trip.
TEST(TomlText, EveryShippedScenarioParsesBackEqual) {
    int checked = 0;
    for (const char* folder : {"examples", "studies/scenarios", "tests", "fuzz/seeds"}) {
        const std::filesystem::path dir = std::filesystem::path(BLOCKDEM_SOURCE_DIR) / folder;
        if (!std::filesystem::is_directory(dir)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
            if (entry.path().extension() != ".toml") continue;
            toml::table root;
            try {
                root = toml::parse_file(entry.path().string());
            } catch (const toml::parse_error&) {
                continue;  // files that test the reader's syntax errors
            }
            const std::string text = toml_text(root);
            EXPECT_EQ(toml::parse(text), root) << entry.path() << "\n" << text;
            ++checked;
        }
    }
    EXPECT_GE(checked, 20);
}

}  // namespace
}  // namespace blockdem
