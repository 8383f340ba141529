#pragma once
// Limit analysis of a dry-jointed rigid-block assembly: the static (lower-bound) theorem as a
// linear program (Livesley 1978; Gilbert, Casapulla and Ahmed 2006). Each interface between two
// blocks, or between a block and a fixed or driven support, carries a normal force n >= 0 (no
// tension) and a shear force s with |s| <= mu n (Coulomb) at each of its two ends; every movable
// block is in equilibrium (3 equations) under its dead load (its weight, m g downwards) plus
// lambda times a live load (m g along a chosen direction, by default +x: a horizontal body force,
// as a quasi-static ground acceleration lambda g or a table tilted by atan(lambda)). The largest
// such lambda is the collapse multiplier. The LP's dual values of the equilibrium rows are the
// virtual velocities of the blocks in the collapse mechanism, from which each interface is
// classified (hinging at one end, opening, sliding). The friction rule of the LP is associative
// (a slipping interface dilates by mu times its slip, even where it separates): for rocking
// mechanisms the multiplier is exact, where joints slip it is an upper value of the
// non-associative problem, which FrictionFlow::non_associative approaches by iterated LPs
// (docs/limit_analysis.md).
//
// Interfaces are found from the geometry at t = 0 (edges of neighbouring polygons that lie on one
// line within a tolerance and overlap); a corner resting on an edge is not an interface.
// No parsing and no printing here.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"
#include "world/model.hpp"

namespace blockdem {

/// Two bodies whose edges touch along a segment. The normal points from a to b.
struct BlockInterface {
    std::uint32_t body_a = 0;             ///< index into Model::bodies
    std::uint32_t body_b = 0;             ///< index into Model::bodies
    std::array<Vec2, 2> end_m;            ///< [m] the ends of the common segment (a corner on an edge: both at the corner)
    Vec2 normal;                          ///< [-] unit, from a to b (the edge's outward normal, of a or minus b's)
    double mu = 0.0;                      ///< [-] friction of the pair's materials
};

/// Edges of two bodies (at least one of them dynamic) that touch: antiparallel within
/// 1e-4 rad, both ends of one within tolerance_m of the other's line, overlapping by more than
/// tolerance_m. Also a corner of one resting on an edge of the other (the corner within
/// tolerance_m of the edge's line and inside it, its two neighbours outside): a one-point
/// interface, both ends at the corner. In body order (a < b), then edge order, then corners.
std::vector<BlockInterface> find_interfaces(const Model& model, double tolerance_m);

/// How a joint slips in the LP: associative (Coulomb's cone as a plastic potential: a slipping
/// joint opens by mu x its slip; the plain static theorem) or non_associative (slip without
/// dilation, approached by iterated LPs whose friction is a shear capacity mu n taken from the
/// previous solution).
enum class FrictionFlow : std::uint8_t { associative, non_associative };

struct LimitOptions {
    /// [-] the live load's direction (unit vector): lambda m g along it on every dynamic body
    Vec2 live_load_direction{1.0, 0.0};
    /// [m] two edges closer than this touch; <= 0: 1e-6 x the largest body extent
    double touch_tolerance_m = 0.0;
    FrictionFlow friction = FrictionFlow::associative;
    int max_iterations = 200;          ///< non_associative: LPs after the first, at most
    double lambda_tolerance = 1e-6;    ///< [-] non_associative: stop when lambda changes by less
};

enum class LimitStatus : std::uint8_t {
    collapse,        ///< a finite largest lambda (which may be < 0: it cannot stand unaided)
    no_equilibrium,  ///< no lambda at all gives equilibrium (not even its own weight is carried)
    unbounded,       ///< the live load can grow without limit (it is carried by the supports)
};

const char* to_string(LimitStatus status);

/// What an interface does in the collapse mechanism.
enum class InterfaceMotion : std::uint8_t {
    locked,          ///< no relative motion
    hinge_at_end_0,  ///< turns about end 0, end 1 opens
    hinge_at_end_1,  ///< turns about end 1, end 0 opens
    opens,           ///< both ends separate
    slides,          ///< slip along the interface (with or without rocking)
};

const char* to_string(InterfaceMotion motion);

/// The forces on one interface at collapse, acting on body b (a gets the opposite).
struct InterfaceForces {
    std::array<double, 2> normal_N{};     ///< [N] at end 0 and end 1, >= 0
    std::array<double, 2> shear_N{};      ///< [N] along the tangent (the normal turned counter-clockwise)
    /// [-] where the resultant normal force acts, as a fraction of the way from end 0 to end 1
    /// (the thrust line's crossing); NaN when the interface carries nothing
    double thrust_fraction = 0.0;
    Vec2 thrust_point_m;                  ///< [m] that point
};

/// A rigid body's virtual (or small finite) motion: velocity of its centroid and rotation.
struct BodyMotion {
    Vec2 velocity;                        ///< [-] relative units (the mechanism's scale is free)
    double rotation = 0.0;                ///< [1/m] in the same units per metre, counter-clockwise
};

/// The relative motion at an interface's ends and what it means.
struct InterfaceKinematics {
    std::array<double, 2> opening{};      ///< b's motion relative to a along the normal, less mu |slip| (dilation)
    std::array<double, 2> slip{};         ///< along the tangent
    InterfaceMotion motion = InterfaceMotion::locked;
};

struct LimitResult {
    LimitStatus status = LimitStatus::no_equilibrium;
    double lambda = 0.0;                          ///< [-] the collapse multiplier (status collapse)
    std::vector<BlockInterface> interfaces;
    std::vector<InterfaceForces> forces;          ///< per interface (status collapse)
    std::vector<BodyMotion> mechanism;            ///< per body; zero for fixed and driven (status collapse)
    std::vector<InterfaceKinematics> kinematics;  ///< per interface (status collapse)
    std::vector<std::uint32_t> unsupported;       ///< dynamic bodies with no interface at all
    int iterations = 0;                           ///< non_associative: LPs solved after the first
    bool converged = true;                        ///< non_associative: lambda settled within max_iterations
    double interface_search_s = 0.0;              ///< [s] wall-clock time spent finding the interfaces
    double lp_solve_s = 0.0;                      ///< [s] wall-clock time spent in GLPK (every LP)
};

/// The largest lambda and its mechanism. Throws std::invalid_argument for a model without
/// gravity or without a dynamic body.
LimitResult solve_limit_analysis(const Model& model, const LimitOptions& options = {});

/// The relative motion at each interface from the bodies' motions (index = body), classified:
/// a value counts when above relative_tolerance x the largest |opening| or |slip| of any end.
/// dilation = true takes mu |slip| off the opening (the LP's associative flow); false reads a
/// DEM's displacements as they are.
std::vector<InterfaceKinematics> interface_kinematics(const Model& model, const std::vector<BlockInterface>& interfaces,
                                                      const std::vector<BodyMotion>& motions, bool dilation,
                                                      double relative_tolerance = 0.05);

/// The centroid of each body at t = 0 [m] (index = body).
std::vector<Vec2> body_centroids_m(const Model& model);

}  // namespace blockdem
