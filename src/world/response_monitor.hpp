#pragma once
// Watches every dynamic body at every step and keeps what the summary reports: peak rotation,
// whether and when it overturned, peak and final displacement relative to the table, and
// whether it slid or rocked (definitions in docs/outputs.md).
//
// Overturning: a body resting on its base tips about a base corner; past the critical angle
// alpha (the angle at that corner between the normal to the base and the line to the centroid,
// atan(b/h) for a b x h half-size rectangle) gravity no longer brings it back. The base is the
// edge facing most nearly down at the start, so a body that starts tilted is judged by its
// base's angle from level (start tilt + rotation). Down and level are gravity's: on a table
// tilted by [simulation] tilt_deg (or a gravity vector) a base along x is tilted by the tilt,
// and a tilting table (tilt_rate_deg_s) adds its change in tilt to every body's. A body has overturned when it ends the run
// tilted beyond alpha; the overturning time is the last time it crossed alpha outwards.
//
// Sliding and rocking are judged on the interface with the body below (its first supporter,
// see below; the table, or the ground, until one is found): a drum in a stack slides or rocks on
// the drum below it, not on the table. Sliding is measured at the base corner the body is
// tipping about (either, when level), along the model's x axis (the table's
// surface, also when the table is tilted by gravity's direction), relative to the point of the supporter that
// was under that corner at the start (the supporter's own rigid motion taken out): rocking moves
// the centroid by about h theta but leaves that corner in place, so a block that rocks without
// sliding shows no base slip. Rocking is the rotation relative to the supporter's. The slip
// threshold lies above the elastic shear displacement of the contacts: it is the larger of
// slip_ratio x the base length and elastic_slip_factor x the largest elastic shear displacement
// (shear spring force / ks) seen at the body's support contacts.
//
// For the outcome of each body (world/outcome.hpp) it also keeps the bodies that held it up at
// the start (its supporters), whether it still touches one and when it last let go of them, how
// far it has dropped relative to the table, and whether it is at rest; records() hands these to
// classify_outcomes.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "world/outcome.hpp"
#include "world/world.hpp"

namespace blockdem {


struct BodyResponse {
    double alpha_ccw_rad = 0.0;          ///< [rad] critical angle tipping counter-clockwise (towards -x)
    double alpha_cw_rad = 0.0;           ///< [rad] critical angle tipping clockwise (towards +x)
    double base_tilt_rad = 0.0;          ///< [rad] the base's angle from level at the start
    Vec2 base_left_offset_m;             ///< [m] base's left corner minus centroid at the start
    Vec2 base_right_offset_m;            ///< [m] base's right corner minus centroid at the start
    double base_length_m = 0.0;          ///< [m]
    double peak_abs_rotation_rad = 0.0;  ///< [rad]
    double time_of_peak_rotation_s = 0.0;///< [s]
    bool beyond_alpha = false;           ///< rotated past alpha now
    double last_crossing_s = -1.0;       ///< [s] last outward crossing of alpha, -1 if never
    double peak_abs_relative_displacement_m = 0.0;  ///< [m] centroid displacement relative to the table
    Vec2 relative_displacement_m;        ///< [m] now
    double base_slip_m = 0.0;            ///< [m] horizontal slip of the base relative to the table, now
    double peak_abs_base_slip_m = 0.0;   ///< [m]
    double sliding_time_s = 0.0;         ///< [s] time with at least one of its contact points sliding
    double rocking_threshold_rad = 0.0;  ///< [rad] rotation above which it counts as rocking (rocking_ratio alpha)
    double slip_threshold_m = 0.0;       ///< [m] slip_ratio x base length (see slip_threshold())
    double start_rotation_rad = 0.0;     ///< [rad] rotation when the monitor started (any body: a supporter's reference)
    std::int64_t support_body = -1;      ///< body whose interface judges sliding and rocking (-1: the ground)
    double peak_abs_rotation_on_support_rad = 0.0;  ///< [rad] peak |rotation relative to the support body|
    double peak_elastic_shear_m = 0.0;   ///< [m] largest |shear spring force| / ks at its support contacts
    double rocking_onset_s = -1.0;       ///< [s] first time |rotation| reached the rocking threshold
    double slip_onset_s = -1.0;          ///< [s] first time it slid beyond the slip threshold

    double height_m = 0.0;               ///< [m] vertical extent at the start
    std::vector<std::uint32_t> supporters;  ///< bodies below it in contact during the support window
    bool touches_a_supporter = false;    ///< now
    double support_lost_time_s = -1.0;   ///< [s] last time it let go of its last supporter (-1: holds one)
    double drop_time_s = -1.0;           ///< [s] first time its centroid was fall_drop_ratio x height below its start
    bool at_rest = true;                 ///< now
    bool touched_a_body = false;         ///< met another body (any contact) at some step
    /// Rested at some step on a fixed or driven body, or on a body that had (a chain of contacts
    /// to the ground, found as the contacts are noted: ResponseMonitor::note_contacts).
    bool rested_on_ground = false;

    bool overturned() const { return beyond_alpha; }
    /// Rocked: it rotated on the body below it by the rocking threshold.
    bool rocked() const { return peak_abs_rotation_on_support_rad >= rocking_threshold_rad; }
    /// [m] base slip above which it counts as sliding: above the contacts' elastic shear.
    double slip_threshold() const { return std::max(slip_threshold_m, elastic_slip_factor * peak_elastic_shear_m); }
    /// Slid: a contact point with the body below slid, and the base moved on it by more than
    /// slip_threshold().
    bool slid() const { return sliding_time_s > 0.0 && peak_abs_base_slip_m > slip_threshold(); }
};

class ResponseMonitor {
public:
    explicit ResponseMonitor(const World& w);
    /// Called once per step with the state at t.
    void observe(const World& w);
    const std::vector<BodyResponse>& responses() const { return responses_; }
    /// Goes on from responses saved earlier in the same run (a restart, io/state_file.hpp): one
    /// per body. What else it holds is recomputed at every step.
    void restore(std::vector<BodyResponse> responses, double start_level_rad);
    double start_level_rad() const { return start_level_rad_; }  ///< [rad] gravity's tilt when it started
    /// What classify_outcomes needs, one record per body (taken-out bodies from w.domain).
    std::vector<BodyRecord> records(const World& w) const;
    const OutcomeThresholds& thresholds() const { return thresholds_; }
    /// The driven body relative to which displacements are measured, or -1 for the ground.
    std::int64_t reference_body() const { return reference_; }

private:
    void note_contacts(const World& w);
    void observe_support(const Bodies& b, std::size_t i, double t_s, BodyResponse& r, Vec2 table_velocity_m_s, Vec2 down);
    void note_support_shear(const World& w, const PairContact& pair, bool a_on_b, bool b_on_a);

    OutcomeThresholds thresholds_;
    std::vector<BodyResponse> responses_;
    std::vector<std::uint8_t> sliding_now_;
    std::vector<std::uint8_t> touching_supporter_now_;
    std::int64_t reference_ = -1;
    double start_level_rad_ = 0.0;   ///< [rad] gravity's tilt when the monitor started
};

/// The angle level makes with the model's x axis at t [rad]: the table's tilt (0 without gravity).
double level_rad(const World& w, double t_s);

}  // namespace blockdem
