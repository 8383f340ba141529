#pragma once
// The Mohr-Coulomb joint of masonry and rock (as UDEC's joint model with residual strength),
// for one contact point whose stiffness is given per unit area of joint (stiffness =
// "per_length"):
//   stiffness: kn = JKN L t, ks = JKS L t [N/m], with L the point's tributary length of the
//            contact [m] and t the out-of-plane thickness of the thinner body [m]; the point
//            stands for the area A = L t of joint;
//   bonded point (a joint bonded at the start: mortar, an intact rock bridge): the normal
//            spring also pulls, F_n = kn overlap - C_n v_n with overlap < 0 in tension, until
//            F_n < -sigma_t A (tensile failure); the shear spring holds up to
//            c A + mu F_n (shear failure beyond). The step on which either strength is
//            exceeded, the bond breaks for good: cohesion and tension fall to zero and
//            the point continues as a dry one with the residual friction;
//   dry point (never bonded, or broken): the linear spring-dashpot-slider of
//            laws/linear_spring_dashpot.hpp with no tension, friction mu (residual_mu once
//            broken).
// Energy: a breaking bond releases what its springs stored beyond what the dry point keeps;
// that step's whole release (normal spring in tension, shear spring down to the residual cap)
// is booked as bond_breakage_j, so the ledger stays closed.
// Signs as in linear_spring_dashpot.hpp: n from a to b, t = n turned counter-clockwise, forces on b.
#include <cstdint>

#include "geometry/vec2.hpp"

#include "laws/contact_parameters.hpp"
#include "laws/linear_spring_dashpot.hpp"

namespace blockdem {

/// A contact point's bond.
enum class BondState : std::uint8_t {
    none,             ///< never bonded: a dry joint
    intact,           ///< bonded: carries cohesion and tension
    broken_tension,   ///< the bond failed in tension: dry, residual friction
    broken_shear,     ///< the bond failed in shear: dry, residual friction
};

/// True for either broken state.
inline bool is_broken(BondState s) { return s == BondState::broken_tension || s == BondState::broken_shear; }

/// A one-point (corner-to-edge) contact stands for this fraction of the least width of the
/// thinner body of its pair (docs/physics.md, "Joint stiffness per unit length").
inline constexpr double corner_length_fraction = 0.1;

/// The stiffness of one point of a per-length joint, and the joint area it stands for.
struct JointPoint {
    double kn_N_m = 0.0;   ///< [N/m] JKN L t
    double ks_N_m = 0.0;   ///< [N/m] JKS L t
    double area_m2 = 0.0;  ///< [m^2] L t
};

/// JKN L t, JKS L t and L t for a tributary length L [m] and thickness t [m].
JointPoint joint_point(const ContactParameters& p, double tributary_length_m, double thickness_m);

/// The tributary length of each point of a contact [m]: half the distance between the two
/// points of an edge-to-edge contact each; for a one-point contact, the larger of the rounding
/// radius rounding_m [m] (an arc pressed on a face: docs/physics.md) and corner_length_fraction
/// times least_width_m.
double tributary_length_m(std::uint32_t points, Vec2 first_m, Vec2 second_m, double least_width_m,
                          double rounding_m = 0.0);

/// This step's forces and dissipation at one point, and its bond state after the step.
struct JointForce {
    ContactForce force;
    BondState bond = BondState::none;
    double bond_breakage_j = 0.0;  ///< [J] released by a bond that broke this step
};

/// Advances one point of a per-length joint by dt (laws as in the header comment). p: the
/// pair's parameters (friction, strengths); point: its stiffness and area; bond: its state
/// before the step.
JointForce mohr_coulomb_joint(const ContactParameters& p, const JointPoint& point, const DashpotCoefficients& c,
                              const ContactKinematics& k, const ContactHistory& previous, BondState bond, double dt_s);

/// Elastic energy stored in one joint point's springs [J]: the normal spring only in
/// compression unless the bond is intact.
double joint_elastic_energy(const JointPoint& point, double overlap_m, double shear_spring_n, BondState bond);

/// The opening [m] at which an intact bond's spring alone reaches the tensile strength,
/// sigma_t / JKN (the narrow phase keeps bonded points open by up to twice that).
double bond_opening_m(const ContactParameters& p);

}  // namespace blockdem
