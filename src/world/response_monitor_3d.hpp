#pragma once
// What summary.json reports of each 3-D body (docs/3d.md, "Outputs"): its turn since t = 0, the
// peak tilt about any horizontal axis, whether it overturned, and its slip relative to the table.
//
// Tilt: the angle between the body's line that was vertical at t = 0 and the vertical now,
// acos(e_z . R e_z) with R the turn since t = 0; it is the rocking angle whatever the horizontal
// axis, and a turn about the vertical (twist) leaves it at zero.
// Overturned: the tilt at the end exceeds the body's overturning angle at t = 0,
// atan(d / h), d the horizontal distance from the centroid to the nearest edge of the body's
// lowest face and h the centroid's height above it: the centroid ended beyond that edge, so the
// body did not rock back (the 2-D outcome's rule, world/outcome.hpp, on the initial base).
// Slip: the centroid's horizontal displacement minus the table's.
// Outcome: the 2-D words and rule (world/outcome.hpp, classify_outcomes) from the 3-D record:
// rocked when the peak tilt passed rocking_ratio x the overturning angle; slid when the base's
// pivot corner (the resting face's lowest corner now, which stays put on what it rests on while
// the body rocks about an edge or a corner) moved more than slip_ratio x the face's least width
// over the body it rests on (a twist on the bed counts as slip), by more than elastic_slip_factor
// x the largest elastic shear stretch there, and one of those points slid (the 2-D rule); fell when it let go of every
// body that held it up in the support window and dropped more than fall_drop_ratio x its height.
// The model has no extent in 3-D yet, so no body leaves it.
#include <cstdint>
#include <utility>
#include <vector>

#include "world/outcome.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

struct BodyResponse3d {
    Vec3 start_position_m;        ///< [m] centroid at t = 0
    Quaternion start_orientation; ///< at t = 0
    double overturning_angle_rad = 0.0;  ///< [rad] tilt to topple from t = 0 over its resting face (atan(d / h) on a level one)
    double peak_tilt_rad = 0.0;          ///< [rad]
    double peak_tilt_time_s = 0.0;       ///< [s]
    Vec3 peak_tilt_axis;                 ///< unit, horizontal: the axis it tilted about at the peak
    double peak_slip_m = 0.0;            ///< [m] largest |horizontal slip| so far
    bool beyond_limit = false;           ///< its tilt is past overturning_angle_rad now
    double last_crossing_s = -1.0;       ///< [s] last outward crossing of that limit, -1 if never
    // What the outcome is decided from (above). Fixed at t = 0:
    std::uint32_t support_face = 0;      ///< the face it rests on at t = 0 (its corners are the pivots)
    double height_m = 0.0;               ///< [m] vertical extent at t = 0
    double base_width_m = 0.0;           ///< [m] least width of the resting face
    double bounding_radius_m = 0.0;      ///< [m] farthest vertex from the centroid
    // Followed:
    double peak_base_slip_m = 0.0;       ///< [m] peak horizontal slip of the pivot corner on its supporter
    bool slid_on_support = false;        ///< a contact point with a supporter slid (Coulomb) at some step
    double peak_elastic_shear_m = 0.0;   ///< [m] largest shear spring stretch at those points (|spring| / ks)
    double rocking_onset_s = -1.0;       ///< [s] first time the tilt passed the rocking threshold
    double slip_onset_s = -1.0;          ///< [s] first time the base slip passed the slip threshold
    std::vector<std::uint32_t> supporters;  ///< bodies below it in contact during the support window
    bool touches_a_supporter = true;     ///< touches one of them now
    double support_lost_time_s = -1.0;   ///< [s] when it last let go of its last supporter (-1: holds one)
    double drop_time_s = -1.0;           ///< [s] first time its drop passed fall_drop_ratio x height
    bool at_rest = true;                 ///< slower than rest_speed now
    bool touched_a_body = false;         ///< met another body (any contact) at some step
    /// Rested at some step on a fixed or driven body, or on a body that had (a chain of contacts
    /// to the ground, found as the contacts are noted: ResponseMonitor3d::note_contacts).
    bool rested_on_ground = false;
};

/// The turn of body i since t = 0 (world frame: q(t) q(0)*).
Quaternion turn_since_start(const World3d& w, const BodyResponse3d& r, std::size_t i);
/// [rad] the tilt of a turn (above).
double tilt_rad(Quaternion turn);
/// [m] body i's centroid at w.time_s. A driven body's is the table's at t: the step places it at
/// the start of a step, so between steps its stored position is a step behind.
Vec3 position_now_m(const World3d& w, std::size_t i);
/// [m/s] body i's velocity at w.time_s (a driven body's: the table's, as above).
Vec3 velocity_now_m_s(const World3d& w, std::size_t i);
/// [m] body i's slip relative to the table now (horizontal; z = 0).
Vec3 slip_m(const World3d& w, const BodyResponse3d& r, std::size_t i);

class ResponseMonitor3d {
public:
    explicit ResponseMonitor3d(const World3d& w, const OutcomeThresholds& thresholds = {});
    /// Updates the peaks with the state at w.time_s (call after every step).
    void update(const World3d& w);
    const std::vector<BodyResponse3d>& bodies() const { return bodies_; }
    const OutcomeThresholds& thresholds() const { return thresholds_; }
    bool overturned(const World3d& w, std::size_t i) const;
    /// The records classify_outcomes (world/outcome.hpp) decides each body's outcome from.
    std::vector<BodyRecord> records(const World3d& w) const;
    /// Puts back what a state file kept (io/state_file_3d.hpp); one entry per body.
    void restore(std::vector<BodyResponse3d> bodies) { bodies_ = std::move(bodies); }

private:
    void note_contacts(const World3d& w);
    void follow_support(const World3d& w, std::size_t i, BodyResponse3d& r) const;

    OutcomeThresholds thresholds_;
    std::vector<BodyResponse3d> bodies_;
    std::vector<std::uint8_t> touching_supporter_now_;  ///< per body, this step
};

/// [m] the drop of body i's centroid since t = 0 relative to the table (positive down).
double drop_m(const World3d& w, const BodyResponse3d& r, std::size_t i);

}  // namespace blockdem
