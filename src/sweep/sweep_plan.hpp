#pragma once
// What a sweep runs: the cartesian product of its axes. An axis is one `--vary key=...` (one
// column), or a case list `--cases FILE` (several columns varied together, one row per point),
// or the record suite `--records` (one record per point) times its scaling levels (`--scale`
// factors or `--target-pga` levels). The first axis varies slowest; case ids count the product
// in that order, so that a case id names the same case on every thread, rank and rerun.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace blockdem::sweep {

/// `key=value` as `--set` takes it.
struct Assignment {
    std::string key;
    std::string value;
};

/// One axis: its columns (scenario keys) and, per point, one value per column (TOML text).
struct SweepAxis {
    std::vector<std::string> keys;
    std::vector<std::vector<std::string>> points;
};

/// One record of the suite, and the record keys it needs (e.g. dt = 0.02 and units = "g" for
/// a file of values only): keys of `[table_motion.horizontal]` with type = "record".
struct RecordEntry {
    std::filesystem::path file;   ///< absolute
    std::string label;            ///< as listed (file name, or the path in the list file)
    std::vector<Assignment> keys;
};

/// How each record is scaled at each level.
enum class RecordScaling { factor, target_pga };

struct RecordSuite {
    std::vector<RecordEntry> records;          ///< empty: no record axis
    RecordScaling scaling = RecordScaling::factor;
    std::vector<std::string> levels{"1"};      ///< factors [-], or target PGAs in pga_unit
    /// m/s^2, gal or g. `blockdem sweep` refuses target PGA levels without their unit
    /// (check_target_pga_unit), so this default never reaches them; it stays because every
    /// sweep's fingerprint hashes it, and a changed fingerprint would stop old sweeps resuming.
    std::string pga_unit = "g";
    std::vector<Assignment> common_keys;       ///< --record-key, for every record
};

struct SweepPlan {
    std::vector<SweepAxis> axes;   ///< --vary and --cases, in command-line order
    RecordSuite suite;

    std::int64_t case_count() const;
    /// Throws std::invalid_argument naming a key varied twice (by two --vary, or a --vary and a
    /// column of --cases): the results would hold two columns of it, the last one winning.
    void check_keys_distinct() const;
    /// Column names of the varied values, in order: every axis key, then "record" and
    /// "scale" or "target_pga_<unit>" when there is a suite.
    std::vector<std::string> value_columns() const;
};

/// One case: the --set assignments, and the record with its level when there is a suite.
struct SweepCase {
    std::int64_t id = 0;
    std::vector<Assignment> assignments;
    std::vector<std::string> column_values;   ///< aligned with value_columns()
    const RecordEntry* record = nullptr;
    std::string level;
};

/// Parses `key=start:stop:step` (inclusive, up to round-off) or `key=v1,v2,...` (commas inside
/// [] or quotes do not split). Throws std::invalid_argument naming the problem.
SweepAxis parse_vary(const std::string& spec);

/// Splits one CSV line into fields: commas split except inside double quotes ("" is a quote).
std::vector<std::string> split_csv_line(const std::string& line);

/// Parses a value list: "a:b:step" or "v1,v2,...".
std::vector<std::string> parse_value_list(const std::string& text);

/// Reads a case list: CSV, first line the keys, then one row per point (quote a value that
/// holds commas). Throws std::invalid_argument naming the file and line.
SweepAxis read_case_list(const std::filesystem::path& file);

/// A directory (every regular file in it but *.json, *.md and hidden ones, sorted by name) or a
/// list file (one record a line: `path [key=value ...]`, '#' starts a comment, paths relative
/// to the list file). Throws std::invalid_argument.
std::vector<RecordEntry> read_record_suite(const std::filesystem::path& path);

/// Refuses (std::invalid_argument, naming the option and the fix) target PGA levels (the text
/// of --target-pga) given without their unit (--target-pga-unit, empty when not given). A target
/// PGA is read in the unit given with it, m/s^2 when none is, as every acceleration in a
/// scenario; `blockdem sweep` used to take g without saying so, so rather than change the
/// meaning of an old command silently, a sweep's levels must name their unit.
void check_target_pga_unit(const std::string& levels, const std::string& unit);

/// Case `id` of the plan (0 <= id < case_count()).
SweepCase make_case(const SweepPlan& plan, std::int64_t id);

/// The override text for the record of a case: assignments under table_motion.horizontal.
std::vector<Assignment> record_assignments(const RecordSuite& suite, const SweepCase& c);

}  // namespace blockdem::sweep
