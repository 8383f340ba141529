// The messages and warnings a new user met (issue 12, part 6), at the level of the functions that
// make them: vertices as listed, binary record files, vertical components, the undamped contact
// and the unit of a sweep's target PGA. (tests/cli/test_loose_ends.sh runs them end to end.)
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "geometry/polygon.hpp"
#include "io/input_error.hpp"
#include "io/run_checks.hpp"
#include "io/scenario.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/records/record_text.hpp"
#include "sweep/sweep_plan.hpp"

namespace blockdem {
namespace {

void expect_contains(const std::string& text, const std::string& part) {
    EXPECT_NE(text.find(part), std::string::npos) << "in: " << text << "\nexpected: " << part;
}

TEST(ListedVertices, ClockwiseListsAreNamedAndNumberedAsWritten) {
    // Counter-clockwise and convex, then the same clockwise: both valid.
    const std::vector<Vec2> ccw{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_FALSE(listed_vertices_problem(ccw));
    const std::vector<Vec2> cw{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    EXPECT_FALSE(listed_vertices_problem(cw));
    EXPECT_GT(signed_area(counter_clockwise(cw)), 0.0);
    EXPECT_EQ(counter_clockwise(ccw), ccw);
    // Clockwise and not convex at the third vertex as written (index 2), which is index 1 once
    // reversed: the message names 2 and says the list ran clockwise.
    const auto problem = listed_vertices_problem({{0, 0}, {0, 0.5}, {0.2, 0.1}, {0.4, 0}});
    ASSERT_TRUE(problem);
    expect_contains(*problem, "not strictly convex at vertex 2 (0.2, 0.1) m");
    expect_contains(*problem, "listed clockwise");
    // The same corner listed counter-clockwise: its own index, and no word of clockwise.
    const auto same = listed_vertices_problem({{0.4, 0}, {0.2, 0.1}, {0, 0.5}, {0, 0}});
    ASSERT_TRUE(same);
    expect_contains(*same, "not strictly convex at vertex 1 (0.2, 0.1) m");
    EXPECT_EQ(same->find("clockwise"), std::string::npos) << *same;
    // Points on a line have no area: not "clockwise".
    const auto line = listed_vertices_problem({{0, 0}, {1, 0}, {2, 0}});
    ASSERT_TRUE(line);
    expect_contains(*line, "enclose no area");
}

TEST(RecordFiles, BinaryContentIsRefusedAsSuch) {
    const std::string zip("PK\x03\x04\x14\x00\x00\x00", 8);
    try {
        records::split_record_text("RSN6.AT2", zip + "rest");
        FAIL() << "a ZIP archive was read as a record";
    } catch (const InputError& e) {
        expect_contains(e.what(), "a binary file, not a PEER AT2 text record");
        expect_contains(e.what(), "ZIP archive");
    }
    try {
        records::split_record_text("record.txt", std::string("1.0 2.0\n3.0\0 4.0\n", 17));
        FAIL() << "a NUL byte was read as text";
    } catch (const InputError& e) {
        expect_contains(e.what(), "a binary file, not a text record");
        expect_contains(e.what(), "line 2");
    }
    // Tabs, CRLF, form feeds, Latin-1 letters and a final DOS end-of-file mark are text.
    EXPECT_NO_THROW(records::split_record_text("old.txt", "St\xe9 1\t2\r\n\f3 4\r\n\x1a"));
}

TEST(RecordFiles, VerticalComponentNames) {
    for (const char* v : {"UP", "Up", "UD", "U-D", "DWN", "V", "VERT", "Vertical", "Z", "HNZ", "BNZ", "hhz"})
        EXPECT_TRUE(is_vertical_component(v)) << v;
    for (const char* h : {"180", "090", "360", "N-S", "EW", "E", "HNE", "BN1", "L", "T", ""})
        EXPECT_FALSE(is_vertical_component(h)) << h;
}

TEST(SweepPlanUnits, TargetPgaNeedsItsUnit) {
    EXPECT_NO_THROW(sweep::check_target_pga_unit("", ""));
    EXPECT_NO_THROW(sweep::check_target_pga_unit("0.1:0.5:0.1", "g"));
    try {
        sweep::check_target_pga_unit("0.1:0.5:0.1", "");
        FAIL() << "levels without a unit were accepted";
    } catch (const std::invalid_argument& e) {
        expect_contains(e.what(), "--target-pga needs --target-pga-unit");
    }
}

const char* two_materials = R"(
[simulation]
duration = 0.1
dt = 1.0e-4
[contact]
kn = 1.0e6
ks = 1.0e6
mu = 0.5
[[contact.pairs]]
materials = ["stone", "steel"]
e = 0.5
[[bodies]]
name = "table"
kind = "fixed"
material = "steel"
shape = "rectangle"
width = 2.0
height = 0.2
center = [0.0, -0.1]
[[bodies]]
name = "block"
material = "stone"
shape = "rectangle"
width = 0.4
height = 0.2
center = [0.0, 0.1]
mass = 1.0
)";

// The warning names the pairs left undamped that can touch a moving body, and only those.
TEST(UndampedContact, WarnsForThePairsWithoutEOrHn) {
    const toml::table root = toml::parse(two_materials);
    const Model model = read_model(root, "two.toml", ".");
    const World w = build_world(model);
    const std::vector<std::string> warnings = input_warnings(root, w);
    ASSERT_EQ(warnings.size(), 1u);
    expect_contains(warnings[0], "so h_n = 0 is used");
    expect_contains(warnings[0], "stone / stone");  // a block may meet another block
    EXPECT_EQ(warnings[0].find("steel / steel"), std::string::npos) << warnings[0];  // only the table is steel
    EXPECT_EQ(warnings[0].find("stone / steel"), std::string::npos) << warnings[0];  // damped by its pair
    toml::table damped = root;
    damped["contact"].as_table()->insert("h_n", 0.0);  // undamped on purpose: no warning
    EXPECT_TRUE(input_warnings(damped, w).empty());
}

}  // namespace
}  // namespace blockdem
