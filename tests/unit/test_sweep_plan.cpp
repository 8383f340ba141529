// Sweep plans (value lists, case lists, record suites, case numbering) and the results table
// (CSV quoting, the durable log and its recovery after a torn write).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sweep/results_table.hpp"
#include "sweep/sweep_plan.hpp"

namespace blockdem::sweep {
namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("blockdem_test_sweep_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void write(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

TEST(SweepPlan, RangesAreInclusiveUpToRoundOff) {
    EXPECT_EQ(parse_value_list("0:1:0.25"), (std::vector<std::string>{"0", "0.25", "0.5", "0.75", "1"}));
    EXPECT_EQ(parse_value_list("0.1:0.3:0.1"), (std::vector<std::string>{"0.1", "0.2", "0.3"}));
    EXPECT_EQ(parse_value_list("5:1:-2"), (std::vector<std::string>{"5", "3", "1"}));
    EXPECT_THROW(parse_value_list("0:1:0"), std::invalid_argument);
    EXPECT_THROW(parse_value_list("0:1:-1"), std::invalid_argument);
}

TEST(SweepPlan, ListsKeepArraysAndStringsWhole) {
    EXPECT_EQ(parse_value_list("one_sine,one_cosine"), (std::vector<std::string>{"one_sine", "one_cosine"}));
    EXPECT_EQ(parse_value_list("[0, 0.4],[0, 0.8]"), (std::vector<std::string>{"[0, 0.4]", "[0, 0.8]"}));
    EXPECT_EQ(parse_value_list("\"a,b\",c"), (std::vector<std::string>{"\"a,b\"", "c"}));
    EXPECT_EQ(parse_value_list("12:30"), (std::vector<std::string>{"12:30"}));  // not a range: a string
    EXPECT_THROW(parse_value_list("1,,2"), std::invalid_argument);
    const SweepAxis axis = parse_vary("contact.mu=0.3,0.6");
    EXPECT_EQ(axis.keys, (std::vector<std::string>{"contact.mu"}));
    EXPECT_EQ(axis.points.size(), 2u);
    EXPECT_THROW(parse_vary("no_equals_sign"), std::invalid_argument);
}

TEST(SweepPlan, CasesCountTheProductWithTheLastAxisFastest) {
    SweepPlan plan;
    plan.axes.push_back(parse_vary("a=1,2"));
    plan.axes.push_back(parse_vary("b=10,20,30"));
    plan.suite.records = {{"/r/x.at2", "x.at2", {}}, {"/r/y.at2", "y.at2", {}}};
    plan.suite.levels = {"0.5", "1"};
    ASSERT_EQ(plan.case_count(), 2 * 3 * 2 * 2);
    EXPECT_EQ(plan.value_columns(), (std::vector<std::string>{"a", "b", "record", "scale"}));
    const SweepCase first = make_case(plan, 0);
    EXPECT_EQ(first.column_values, (std::vector<std::string>{"1", "10", "x.at2", "0.5"}));
    const SweepCase c = make_case(plan, 1 * 12 + 2 * 4 + 1 * 2 + 1);  // a=2, b=30, y.at2, 1
    EXPECT_EQ(c.column_values, (std::vector<std::string>{"2", "30", "y.at2", "1"}));
    ASSERT_EQ(c.assignments.size(), 2u);
    EXPECT_EQ(c.assignments[1].key, "b");
    const std::vector<Assignment> rec = record_assignments(plan.suite, c);
    EXPECT_EQ(rec.front().key, "table_motion.horizontal.type");
    EXPECT_EQ(rec.back().key, "table_motion.horizontal.scale");
    EXPECT_EQ(rec.back().value, "1");
    plan.suite.scaling = RecordScaling::target_pga;
    EXPECT_EQ(plan.value_columns().back(), "target_pga_g");
}

TEST(SweepPlan, CaseListAndRecordListFiles) {
    const auto dir = scratch("lists");
    write(dir / "cases.csv", "# period and duration together\nperiod,duration\n0.5,10\n1,\"20\"\n");
    const SweepAxis axis = read_case_list(dir / "cases.csv");
    EXPECT_EQ(axis.keys, (std::vector<std::string>{"period", "duration"}));
    ASSERT_EQ(axis.points.size(), 2u);
    EXPECT_EQ(axis.points[1][1], "20");
    write(dir / "bad.csv", "a,b\n1\n");
    EXPECT_THROW(read_case_list(dir / "bad.csv"), std::invalid_argument);

    write(dir / "suite.txt", "# a suite\nsub/one.AT2\nvalues.dat dt=0.02 unit=g  # values only\n");
    const auto suite = read_record_suite(dir / "suite.txt");
    ASSERT_EQ(suite.size(), 2u);
    EXPECT_EQ(suite[0].file, (dir / "sub/one.AT2").lexically_normal());
    EXPECT_EQ(suite[1].label, "values.dat");
    ASSERT_EQ(suite[1].keys.size(), 2u);
    EXPECT_EQ(suite[1].keys[1].value, "g");

    std::filesystem::create_directories(dir / "folder");
    write(dir / "folder/b.AT2", "x");
    write(dir / "folder/a.AT2", "x");
    write(dir / "folder/a.AT2.json", "{}");
    write(dir / "folder/.hidden", "x");
    const auto listed = read_record_suite(dir / "folder");
    ASSERT_EQ(listed.size(), 2u);
    EXPECT_EQ(listed[0].label, "a.AT2");
}

TEST(SweepResults, CsvFieldsAreQuotedOnlyWhenNeeded) {
    EXPECT_EQ(csv_field("plain"), "plain");
    EXPECT_EQ(csv_field("a, b"), "\"a, b\"");
    EXPECT_EQ(csv_field("say \"x\"\nnext"), "\"say \"\"x\"\" next\"");
    EXPECT_EQ(split_csv_line("1,\"a, b\",\"q\"\"\",,x"), (std::vector<std::string>{"1", "a, b", "q\"", "", "x"}));
}

TEST(SweepResults, LogKeepsRowsAndCutsATornLastLine) {
    const auto dir = scratch("log");
    const auto file = dir / "finished_cases.csv";
    {
        FinishedCasesLog log(file, "case_id,x");
        log.append(3, "3,c");
        log.append(0, "0,a");
    }
    {
        std::ofstream(file, std::ios::app) << "7,tor";  // a write cut short by a kill
    }
    FinishedCasesLog again(file, "case_id,x");
    ASSERT_EQ(again.rows().size(), 2u);
    EXPECT_EQ(again.rows().begin()->second, "0,a");
    again.append(7, "7,torn no more");
    write_sorted_results(dir / "results.csv", "case_id,x", again.rows());
    std::ifstream in(dir / "results.csv");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "case_id,x\n0,a\n3,c\n7,torn no more\n");
    EXPECT_THROW(FinishedCasesLog(file, "case_id,y"), std::runtime_error);
}

}  // namespace
}  // namespace blockdem::sweep
