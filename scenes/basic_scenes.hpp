#pragma once
// Scene builders shared by examples, tests and benchmarks: plain Models built in code.
#include "world/model.hpp"

namespace blockdem::scenes {

/// The paper's Fig. 5 contact: kn = ks = 2e4 N/m, mu = 0.3, e = 0.4 (paper meaning), h_s = 1.
ContactParameters paper_contact();

/// A driven table (top surface at y = 0) and one width x height block resting on it,
/// centred at x = 0, of the given mass (thickness 1 m).
Model block_on_table(double width_m, double height_m, double mass_kg, const ContactParameters& contact,
                     double duration_s, double dt_s);

/// The paper's sliding analysis (Fig. 5): 0.5 x 0.2 m block of 1 kg, table 3.5 cos(2 pi t) m/s^2.
Model paper_sliding(double h_s, double duration_s);

/// A column of n identical blocks (width x height each) on a fixed base, stacked touching.
Model block_stack(int n, double width_m, double height_m, double density_kg_m3, const ContactParameters& contact,
                  double duration_s);

}  // namespace blockdem::scenes
