#pragma once
// Hertz's law for the normal contact force in the overlap delta (docs/design.md §2.6):
//   F = 4/3 E* sqrt(R*) delta^{3/2},  U = 8/15 E* sqrt(R*) delta^{5/2},  dF/ddelta = 3/2 F / delta,
// with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and an effective radius R* per pair type.
#include <algorithm>
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
  // Optional barrier (D = 0: none): beyond the onset overlap d0 a term
  //   U_b = kappa (delta - d0)^2 / (D - delta),  kappa = 1.5 k sqrt(d0) D,
  // is added (C1 at d0, infinite at D, the overlap at which the bodies' centres would pass
  // through each other). A numerical safeguard for soft contacts that Hertz alone cannot stop
  // (a wire pushed into a shell with E_s << E_w); it never acts below d0.
  double D = 0, d0 = 0;

  static Hertz from(double E_star, double R_star) {
    return Hertz{4.0 / 3.0 * E_star * std::sqrt(R_star)};
  }
  // Hertz up to d0 = onset * limit, then the barrier towards D = limit [m].
  Hertz& with_barrier(double limit, double onset) {
    D = limit;
    d0 = onset * limit;
    return *this;
  }
  double kappa() const { return 1.5 * k * std::sqrt(d0) * D; }
  bool in_barrier(double delta) const { return D > 0 && delta > d0; }
  double gap(double delta) const { return std::max(D - delta, 1e-12 * D); }
  double force(double delta) const {  // [N]
    double f = k * delta * std::sqrt(delta);
    if (in_barrier(delta)) {
      const double e = delta - d0, g = gap(delta);
      f += kappa() * (2.0 * e * g + e * e) / (g * g);
    }
    return f;
  }
  double energy(double delta) const {  // [J]
    double U = 0.4 * k * delta * delta * std::sqrt(delta);
    if (in_barrier(delta)) U += kappa() * (delta - d0) * (delta - d0) / gap(delta);
    return U;
  }
  double stiffness(double delta) const {  // [N/m]
    double s = 1.5 * k * std::sqrt(delta);
    if (in_barrier(delta)) {
      const double e = delta - d0, g = gap(delta);
      s += kappa() * 2.0 * (g + e) * (g + e) / (g * g * g);
    }
    return s;
  }
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
