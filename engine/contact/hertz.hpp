#pragma once
// Hertz's law for the normal contact force in the overlap delta (DESIGN §3):
//   F = 4/3 E* sqrt(R*) delta^{3/2},  U = 8/15 E* sqrt(R*) delta^{5/2},  dF/ddelta = 3/2 F / delta,
// with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and an effective radius R* per pair type.
#include <cmath>
#include <limits>

namespace wirepack {

// Effective modulus E* [Pa]; pass E2 = infinity for a rigid second body.
inline double effective_modulus(double E1, double nu1, double E2, double nu2) {
  const double inv = (1.0 - nu1 * nu1) / E1 + (std::isinf(E2) ? 0.0 : (1.0 - nu2 * nu2) / E2);
  return 1.0 / inv;
}

struct Hertz {
  double k = 0;  // 4/3 E* sqrt(R*) [N / m^{3/2}]

  static Hertz from(double E_star, double R_star) {
    return Hertz{4.0 / 3.0 * E_star * std::sqrt(R_star)};
  }
  double force(double delta) const { return k * delta * std::sqrt(delta); }                 // [N]
  double energy(double delta) const { return 0.4 * k * delta * delta * std::sqrt(delta); }  // [J]
  double stiffness(double delta) const { return 1.5 * k * std::sqrt(delta); }               // [N/m]
};

// Normal force including a dashpot on the approach speed (positive when closing, m/s), with
// damping coefficient 2 zeta sqrt(k_c m_eff) at the current contact stiffness k_c. The total is
// never attractive. Returns the force magnitude [N].
inline double damped_normal_force(const Hertz& h, double delta, double approach_speed, double zeta,
                                  double m_eff) {
  const double f = h.force(delta);
  if (zeta <= 0.0 || approach_speed == 0.0) return f;
  const double eta = 2.0 * zeta * std::sqrt(h.stiffness(delta) * m_eff);
  const double total = f + eta * approach_speed;
  return total > 0.0 ? total : 0.0;
}

}  // namespace wirepack
