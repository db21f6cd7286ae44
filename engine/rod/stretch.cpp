#include "engine/rod/stretch.hpp"

#include <algorithm>
#include <limits>

namespace wirepack {

double StretchTerm::accumulate(const State& s, Forces& out) {
  double U = 0.0;
  const int ne = s.num_edges();
  for (int j = 0; j < ne; ++j) {
    const Vec3 e = s.x[j + 1] - s.x[j];
    const double len = out.edge_len[j];
    const double lbar = s.rest_length[j];
    const double strain = len / lbar - 1.0;
    U += 0.5 * EA_ * strain * strain * lbar;
    // dU/dx_{j+1} = EA eps t_j ; dU/dx_j = -EA eps t_j
    const Vec3 g = (EA_ * strain / len) * e;
    out.f[j] += g;
    out.f[j + 1] -= g;
  }
  min_rest_ = out.min_rest_length;
  return U;
}

double StretchTerm::energy(const State& s) {
  double U = 0.0;
  for (int j = 0; j < s.num_edges(); ++j) {
    const double strain = (s.x[j + 1] - s.x[j]).norm() / s.rest_length[j] - 1.0;
    U += 0.5 * EA_ * strain * strain * s.rest_length[j];
  }
  return U;
}

double StretchTerm::omega_max_sq(const RodInertia& inertia) const {
  // Highest axial mode of a chain of springs EA/l between masses m: omega^2 = 4 EA / (l m).
  if (!(min_rest_ > 0) || !std::isfinite(min_rest_)) return 0.0;
  return 4.0 * EA_ / (min_rest_ * inertia.node_mass);
}

}  // namespace wirepack
