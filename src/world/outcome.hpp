#pragma once
// What happened to each dynamic body in a run, in one word from a documented set
// (docs/outputs.md, "Outcomes"), decided from what the response monitor recorded, so that the
// rule is a plain function that can be tested on hand-made records. The words, most severe
// first (a body gets the first that applies):
//   left_model  its bounding box left the model's extent (world/model_domain.hpp);
//   fell        it touches none of the bodies that held it up at the start and its centroid
//               ended more than fall_drop_ratio x its height below where it started (relative
//               to the table); or every body that held it up fell or left, and it dropped as
//               much (it came down with them);
//   overturned  it ended the run tilted beyond the critical angle of the base it stood on;
//   rocked_and_slid, rocked, slid   rotation above rocking_ratio x the critical angle, base
//               slip above slip_ratio x the base length;
//   stable      none of these.
// "Held it up" (the supporters): the bodies it touched during the first support_window of the
// run at a contact whose normal, pointing into it, points upwards (n_y > 0.1, within 84 deg of
// vertical): the body below a drum, the course below a brick, not a neighbour beside it.
// A body with no supporters (in flight at the start) cannot fall in this sense.
// An assembly's collapse summary counts the blocks that fell, overturned or left the model, the
// fraction of its mass that ended more than displaced_ratio x its own height from where it
// started, and the first block to go.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

enum class Outcome : std::uint8_t { stable, rocked, slid, rocked_and_slid, overturned, fell, left_model };

/// "stable", "rocked", "slid", "rocked_and_slid", "overturned", "fell", "left_model".
const char* to_string(Outcome outcome);
/// Failure for fragility curves, mode maps and collapse counts: overturned, fell or left_model.
bool is_failure(Outcome outcome);

/// The slip threshold is at least this many times the largest elastic shear displacement seen
/// at a body's support contacts: base slip below it can be the springs' deformation alone.
inline constexpr double elastic_slip_factor = 2.0;

/// [outcomes] in a scenario; every ratio is dimensionless and >= 0.
struct OutcomeThresholds {
    double rocking_ratio = 0.01;      ///< [-] peak |rotation| / critical angle at which a body rocked
    double slip_ratio = 1.0e-3;       ///< [-] peak base slip / base length at which it slid
    double fall_drop_ratio = 0.5;     ///< [-] drop of the centroid / its height at which it fell
    double displaced_ratio = 0.5;     ///< [-] final displacement / its height at which it counts as displaced
    double rest_speed_m_s = 0.01;     ///< [m/s] speed (centroid + bounding radius x |omega|) below which it is at rest
    double support_window_s = 0.01;   ///< [s] its supporters are the bodies below it in contact this early
};

/// What the monitor recorded of one body (world/response_monitor.hpp); times are -1 when the
/// event did not happen.
struct BodyRecord {
    bool dynamic = false;
    double mass_kg = 0.0;                    ///< [kg]
    double height_m = 0.0;                   ///< [m] vertical extent at the start
    bool rocked = false;
    double rocking_time_s = -1.0;            ///< [s] first time |rotation| passed the rocking threshold
    bool slid = false;
    double sliding_time_s = -1.0;            ///< [s] first time the base slip passed the slip threshold
    bool overturned = false;
    double overturning_time_s = -1.0;        ///< [s] last outward crossing of the critical angle
    std::vector<std::uint32_t> supporters;   ///< body ids that held it up at the start
    bool touches_a_supporter = true;         ///< at the end of the run
    double support_lost_time_s = -1.0;       ///< [s] when it last let go of its last supporter (-1: holds one)
    double drop_m = 0.0;                     ///< [m] how far its centroid ended below its start, relative to the table
    double drop_time_s = -1.0;               ///< [s] first time the drop passed fall_drop_ratio x height
    double final_displacement_m = 0.0;       ///< [m] |centroid displacement| relative to the table at the end
    Vec2 final_position_m;                   ///< [m] centroid at the end
    bool at_rest = true;                     ///< slower than rest_speed at the end
    bool touched_a_body = true;              ///< met another body (any contact) at some step of the run
    bool rested_on_ground = true;            ///< touched a fixed or driven body, or one that had, at some step
    bool left_model = false;
    double left_model_time_s = -1.0;         ///< [s]
    Vec2 left_model_position_m;              ///< [m] centroid when it left
};

struct ClassifiedOutcome {
    Outcome outcome = Outcome::stable;
    double time_s = -1.0;                    ///< [s] time of the event that decided it (-1 for stable)
    /// When it started to fail [s]: for fell and left_model the time it let go of its supporters
    /// if it did, else time_s; time_s for overturned; -1 when it did not fail.
    double failure_time_s = -1.0;
    Vec2 rest_position_m;                    ///< [m] fell: where it ended; left_model: where it left
    bool at_rest = true;                     ///< fell: false when still moving at the end ("falling")
};

/// A warning for each dynamic body that touched no other body during the whole run (names[i]:
/// body i's name): it was in free flight from the start, so its outcome, stable with nothing to
/// stand on, says nothing of its stability. Then one for each that touched bodies but never,
/// through them, a fixed or driven body: a group in free flight together (a stack placed beside
/// the table), whose lowest member was reported stable after falling with the others. Both
/// dimensions.
std::vector<std::string> untouched_body_warnings(const std::vector<BodyRecord>& records, const std::vector<std::string>& names,
                                                 double duration_s);

/// A contact between two bodies' responses passes the ground on (a_is_ground, b_is_ground: the
/// body is fixed or driven): one that rests on the ground, or on a body that did, rests on it.
/// Noted at every contact of every observed step in the table's order, a stack on the table is
/// found grounded from its bottom up, at least a body a step.
template <class Response>
void note_ground(Response& a, Response& b, bool a_is_ground, bool b_is_ground) {
    const bool a_grounded = a_is_ground || a.rested_on_ground;
    const bool b_grounded = b_is_ground || b.rested_on_ground;
    a.rested_on_ground = a.rested_on_ground || b_grounded;
    b.rested_on_ground = b.rested_on_ground || a_grounded;
}

/// One outcome per record (index = body id). Records of bodies that are not dynamic get stable.
std::vector<ClassifiedOutcome> classify_outcomes(const std::vector<BodyRecord>& records, const OutcomeThresholds& thresholds);

/// The collapse of a group of bodies (an assembly, or every dynamic body).
struct CollapseSummary {
    std::string group;
    std::size_t blocks = 0;
    std::size_t fell = 0;
    std::size_t overturned = 0;
    std::size_t left_model = 0;
    double displaced_mass_fraction = 0.0;   ///< [-] of the group's mass displaced beyond displaced_ratio x height
    std::int64_t first_to_go = -1;          ///< body id of the failed block with the earliest failure_time_s
    double first_to_go_time_s = -1.0;       ///< [s]
};

CollapseSummary summarize_collapse(const std::string& group, const std::vector<std::uint32_t>& members,
                                   const std::vector<BodyRecord>& records, const std::vector<ClassifiedOutcome>& outcomes,
                                   const OutcomeThresholds& thresholds);

/// The collapse of each assembly, in the order its first dynamic body comes, then of every
/// dynamic body ("all"). group_of_body[i]: the assembly that made body i ("" for none: it is only
/// in "all"); the same length as records.
std::vector<CollapseSummary> summarize_collapse_by_group(const std::vector<std::string>& group_of_body,
                                                         const std::vector<BodyRecord>& records,
                                                         const std::vector<ClassifiedOutcome>& outcomes,
                                                         const OutcomeThresholds& thresholds);

}  // namespace blockdem
