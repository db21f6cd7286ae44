#include "engine/rod/bend.hpp"

#include <algorithm>
#include <limits>

namespace wirepack {

namespace {
// 1 + c is kept away from 0 (a complete fold-back) so the energy stays finite; such a state is
// far outside anything a step accepts.
constexpr double kMinOnePlusCos = 1e-9;
}  // namespace

double BendTerm::accumulate(const State& s, Forces& out) {
  const int n = s.num_nodes();
  double U = 0.0;
  min_rest_ = out.min_rest_length;
  if (n < 3) return 0.0;
  const Vec3List& t = out.edge_t;
  const std::vector<double>& len = out.edge_len;
  for (int i = 1; i + 1 < n; ++i) {
    const Vec3& t0 = t[i - 1];
    const Vec3& t1 = t[i];
    const double c = out.node_cos[i];  // t0 . t1
    const double opc = std::max(1.0 + c, kMinOnePlusCos);
    const double lbar = 0.5 * (s.rest_length[i - 1] + s.rest_length[i]);
    const double k = 2.0 * EI_ / lbar;  // U_i = k (1 - c) / (1 + c)
    U += k * (1.0 - c) / opc;
    const double dU_dc = -2.0 * k / (opc * opc);
    // dc/de0 = (t1 - c t0) / |e0|,  dc/de1 = (t0 - c t1) / |e1|
    const Vec3 g0 = (dU_dc / len[i - 1]) * (t1 - c * t0);
    const Vec3 g1 = (dU_dc / len[i]) * (t0 - c * t1);
    out.f[i - 1] += g0;
    out.f[i] += g1 - g0;
    out.f[i + 1] -= g1;
  }
  return U;
}

double BendTerm::energy(const State& s) {
  const int n = s.num_nodes();
  double U = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    const Vec3 t0 = (s.x[i] - s.x[i - 1]).normalized();
    const Vec3 t1 = (s.x[i + 1] - s.x[i]).normalized();
    const double c = t0.dot(t1);
    const double lbar = 0.5 * (s.rest_length[i - 1] + s.rest_length[i]);
    U += 2.0 * EI_ / lbar * (1.0 - c) / std::max(1.0 + c, kMinOnePlusCos);
  }
  return U;
}

double BendTerm::omega_max_sq(const RodInertia& inertia) const {
  // Zig-zag mode of the discrete beam: omega^2 = 16 E I / (l^3 m).
  if (!(min_rest_ > 0) || !std::isfinite(min_rest_)) return 0.0;
  return 16.0 * EI_ / (min_rest_ * min_rest_ * min_rest_ * inertia.node_mass);
}

}  // namespace wirepack
