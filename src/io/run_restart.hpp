#pragma once
// What `blockdem run --restart STATE.h5` does to the files of the run it continues
// (docs/outputs.md, "State files"): history.csv and energy.csv keep their header and the rows
// written before the state (StateFileInfo::output_rows; an interrupted run wrote one more, at the
// time it stopped, which goes), and the run appends to them, so that the files end as those of
// a run that never stopped. Continued in the run's own folder, the files are cut back in place;
// in a new folder, they are copied first.
#include <cstdint>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "io/state_file.hpp"

namespace blockdem {

/// The refusal of a restart whose bodies changed mass or shape (why: the mismatch): the state's
/// momenta, contact overlaps and energy ledger are those of the bodies it was saved with, so a
/// run under the changed bodies would go on from a state they never were in.
inline std::string restart_body_change(const std::filesystem::path& scenario, const std::string& why) {
    return fmt::format("the state does not belong to scenario {}: {}; a restart goes on with the bodies the state was "
                       "saved with (to start changed bodies from it, give it as [simulation] initial_state: a new run)",
                       scenario.string(), why);
}

/// The folders and the scenario of a restart (docs/outputs.md, "Restart").
struct RestartFolders {
    std::filesystem::path run_folder;  ///< the run the state belongs to: its rows and frames are read there
    std::filesystem::path scenario;    ///< the scenario given, else run_folder/scenario.toml
    std::filesystem::path out_dir;     ///< --out, else run_folder (the run goes on in place)
};

/// A state in a folder named state/ belongs to the folder above it, wherever the run was first
/// written (the folder may have been moved or copied): nothing is read from, or written to, the
/// folder in the state's attributes then. A state anywhere else (a file copied out of its run)
/// reads the rows before it from the folder it was written in (the state's run_folder), and goes
/// on only into an --out given. Throws InputError naming the state file, or the missing
/// scenario.toml, when the restart has no scenario or no folder to write to.
RestartFolders restart_folders(const std::filesystem::path& state_file, const StateFileInfo& info,
                               const std::filesystem::path& scenario, const std::filesystem::path& out_dir);

/// Keeps the header and the first `rows` rows of the CSV file `from`, in place (to == from) or as
/// a copy to `to`. Throws InputError when `from` is missing or has fewer rows (not the files of
/// this state's run), OutputError when the copy cannot be written.
void keep_first_rows(const std::filesystem::path& from, const std::filesystem::path& to, std::int64_t rows);

/// keep_first_rows for a file whose header follows comment lines starting with '#' (sensors.csv,
/// interfaces.csv). Rows are lines: interfaces.csv has one per (time, pair), and its count comes
/// from the state's /interfaces group (io/measurement_state_parts.hpp), not from output_rows.
void keep_rows_after_comments(const std::filesystem::path& from, const std::filesystem::path& to, std::int64_t rows);

}  // namespace blockdem
