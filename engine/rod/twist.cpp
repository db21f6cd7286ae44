#include "engine/rod/twist.hpp"

#include <algorithm>
#include <limits>

#include "engine/rod/frames.hpp"

namespace wirepack {

double TwistTerm::accumulate(const RodState& s, RodForces& out) {
  const int n = s.num_nodes();
  double min_rest = std::numeric_limits<double>::infinity();
  for (int j = 0; j + 1 < n; ++j) min_rest = std::min(min_rest, s.rest_length[j]);
  min_rest_ = min_rest;
  double U = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    const double lbar = 0.5 * (s.rest_length[i - 1] + s.rest_length[i]);
    const double m = s.theta[i] - s.theta[i - 1] + s.ref_twist[i];
    U += 0.5 * GJ_ * m * m / lbar;
    const double dU_dm = GJ_ * m / lbar;
    out.torque[i] -= dU_dm;
    out.torque[i - 1] += dU_dm;
    const Vec3 e0 = s.x[i] - s.x[i - 1];
    const Vec3 e1 = s.x[i + 1] - s.x[i];
    const double len0 = e0.norm();
    const double len1 = e1.norm();
    const Vec3 t0 = e0 / len0;
    const Vec3 t1 = e1 / len1;
    const Vec3 kb = (2.0 / std::max(1.0 + t0.dot(t1), 1e-9)) * t0.cross(t1);
    const Vec3 g0 = (dU_dm / (2.0 * len0)) * kb;  // dU/de^{i-1}
    const Vec3 g1 = (dU_dm / (2.0 * len1)) * kb;  // dU/de^i
    out.f[i - 1] += g0;
    out.f[i] += g1 - g0;
    out.f[i + 1] -= g1;
  }
  return U;
}

double TwistTerm::energy(const RodState& s) {
  RodState c = s;
  update_reference_frames(c);
  double U = 0.0;
  for (int i = 1; i + 1 < c.num_nodes(); ++i) {
    const double lbar = 0.5 * (c.rest_length[i - 1] + c.rest_length[i]);
    const double m = c.theta[i] - c.theta[i - 1] + c.ref_twist[i];
    U += 0.5 * GJ_ * m * m / lbar;
  }
  return U;
}

double TwistTerm::omega_max_sq(const RodInertia& inertia) const {
  // Torsional chain: springs G J / l between edge inertias I: omega^2 = 4 G J / (l I).
  if (!(min_rest_ > 0) || !std::isfinite(min_rest_) || inertia.edge_twist_inertia <= 0) return 0;
  return 4.0 * GJ_ / (min_rest_ * inertia.edge_twist_inertia);
}

}  // namespace wirepack
