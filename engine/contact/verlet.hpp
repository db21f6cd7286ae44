#pragma once
// The Verlet lists of the three pair contacts (wire self, wire-shell, shell self; docs/design.md
// §3.5): a list built at positions x_b holds the pairs within contact distance + skin, and stays
// valid while no point has moved more than skin / 2 since (two points close in by at most the
// sum of their moves). VerletReference keeps x_b and the squared moves; quarter_slack2 lets a
// pair of the list be skipped while it cannot touch yet.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "engine/types.hpp"

namespace wirepack {

// The positions a Verlet list was built at, and each point's squared move since (public for the
// terms' checkpoints, which store `at_build`).
struct VerletReference {
  Vec3List at_build;           // positions at the build (n) [m]
  std::vector<double> moved2;  // |x - at_build|^2 per point at the last check (n) [m^2]

  // Takes the first n points of x as the build positions; every move is 0.
  void build(const Vec3List& x, std::size_t n) {
    at_build.assign(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n));
    moved2.assign(n, 0.0);
  }
  // Whether one of the first n points of x moved more than skin / 2 since the build [m]; the
  // squared moves are recorded up to that point (all n when none did). n <= at_build.size().
  bool moved_beyond(const Vec3List& x, std::size_t n, double skin) {
    const double limit2 = 0.25 * skin * skin;
    moved2.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      moved2[i] = (x[i] - at_build[i]).squaredNorm();
      if (moved2[i] > limit2) return true;
    }
    return false;
  }
  // The largest squared move of x (at_build.size() points) since the build [m^2], without
  // recording the moves: no early exit, a branch-free loop over the coordinates vectorises.
  double max_moved2(const Vec3List& x) const {
    const std::size_t n = at_build.size();
    const double* a = n ? x.front().data() : nullptr;
    const double* b = n ? at_build.front().data() : nullptr;
    double worst = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double dx = a[3 * k] - b[3 * k], dy = a[3 * k + 1] - b[3 * k + 1],
                   dz = a[3 * k + 2] - b[3 * k + 2];
      worst = std::max(worst, dx * dx + dy * dy + dz * dz);
    }
    return worst;
  }
};

// Pairs that cannot touch yet (wire self-contact, wire-shell contact): a pair at distance d at
// the list build, with contact distance D, cannot touch while every point of it has moved less
// than (d - D) / 2 since the build (its distance shrinks by at most the moves of its two
// sides). Comparing squared moves against a quarter of the squared slack avoids roots.
// (d - D - margin)^2 / 4 for d = sqrt(dist2) [m^2], 0 for a pair within reach already; the
// margin, 1e-9 of `length_scale` [m], keeps the rounding of distances from skipping a pair at
// the limit, so a skipped pair is one whose exact evaluation would find no contact.
inline double quarter_slack2(double dist2, double contact, double length_scale) {
  const double slack = std::max(std::sqrt(dist2) - contact - 1e-9 * length_scale, 0.0);
  return 0.25 * slack * slack;
}

}  // namespace wirepack
