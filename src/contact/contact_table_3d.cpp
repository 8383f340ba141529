#include "contact/contact_table_3d.hpp"

namespace blockdem {

void carry_history(const std::vector<ContactPoint3d>& previous, std::vector<ContactPoint3d>& current) {
    std::size_t j = 0;
    for (ContactPoint3d& p : current) {
        while (j < previous.size() && previous[j].key < p.key) ++j;
        if (j < previous.size() && previous[j].key == p.key) {
            p.normal_dashpot_n = previous[j].normal_dashpot_n;
            p.shear = previous[j].shear;
            const double before = previous[j].stiffness_share;
            if (p.stiffness_share != before)
                p.shear.spring_n = before > 0.0 ? (p.stiffness_share / before) * p.shear.spring_n : Vec3{};
        }
    }
}

}  // namespace blockdem
