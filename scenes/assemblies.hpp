#pragma once
// Block-assembly generators (issue 5), shared by the scenario keys ([[assemblies]],
// io/assembly_keys.hpp), the tests and the benchmarks. Each returns plain polygons or BodyDefs;
// docs/assemblies.md describes every parameter with a picture in words.
//
//   block_column       drums of a column, each (width, height), stacked and centred;
//   masonry_wall       running bond, flat or stepped ends, openings (window, door) with lintels;
//   s3_wall_scene      the peers' scene S3 (../shared/peers/common/scen.h): N bricks 0.2 x 0.1 m;
//   jointed_rock_mass  a region (convex or not) cut by joint sets (dip, spacing, random spread);
//   voronoi_packing    a region cut into the Voronoi cells of jittered-grid seeds (rockfill).
// Blocks are numbered in the order made, and each generator is deterministic for a given seed
// (its own 64-bit generator, not std::*_distribution, whose output differs between libraries).
#include <cstdint>
#include <string>
#include <vector>

#include "world/model.hpp"

namespace blockdem::scenes {

using Polygon = std::vector<Vec2>;  ///< counter-clockwise corners [m]

/// How generated blocks become bodies: names are prefix + number (from 0).
struct BlockStyle {
    std::string name_prefix = "block";
    std::string material = "default";
    double density_kg_m3 = 2500.0;  ///< [kg/m^3]
    double thickness_m = 1.0;       ///< [m] out of plane
    bool record = false;            ///< write every block to history.csv (off: large assemblies)
};

/// Dynamic bodies from polygons, named prefix0, prefix1, ...
std::vector<BodyDef> as_bodies(const std::vector<Polygon>& polygons, const BlockStyle& style);

/// Makes every body whose centroid lies inside zone (a polygon, convex or not) of the given kind:
/// the fixed or driven boundary of a rock mass (its foundation and its back), as UDEC fixes
/// the blocks along a model's boundary. Returns how many bodies changed.
std::size_t set_kind_inside(std::vector<BodyDef>& bodies, const Polygon& zone, BodyKind kind);

/// A column of blocks stacked from base_center_m upwards; sizes_m[i] = (width, height) [m].
std::vector<Polygon> block_column(const std::vector<Vec2>& sizes_m, Vec2 base_center_m);

/// A rectangular opening in a wall [m], relative to the wall's lower-left corner. Its bottom
/// and top are rounded to whole courses. lintel_bearing_m > 0 puts one lintel block over it,
/// reaching that far onto the masonry on each side.
struct WallOpening {
    double x_m = 0.0;
    double y_m = 0.0;
    double width_m = 0.0;
    double height_m = 0.0;
    double lintel_bearing_m = 0.0;
};

struct WallSpec {
    Vec2 origin_m;                  ///< [m] lower-left corner of the wall
    double length_m = 2.0;          ///< [m]
    int courses = 10;
    double brick_length_m = 0.2;    ///< [m]
    double brick_height_m = 0.1;    ///< [m]
    bool stepped_ends = false;      ///< odd courses half a brick shorter at each end (no half bricks)
    double min_piece_fraction = 0.25;  ///< remainders shorter than this x brick length join their neighbour
    std::vector<WallOpening> openings;
};

/// A running-bond wall: course r has joints at k L (r even) or (k + 1/2) L (r odd).
std::vector<Polygon> masonry_wall(const WallSpec& spec);

/// Scene S3 of the peers (signals.md): N bricks 0.2 x 0.1 m in C = round(sqrt(2N)) columns,
/// odd rows C - 1 bricks shifted by 0.1 m, 40 kg each, on a driven table shaken at
/// 0.3 g sin(4 pi t); mu = 0.6, kn = ks = 6e7 N/m (a full-face contact period of about 50 steps
/// at dt = 1e-4 s, as in the LAMMPS run), e = 0.5 (rebound meaning).
Model s3_wall_scene(int bricks, double duration_s = 1.0, double dt_s = 1e-4);

/// A keyed brick (concave, 20 corners): L x H with two tongues on top and two grooves below,
/// w wide and t deep, centred at L/4 and 3L/4 from its left end, so that a brick of the next
/// course, shifted by L/2, takes the tongues of the two below it. Lower-left corner of the
/// L x H body at origin_m; the tongues rise to H + t. Counter-clockwise.
Polygon keyed_brick(Vec2 origin_m, double length_m, double height_m, double key_width_m, double key_depth_m);

/// Scene S3 with keyed bricks (concave bodies, docs/performance.md): the same table, motion,
/// contact and course layout as s3_wall_scene, every brick 0.2 x 0.1 m with 0.04 x 0.02 m keys
/// that fit exactly, 40 kg each. dt is derived (dt_safety x the stable limit): a keyed brick
/// touches its neighbours at many more points than a plain one, which S3's 1e-4 s exceeds.
Model keyed_wall_scene(int bricks, double duration_s = 1.0);

/// Scene S3 with bonded joints (docs/performance.md, "Joints"): the same bricks, table and
/// motion, stiffness per length JKN = JKS = 1.2e9 Pa/m (a point standing for 0.05 m of a 1 m
/// deep joint, the end of a bed or head joint of S3, then has S3's 6e7 N/m), cohesion 2e5 Pa
/// and tensile strength 1e5 Pa, every brick bonded to the bricks it touches at the start (not
/// to the table). The strengths are well above the 0.3 g wall's stresses, so the bonds stay
/// intact: the scene times an intact bonded wall.
Model bonded_wall_scene(int bricks, double duration_s = 1.0);

/// One set of parallel joints. The dip is the angle of the joint trace from +x, counter-
/// clockwise [deg]; spacing is measured normal to the joints; each gap is spacing x (1 + spacing
/// spread x u) and each joint's dip is dip + dip spread x u, u uniform in [-1, 1].
struct JointSet {
    double dip_deg = 0.0;
    double spacing_m = 1.0;
    double spacing_spread = 0.0;    ///< [-] in [0, 1)
    double dip_spread_deg = 0.0;    ///< [deg]
    Vec2 origin_m;                  ///< [m] a point on one joint of the set
};

struct RockMassSpec {
    Polygon region_m;                ///< [m] outline, convex or not, either orientation
    std::vector<JointSet> joint_sets;
    std::uint64_t seed = 1;
    double min_block_area_m2 = 0.0;  ///< [m^2] smaller blocks are dropped (0: keep all)
};

struct GeneratedBlocks {
    std::vector<Polygon> polygons;
    std::size_t dropped = 0;         ///< blocks below the minimum area (or slivers at round-off)
    double dropped_area_m2 = 0.0;    ///< [m^2]
};

/// The region cut into convex blocks by every joint of every set (full persistence).
GeneratedBlocks jointed_rock_mass(const RockMassSpec& spec);

/// A slope cross-section with its toe at the origin: a base layer of base_height_m under the
/// whole section, toe_length_m of flat ground in front of the toe, a face rising at face_deg to
/// height slope_height_m above the base, and crest_length_m of flat top behind the crest.
/// Non-convex whenever toe_length_m > 0.
Polygon slope_region(double base_height_m, double slope_height_m, double face_deg, double toe_length_m,
                     double crest_length_m);

struct VoronoiSpec {
    Polygon region_m;                ///< [m] outline, convex or not
    double cell_size_m = 0.1;        ///< [m] seeds on a square grid of this pitch
    double jitter = 1.0;             ///< [-] 0: a regular grid (squares), 1: anywhere in its grid cell
    std::uint64_t seed = 1;
    double shrink = 0.0;             ///< [-] scale each cell about its centroid by 1 - shrink (gaps)
};

/// The region cut into the Voronoi cells of jittered-grid seeds (exact cells, clipped to the region).
GeneratedBlocks voronoi_packing(const VoronoiSpec& spec);

/// Upper estimates of how many blocks a generator makes, from its spec alone and in double (the
/// spec may be absurd: a wall 1e9 m long), so that a scenario can be refused before generating.
/// Wall: courses x (length / brick length + 2 + 2 per opening). Rock mass: the faces of the
/// joint lines' arrangement, 1 + sum n_i + sum_{i<j} n_i n_j, plus the pieces of a non-convex
/// region, with n_i the lines of set i across the region at its smallest spacing. Voronoi: the
/// seed grid's cells.
double estimated_block_count(const WallSpec& spec);
double estimated_block_count(const RockMassSpec& spec);
double estimated_block_count(const VoronoiSpec& spec);

}  // namespace blockdem::scenes

