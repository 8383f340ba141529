#pragma once
// A ground-motion record as read from a strong-motion file: equally spaced acceleration in SI,
// and the facts its header states. Readers exist for PEER NGA .AT2 (all header variants seen in
// real files), NIED K-NET/KiK-net ASCII, COSMOS V2, JMA-style CSV and plain text/CSV; the format
// is detected from the content or given. Formats and their quirks: docs/records.md.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace blockdem {

/// The most samples a record (or a motion made from one, padding included) may have: a 1000 Hz
/// record of 5.5 hours; 160 MB per copy of the series.
inline constexpr std::size_t max_record_samples = 20'000'000;
/// [s] The sample intervals accepted (10 microseconds to 1 s): strong-motion records are sampled
/// at 50 to 1000 Hz; outside this range a header or a given dt is wrong.
inline constexpr double min_record_dt_s = 1e-5;
inline constexpr double max_record_dt_s = 1.0;

enum class RecordFormat { automatic, peer_at2, knet, cosmos_v2, jma_csv, plain_text };

/// A record in SI with the header facts it came with. Plain data: print it, copy it.
struct GroundMotionRecord {
    std::string file;                         ///< the file it was read from
    RecordFormat format = RecordFormat::automatic;  ///< the format it was read as
    std::string event;                        ///< event name/date as in the header ("" if absent)
    std::string station;                      ///< station as in the header ("" if absent)
    std::string component;                    ///< component/direction as in the header, e.g. "180", "N-S", "UP"
    std::string units_in_file;                ///< the units as the file (or the user) states them, e.g. "g"
    double to_m_s2 = 1.0;                     ///< [m/s^2 per file unit] the factor applied
    double dt_s = 0.0;                        ///< [s] sample interval
    std::vector<double> acceleration_m_s2;    ///< [m/s^2] samples at t_k = k dt_s
    std::vector<std::string> notes;           ///< what the reader did or noticed (mean removed, extra values)

    std::size_t npts() const { return acceleration_m_s2.size(); }
    /// [s] (npts - 1) dt: time of the last sample.
    double duration_s() const { return npts() > 0 ? static_cast<double>(npts() - 1) * dt_s : 0.0; }
};

/// How to read a file. Empty strings and zero mean "from the file".
struct RecordReadOptions {
    RecordFormat format = RecordFormat::automatic;
    std::string units;       ///< overrides the file's units ("m/s^2", "gal", "g"); required for plain text without units
    double dt_s = 0.0;       ///< [s] for a values-only plain-text file (no time column); 0 = not given
    std::string component;   ///< picks a column (JMA/CSV) or channel (COSMOS); checked against single-component headers
};

/// Reads a record file. Throws InputError naming the file and line for anything malformed.
GroundMotionRecord read_ground_motion_record(const std::filesystem::path& file, const RecordReadOptions& options = {});

/// True when a component name, as record headers write it, denotes the vertical direction: UP,
/// UD (U-D), DN, DWN, DOWN, V, VER, VERT, VERTICAL, Z, or a SEED channel code ending in Z (HNZ,
/// BNZ). Case, blanks and '-' are ignored; azimuths ("090") and N/S/E/W names are horizontal.
bool is_vertical_component(const std::string& component);

/// "auto", "peer-at2", "knet", "cosmos-v2", "jma-csv", "plain".
std::string_view record_format_name(RecordFormat format);
/// The inverse of record_format_name; also accepts "at2", "kiknet", "cosmos", "jma", "csv", "text".
/// Throws std::invalid_argument listing the names for anything else.
RecordFormat parse_record_format(std::string_view name);
/// The format names accepted by parse_record_format, comma-separated (for messages).
std::string record_format_names();

}  // namespace blockdem
