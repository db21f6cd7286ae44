#pragma once
// Verlet-list pairs that cannot touch yet (wire self-contact, wire-shell contact): a pair at
// distance d at the list build, with contact distance D, cannot touch while every point of it
// has moved less than (d - D) / 2 since the build (its distance shrinks by at most the moves of
// its two sides). Comparing squared moves against a quarter of the squared slack avoids roots.
#include <algorithm>
#include <cmath>

namespace wirepack {

// (d - D - margin)^2 / 4 for d = sqrt(dist2) [m^2], 0 for a pair within reach already; the
// margin, 1e-9 of `length_scale` [m], keeps the rounding of distances from skipping a pair at
// the limit, so a skipped pair is one whose exact evaluation would find no contact.
inline double quarter_slack2(double dist2, double contact, double length_scale) {
  const double slack = std::max(std::sqrt(dist2) - contact - 1e-9 * length_scale, 0.0);
  return 0.25 * slack * slack;
}

}  // namespace wirepack