namespace blockdem::scenes {

/// A jointed rock slope of about `blocks` blocks (two joint sets: -20 deg and 80 deg, 20%
/// spacing spread, seeded) on a driven table shaken like S3, its foundation and back blocks
/// driven with the table; rock 2600 kg/m^3, mu = 0.6.
Model rock_slope_scene(int blocks, double duration_s = 1.0);

/// A dense Voronoi rockfill of about `blocks` blocks in a 2:1 box on a driven table shaken like S3.
Model rockfill_scene(int blocks, double duration_s = 1.0);

}  // namespace blockdem::scenes

namespace blockdem::scenes {

/// A masonry arch with radial joints (scenes/arch.cpp): a circular ring of `voussoirs` equal
/// blocks (each a trapezoid between two radial joints, its faces the chords of the intrados and
/// the extrados) springing from two abutment blocks whose top faces are the springing joints.
/// The centre line (radius R, midway through the ring) springs from origin_m +- (span/2, 0) and
/// rises rise_m above them: R = (span^2 / 4 + rise^2) / (2 rise); rise = span / 2 is a
/// semicircle. Each abutment lies under its springing joint, abutment_height_m deep below the
/// lower end of that joint.
struct ArchSpec {
    Vec2 origin_m;                  ///< [m] midpoint between the centre line's springings
    double span_m = 2.0;            ///< [m] of the centre line, < 10 km
    double rise_m = 1.0;            ///< [m] of the centre line, in [span / 1000, span / 2]
    double ring_thickness_m = 0.15; ///< [m] radial, < 2 R
    int voussoirs = 20;             ///< >= 3
    double abutment_height_m = 0.0; ///< [m] <= 0: the ring thickness
};

struct ArchBlocks {
    std::vector<Polygon> voussoirs;   ///< from the left springing to the right one
    Polygon left_abutment;
    Polygon right_abutment;
};

/// The centre line's radius [m] of an arch of that span and rise.
double arch_radius_m(double span_m, double rise_m);

/// The arch's blocks. Throws std::invalid_argument naming the parameter for values out of range.
ArchBlocks masonry_arch(const ArchSpec& spec);

/// The arch's bodies: the voussoirs dynamic, named prefix0, prefix1, ... from the left, then
/// prefix_left_abutment and prefix_right_abutment of the given kind (fixed or driven).
std::vector<BodyDef> arch_bodies(const ArchBlocks& arch, const BlockStyle& style, BodyKind abutments);

}  // namespace blockdem::scenes
