#include "engine/rod/twist.hpp"

#include <algorithm>
#include <limits>

#include "engine/rod/frames.hpp"

namespace wirepack {

double TwistTerm::accumulate(const State& s, Forces& out) {
  const int end = twist_end_node(s, free_at_guide_);
  min_rest_ = out.min_rest_length;
  double U = 0.0;
  for (int i = 1; i < end; ++i) {
    const double lbar = 0.5 * (s.rest_length[i - 1] + s.rest_length[i]);
    const double m = s.theta[i] - s.theta[i - 1] + s.ref_twist[i];
    U += 0.5 * GJ_ * m * m / lbar;
    const double dU_dm = GJ_ * m / lbar;
    out.torque[i] -= dU_dm;
    out.torque[i - 1] += dU_dm;
    const double len0 = out.edge_len[i - 1];
    const double len1 = out.edge_len[i];
    const Vec3 kb = (2.0 / std::max(1.0 + out.node_cos[i], 1e-9)) * out.node_cross[i];
    const Vec3 g0 = (dU_dm / (2.0 * len0)) * kb;  // dU/de^{i-1}
    const Vec3 g1 = (dU_dm / (2.0 * len1)) * kb;  // dU/de^i
    out.f[i - 1] += g0;
    out.f[i] += g1 - g0;
    out.f[i + 1] -= g1;
  }
  return U;
}

double TwistTerm::energy(const State& s) {
  State c = s;
  update_reference_frames(c);
  double U = 0.0;
  const int end = twist_end_node(c, free_at_guide_);
  for (int i = 1; i < end; ++i) {
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
