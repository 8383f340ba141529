#pragma once
// summary.json: per body its outcome (world/outcome.hpp) with the peak rotation, overturning,
// sliding and rocking, displacement relative to the table; per assembly its collapse; the
// model's extent and the bodies that left it; the run's checks and warnings (io/run_checks.hpp);
// for the run its status and the energy balance. Written at the end of a run, and also when the
// run stops on an error (status "failed" with the message) or on a signal (status
// "interrupted"). Written whole or not at all (io/output_file.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/outcome.hpp"
#include "world/response_monitor.hpp"
#include "world/world.hpp"

namespace blockdem {

struct RunInfo {
    std::string scenario;        ///< scenario file
    std::string status;          ///< "completed", "failed" or "interrupted" (SIGINT / SIGTERM)
    std::string error;           ///< the message when failed
    // (The wall-clock time is in run_info.json: summary.json holds results only, the same
    // byte for byte for a run and for the same run stopped and restarted.)
};

nlohmann::json make_summary(const World& w, const ResponseMonitor& monitor, const RunInfo& info);
void write_summary(const std::filesystem::path& file, const nlohmann::json& summary);
/// summary.json's "settling": what settling did before t = 0, or null (both dimensions).
nlohmann::json settling_summary(const std::optional<SettlingRecord>& settled);
/// summary.json's "collapse" (both dimensions): one entry per group of
/// summarize_collapse_by_group, its first block to go named from body_names.
nlohmann::json collapse_json(const std::vector<CollapseSummary>& groups, const std::vector<std::string>& body_names);

}  // namespace blockdem
