#pragma once
// The per-format readers behind read_ground_motion_record(), one file each, and what they share.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "motion/records/acceleration_units.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/records/record_text.hpp"

namespace blockdem::records {

GroundMotionRecord read_peer_at2(const RecordText& text, const RecordReadOptions& options);
GroundMotionRecord read_knet(const RecordText& text, const RecordReadOptions& options);
GroundMotionRecord read_cosmos_v2(const RecordText& text, const RecordReadOptions& options);
GroundMotionRecord read_jma_csv(const RecordText& text, const RecordReadOptions& options);
GroundMotionRecord read_plain_text(const RecordText& text, const RecordReadOptions& options);

/// The NPTS/DT phrase of an AT2 header line as written: "NPTS= 4000, DT= .0100 SEC" anywhere on
/// the line, or "4096  0.0100  NPTS, DT" at its start. dt may be empty ("DT= SEC").
struct NptsDtText {
    std::string_view npts;
    std::string_view dt;
};
std::optional<NptsDtText> find_npts_dt_phrase(std::string_view line);

/// The count of "<type> (Format v01.20 with N text lines)", the first line of a COSMOS block.
/// `need_version` also requires the "Format vX.Y" before it (format detection).
std::optional<std::string_view> cosmos_text_line_count(std::string_view line, bool need_version);

/// The format, from the first lines of the content (never from the file name).
RecordFormat detect_record_format(const RecordText& text);

/// m/s^2 per file unit: the user's override when given, else file_units (as stated at line
/// `line`). An unknown unit is an InputError at that line (or naming the option).
double resolve_units(const RecordText& text, const RecordReadOptions& options, const std::string& file_units,
                     std::size_t line);

/// True when two component names denote the same direction: case, blanks and '-' ignored,
/// numbers compared as numbers ("067" = "67", "N-S" = "ns").
bool same_component(const std::string& a, const std::string& b);

/// Refuses, at line `line`, a sample interval outside min_record_dt_s..max_record_dt_s.
void check_sample_interval(const RecordText& text, std::size_t line, double dt_s);

/// For single-component files: an asked-for component that differs from the header's is an
/// InputError at the header line, so that a wrong file is not silently used.
void check_component(const RecordText& text, const RecordReadOptions& options, const std::string& header_component,
                     std::size_t line);

/// Refuses a value that to_m_s2 takes beyond the range of a double (1e308 g): an InputError at
/// its line, which line_of(k) gives for value k (asked only then: the readers' layouts differ,
/// and finding a line may walk the file).
void check_si_range(const RecordText& text, const std::vector<double>& in_file, double to_m_s2,
                    const std::function<std::size_t(std::size_t)>& line_of);

/// Scales counts or file units to m/s^2 in place, after check_si_range.
void convert_to_si(const RecordText& text, GroundMotionRecord& record, double to_m_s2,
                   const std::function<std::size_t(std::size_t)>& line_of);

}  // namespace blockdem::records
