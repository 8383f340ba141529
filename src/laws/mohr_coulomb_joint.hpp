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
//            broken);
//   dilation (as UDEC's joint dilation angle psi; dry points only): the point carries its
//            accumulated dilation u_d [m], and its normal spring and dashpot act on overlap + u_d.
//            A step on which the slider slips by du_p (the part of this step's shear
//            displacement that the spring does not take) adds tan(psi) du_p to u_d, and this
//            step's normal force already includes it: u_d, the normal force and the friction cap
//            are solved together (closed form: the cap rises with the slip), so the point ends
//            on its Coulomb cap. In steady sliding du_p is the whole shear increment, UDEC's
//            |du_s|. With dilation_zero_slip z, u_d stops at tan(psi) z. A confined joint's
//            normal force rises by kn du_d; a free one opens.
// Energy: a breaking bond releases what its springs stored beyond what the dry point keeps;
// that step's whole release (normal spring in tension, shear spring down to the residual cap)
// is booked as bond_breakage_j, so the ledger stays closed. A dilating step moves
// (F_n,last + F_n) du_d / 2 (the normal force's trapezoid over the dilation) from the slip's
// friction work into the normal spring and dashpot: the normal element then takes from the
// bodies what it stores and damps on overlap + u_d, and the ledger closes per step
// (docs/physics.md, "Dilation").
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
    double dilation_m = 0.0;       ///< [m] the point's accumulated dilation u_d after the step
};

/// What a dilating point carries from the last step besides ContactHistory.
struct DilationHistory {
    double dilation_m = 0.0;      ///< [m] accumulated dilation u_d before the step
    double normal_force_n = 0.0;  ///< [N] last step's normal force (spring and dashpot), for the dilation's work
};

/// Advances one point of a per-length joint by dt (laws as in the header comment). p: the
/// pair's parameters (friction, strengths); point: its stiffness and area; bond: its state
/// before the step; dilation: u_d and last step's normal force (read only where p.tan_dilation > 0).
JointForce mohr_coulomb_joint(const ContactParameters& p, const JointPoint& point, const DashpotCoefficients& c,
                              const ContactKinematics& k, const ContactHistory& previous, BondState bond, double dt_s,
                              const DilationHistory& dilation = {});

/// Elastic energy stored in one joint point's springs [J]: the normal spring (on overlap +
/// dilation_m) only in compression unless the bond is intact.
double joint_elastic_energy(const JointPoint& point, double overlap_m, double shear_spring_n, BondState bond,
                            double dilation_m = 0.0);

/// The opening [m] at which an intact bond's spring alone reaches the tensile strength,
/// sigma_t / JKN (the narrow phase keeps bonded points open by up to twice that).
double bond_opening_m(const ContactParameters& p);

}  // namespace blockdem
