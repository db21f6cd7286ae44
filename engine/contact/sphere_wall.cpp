#include "engine/contact/sphere_wall.hpp"

#include <algorithm>

namespace wirepack {

SphereWallTerm::SphereWallTerm(const SphereWallParams& p)
    : p_(p),
      wall_(Hertz::from(p.E_star, p.r * p.R / (p.R - p.r))),
      rim_(Hertz::from(p.E_star, p.r)),
      z_rim_(-std::sqrt(p.R * p.R - p.hole_radius * p.hole_radius)) {}

bool SphereWallTerm::overlap(const Vec3& x, double& delta, Vec3& normal, bool& rim) const {
  const double rho_perp2 = x[0] * x[0] + x[1] * x[1];
  rim = x[2] < 0.0 && rho_perp2 < p_.hole_radius * p_.hole_radius && x[2] < z_rim_ + 2.0 * p_.r;
  if (rim) {
    // Nearest point of the rim circle; the node pushes away from it.
    const double rho_perp = std::sqrt(rho_perp2);
    Vec3 radial = rho_perp > 0 ? Vec3(x[0] / rho_perp, x[1] / rho_perp, 0.0) : Vec3::UnitX();
    const Vec3 rim_point = p_.hole_radius * radial + Vec3(0, 0, z_rim_);
    const Vec3 d = rim_point - x;  // from the node towards the rim
    const double dist = d.norm();
    delta = p_.r - dist;
    if (delta <= 0.0 || dist == 0.0) return false;
    normal = d / dist;
    return true;
  }
  const double dist = x.norm();
  delta = dist + p_.r - p_.R;
  if (delta <= 0.0 || dist == 0.0) return false;
  normal = x / dist;
  return true;
}

template <bool kForces>
double SphereWallTerm::visit(const RodState& s, RodForces* out) {
  double U = 0.0;
  double kmax = 0.0;
  int count = 0;
  for (int i = 0; i < s.n_free; ++i) {
    double delta;
    Vec3 n;
    bool rim;
    if (!overlap(s.x[i], delta, n, rim)) continue;
    const Hertz& h = rim ? rim_ : wall_;
    U += h.energy(delta);
    ++count;
    if constexpr (kForces) {
      const double approach = s.v[i].dot(n);  // speed towards the wall [m/s]
      const double f = damped_normal_force(h, delta, approach, p_.damping_ratio, p_.node_mass);
      out->f[i] -= f * n;
      kmax = std::max(kmax, h.stiffness(delta));
    }
  }
  if constexpr (kForces) {
    max_stiffness_ = kmax;
    contacts_ = count;
  }
  return U;
}

double SphereWallTerm::accumulate(const RodState& s, RodForces& out) {
  return visit<true>(s, &out);
}

double SphereWallTerm::energy(const RodState& s) {
  return visit<false>(s, nullptr);
}

double SphereWallTerm::omega_max_sq(const RodInertia& inertia) const {
  return max_stiffness_ / inertia.node_mass;
}

}  // namespace wirepack
