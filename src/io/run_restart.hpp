#pragma once
// What `blockdem run --restart STATE.h5` does to the files of the run it continues
// (docs/outputs.md, "State files"): history.csv and energy.csv keep their header and the rows
// written before the state (StateFileInfo::output_rows; an interrupted run wrote one more, at the
// time it stopped, which goes), and the run appends to them, so that the files end as those of
// a run that never stopped. Continued in the run's own folder, the files are cut back in place;
// in a new folder, they are copied first.
#include <cstdint>
#include <filesystem>

#include "io/state_file.hpp"

namespace blockdem {

/// The folder of the run a state file belongs to: the folder above its state/ folder when that
/// holds the run's scenario.toml (the folder may have moved), else the folder it was written in.
std::filesystem::path state_run_folder(const std::filesystem::path& state_file, const StateFileInfo& info);

/// Keeps the header and the first `rows` rows of the CSV file `from`, in place (to == from) or as
/// a copy to `to`. Throws InputError when `from` is missing or has fewer rows (not the files of
/// this state's run), OutputError when the copy cannot be written.
void keep_first_rows(const std::filesystem::path& from, const std::filesystem::path& to, std::int64_t rows);

/// keep_first_rows for a file whose header follows comment lines starting with '#' (sensors.csv,
/// interfaces.csv). Rows are lines: interfaces.csv has one per (time, pair), and its count comes
/// from the state's /interfaces group (io/measurement_state_parts.hpp), not from output_rows.
void keep_rows_after_comments(const std::filesystem::path& from, const std::filesystem::path& to, std::int64_t rows);

}  // namespace blockdem
