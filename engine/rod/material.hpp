#pragma once
// Section and material constants of the wire (paper Eq. (1)).
#include "core/section.hpp"
#include "engine/params.hpp"

namespace wirepack {

struct RodMaterial {
  double E = 0;  // Young's modulus [Pa]
  double G = 0;  // shear modulus E / (2 (1 + nu)) [Pa]
  double A = 0;  // cross-section pi r^2 [m^2]
  double I = 0;  // second moment pi r^4 / 4 [m^4]
  double J = 0;  // polar moment 2 I [m^4]
  double r = 0;  // radius [m]

  static RodMaterial from(const WireParams& w) {
    RodMaterial m;
    m.r = w.radius;
    m.E = w.youngs_modulus;
    m.G = w.youngs_modulus / (2.0 * (1.0 + w.poisson_ratio));
    m.A = section_area(w.radius);
    m.I = section_second_moment(w.radius);
    m.J = 2.0 * m.I;
    return m;
  }
  double EA() const { return E * A; }
  double EI() const { return E * I; }
  double GJ() const { return G * J; }
};

}  // namespace wirepack
