#pragma once
// What a simulation is built from: plain definitions with defaults, filled by the scenario
// parser (io/) or by the scene builders (scenes/). No parsing and no printing here.
#include <cstdint>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"
#include "laws/contact_parameters.hpp"
#include "laws/material_stiffness.hpp"
#include "motion/table_motion.hpp"
#include "world/outcome.hpp"

namespace blockdem {

enum class BodyKind : std::uint8_t {
    dynamic,  ///< moves under gravity and contact forces (3 degrees of freedom)
    fixed,    ///< never moves
    driven,   ///< follows the table motion exactly (a shaking table); rotation fixed
};

const char* to_string(BodyKind kind);

/// One rigid convex polygon. Mass and inertia come from density and thickness unless given.
struct BodyDef {
    std::string name;
    BodyKind kind = BodyKind::dynamic;
    std::vector<Vec2> vertices_m;            ///< [m] world positions at t = 0, counter-clockwise, convex
    std::string material = "default";
    double density_kg_m3 = 0.0;              ///< [kg/m^3]
    double thickness_m = 1.0;                ///< [m] out-of-plane thickness
    std::optional<double> mass_kg;           ///< [kg] overrides density * area * thickness
    std::optional<double> inertia_kg_m2;     ///< [kg m^2] about the centroid; default from geometry
    Vec2 velocity_m_s;                       ///< [m/s] initial velocity of the centroid
    double angular_velocity_rad_s = 0.0;     ///< [rad/s] initial, counter-clockwise
    bool record = true;                      ///< write this body to history.csv
    std::string assembly;                    ///< name of the [[assemblies]] entry that made it ("" for [[bodies]])
    /// Bodies with the same nonzero group are bonded where they touch at the start (a bonded
    /// assembly, or [[bodies]] with bonded = true: docs/scenario.md); 0: no bonds.
    std::uint32_t bond_group = 0;
};

/// Contact parameters for every pair of materials (symmetric).
struct MaterialPairs {
    std::vector<std::string> materials;          ///< index = material id
    std::vector<ContactParameters> parameters;   ///< materials.size()^2, row-major
    std::vector<StiffnessOrigin> origins;        ///< like parameters, or empty: every kn and ks given
    /// [m] [contact] rounding: every corner is an arc of this radius (geometry/rounded_contact.hpp); 0: sharp
    double rounding_m = 0.0;
    /// [contact] sub_contacts: the points of an edge-to-edge per-length contact (contact/sub_contacts.hpp)
    std::uint32_t sub_contacts = 2;
    /// Some pair's joints dilate (ContactParameters::tan_dilation > 0): the narrow phase then
    /// keeps dilated points (contact/narrow_phase.cpp). Kept by set, uniform and refresh_any_dilation.
    bool any_dilation = false;

    std::uint32_t id(const std::string& material) const;  ///< throws std::out_of_range
    const ContactParameters& at(std::uint32_t i, std::uint32_t j) const {
        return parameters[i * materials.size() + j];
    }
    void set(std::uint32_t i, std::uint32_t j, const ContactParameters& p);
    void refresh_any_dilation();
    /// One material, one parameter set.
    static MaterialPairs uniform(const ContactParameters& p);
};

/// The fraction of the stable limit a derived dt uses (dt_safety), and the one suggested when a
/// given dt is above the limit.
inline constexpr double default_dt_safety = 0.5;

/// Overlaps deeper than this fraction of the thinner body's least width are reported as a
/// warning: the rigid-body idealisation is then in question.
inline constexpr double overlap_warning_ratio = 0.01;
/// An axis-aligned box [m]; a body whose bounding box lies wholly outside it has left the model.
struct DomainBox {
    Vec2 lo_m;   ///< [m] lower-left corner
    Vec2 hi_m;   ///< [m] upper-right corner
};

struct SimulationSettings {
    double duration_s = 1.0;                 ///< [s]
    std::optional<double> dt_s;              ///< [s]; nullopt: dt_safety * critical time step
    double dt_safety = default_dt_safety;    ///< [-] fraction of the critical step used when dt is derived
    /// [m/s^2] gravity's magnitude; it acts in -y turned by the tilt (gravity_at below)
    double gravity_m_s2 = 9.81;
    /// [rad] the table's tilt at t = 0, counter-clockwise positive (its +x end raised): gravity
    /// in the model's frame is g (-sin tilt, -cos tilt). [simulation] gravity = [gx, gy] sets it
    /// to atan2(-gx, -gy), plus tilt_deg.
    double tilt_rad = 0.0;
    /// [rad/s] the tilt grows at this rate from t = 0 (a tilting-table test; 0 during settling)
    double tilt_rate_rad_s = 0.0;
    double output_interval_s = 1e-3;         ///< [s] between rows of history.csv
    double max_energy_error = 0.5;           ///< [-] stop when the balance error exceeds this fraction
    /// [-] stop when an overlap exceeds this fraction of the least width of the thinner body of
    /// its pair (a contact too soft for its load: bodies sinking into each other)
    double max_overlap_ratio = 0.25;
    /// [simulation] domain: the model's extent; nullopt: derived (world/model_domain.hpp).
    std::optional<DomainBox> domain;
    OutcomeThresholds outcomes;              ///< [outcomes]: thresholds of world/outcome.hpp
};

/// The table's tilt at t [rad] (tilt_rad + tilt_rate_rad_s t).
inline double tilt_at_rad(const SimulationSettings& s, double t_s) { return s.tilt_rad + s.tilt_rate_rad_s * t_s; }

/// Gravity at t in the model's frame [m/s^2]: g (-sin tilt, -cos tilt).
inline Vec2 gravity_at(const SimulationSettings& s, double t_s) {
    const double tilt = tilt_at_rad(s, t_s);
    return {-s.gravity_m_s2 * std::sin(tilt), -s.gravity_m_s2 * std::cos(tilt)};
}

/// How friction acts while settling: "held" (every contact sticks, whatever its shear: the
/// contacts are loaded in place, and the real mu applies from t = 0) or "actual" (the
/// scenario's mu, so that bodies may slide into place while settling).
enum class SettlingFriction { held, actual };

/// The friction coefficient that stands for "held": far above any shear / normal force ratio a
/// contact reaches, yet finite, so that a contact with no normal force still carries no shear.
inline constexpr double held_friction_mu = 1e6;

/// A settling stage before the run (world/settling.hpp): the bodies are stepped under gravity,
/// table at rest, until every dynamic body's kinetic energy / (m g L) stays below kinetic_ratio
/// for window_s (L: its size).
struct SettlingSettings {
    double kinetic_ratio = 1e-8;   ///< [-]
    double window_s = 0.05;        ///< [s]
    double max_time_s = 5.0;       ///< [s] give up (and report) after this much simulated time
    SettlingFriction friction = SettlingFriction::held;
};

struct Model {
    SimulationSettings settings;
    std::optional<SettlingSettings> settling;  ///< settle before t = 0 (build_world does it)
    std::vector<BodyDef> bodies;
    MaterialPairs contact;
    TableMotion table_motion;
};

}  // namespace blockdem
