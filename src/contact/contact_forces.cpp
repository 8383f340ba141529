#include "contact/contact_forces.hpp"

#include "laws/linear_spring_dashpot.hpp"

namespace blockdem {
namespace {

ContactParameters softened(ContactParameters p, double scale) {
    p.kn_N_m *= scale;
    p.ks_N_m *= scale;
    return p;
}

}  // namespace

ContactDissipation apply_contact_law(World& w) {
    Bodies& b = w.bodies;
    ContactDissipation lost;
    for (PairContact& pair : w.contacts) {
        if (pair.count == 0) continue;
        const std::uint32_t ia = pair.a;
        const std::uint32_t ib = pair.b;
        const ContactParameters params = softened(w.contact.at(b.material[ia], b.material[ib]), pair.stiffness_scale);
        const double reduced_mass = 1.0 / (b.inv_mass_1_kg[ia] + b.inv_mass_1_kg[ib]);
        const DashpotCoefficients dash = dashpot_coefficients(params, reduced_mass / pair.count);
        const Vec2 n = pair.normal;
        const Vec2 t = perp(n);
        for (std::uint32_t k = 0; k < pair.count; ++k) {
            ContactPoint& point = pair.points[k];
            const Vec2 ra = point.point_m - b.position_m[ia];
            const Vec2 rb = point.point_m - b.position_m[ib];
            const Vec2 relative = (b.velocity_m_s[ib] + cross(b.angular_velocity_rad_s[ib], rb)) -
                                  (b.velocity_m_s[ia] + cross(b.angular_velocity_rad_s[ia], ra));
            const ContactKinematics kin{point.overlap_m, dot(relative, n), dot(relative, t)};
            const ContactForce f = linear_spring_dashpot(params, dash, kin, point.shear_spring_n, w.dt_s);
            point.normal_force_n = f.normal_n;
            point.shear_spring_n = f.shear_spring_n;
            point.shear_force_n = f.shear_n;
            point.sliding = f.sliding;
            const Vec2 on_b = f.normal_n * n + f.shear_n * t;
            b.force_n[ib] += on_b;
            b.torque_n_m[ib] += cross(rb, on_b);
            b.force_n[ia] -= on_b;
            b.torque_n_m[ia] -= cross(ra, on_b);
            lost.normal_dashpot_j += f.normal_dashpot_work_j;
            lost.shear_dashpot_j += f.shear_dashpot_work_j;
            lost.friction_j += f.friction_work_j;
        }
    }
    return lost;
}

double contact_elastic_energy(const World& w) {
    double energy = 0.0;
    for (const PairContact& pair : w.contacts) {
        if (pair.count == 0) continue;
        const ContactParameters params =
            softened(w.contact.at(w.bodies.material[pair.a], w.bodies.material[pair.b]), pair.stiffness_scale);
        for (std::uint32_t k = 0; k < pair.count; ++k)
            energy += contact_elastic_energy(params, pair.points[k].overlap_m, pair.points[k].shear_spring_n);
    }
    return energy;
}

}  // namespace blockdem
