#include "engine/contact/segment_distance.hpp"

#include <algorithm>
#include <limits>

namespace wirepack {

// Notation: P(s) = p0 + s d1, Q(t) = q0 + t d2, r = p0 - q0, and the squared distance
//   F(s, t) = |r + s d1 - t d2|^2 = a s^2 - 2 b s t + e t^2 + 2 c s - 2 f t + |r|^2
// with a = d1.d1, e = d2.d2, b = d1.d2, c = d1.r, f = d2.r; F is convex on the unit square.
//
// For fixed s the best t on the whole line is t*(s) = (b s + f) / e (well conditioned: only a
// division by e). The "valley" t = t*(s) holds the line-line minimisers for every s, and along
// it F rises only with curvature D / e, D = a e - b^2 = |d1 x d2|^2. So, after a fast path for
// clearly non-parallel directions (step 0):
//   1. valley part inside the square: s in [lo, hi] where 0 <= t*(s) <= 1;
//   2. parallel (D ~ 0 to rounding): every valley point in the square is a minimiser; take
//      the midpoint of [lo, hi] (the middle of the overlap): symmetric, continuous forces;
//   3. otherwise the line-line minimiser s_u = (b f - c e) / D; if it lies in [lo, hi] it is the
//      answer. For nearly parallel segments s_u is inaccurate, but an error ds costs only
//      (D / e) ds^2 in F because the point stays on the valley;
//   4. else the minimum is on the square's boundary: the best of the four edge minimisers
//      (each a clamped point-segment projection, always well conditioned).
// No step divides by a quantity that can be ~0 except s_u, which is guarded by steps 0 and 2.

namespace {

double clamp01(double x) {
  return std::clamp(x, 0.0, 1.0);
}

// Squared distance between P(s) and Q(t), formed from r so that large absolute coordinates do
// not cost precision [m^2].
double dist2_at(const Vec3& r, const Vec3& d1, const Vec3& d2, double s, double t) {
  return (r + s * d1 - t * d2).squaredNorm();
}

}  // namespace

SegmentClosest segment_segment_closest(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                       const Vec3& q1) {
  const Vec3 d1 = p1 - p0;
  const Vec3 d2 = q1 - q0;
  const Vec3 r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();

  // Degenerate segments: point-point, point-segment (clamped projection).
  if (a <= 0.0 && e <= 0.0) return {0.0, 0.0, r.squaredNorm()};
  if (a <= 0.0) {
    const double t = clamp01(d2.dot(r) / e);
    return {0.0, t, dist2_at(r, d1, d2, 0.0, t)};
  }
  if (e <= 0.0) {
    const double s = clamp01(-d1.dot(r) / a);
    return {s, 0.0, dist2_at(r, d1, d2, s, 0.0)};
  }

  const double b = d1.dot(d2);
  const double c = d1.dot(r);
  const double f = d2.dot(r);

  // Step 0, fast path for directions more than 0.01 rad apart (sin^2 >= 1e-4), where s_u has
  // an error of at most ~1e4 eps |r| / |d1|: clamp s_u to [0, 1] and take the best t for it; if
  // that t leaves [0, 1], the minimum lies on that edge (t = 0 or 1): clamp t and take the best
  // s for it (the classic clamping, Ericson, Real-Time Collision Detection, 2005). Exact for an
  // exact s_u; an error ds in s_u costs at most a ds^2 in F.
  // D and the numerator b f - c e = (d1 x d2).(d2 x r) come from cross products: relative error
  // ~eps / sin(angle), where a e - b^2 would give eps / sin(angle)^2.
  const Vec3 n = d1.cross(d2);
  const double D = n.squaredNorm();
  if (D >= 1e-4 * a * e) {
    double s = clamp01(n.dot(d2.cross(r)) / D);
    double t = (b * s + f) / e;
    if (t < 0.0) {
      t = 0.0;
      s = clamp01(-c / a);
    } else if (t > 1.0) {
      t = 1.0;
      s = clamp01((b - c) / a);
    }
    return {s, t, dist2_at(r, d1, d2, s, t)};
  }

  // Step 1: s-interval [lo, hi] of the valley inside the square, from 0 <= b s + f <= e.
  double lo = 0.0;
  double hi = 1.0;
  if (b != 0.0) {
    const double x0 = -f / b;       // t*(x0) = 0
    const double x1 = (e - f) / b;  // t*(x1) = 1
    lo = std::max(lo, std::min(x0, x1));
    hi = std::min(hi, std::max(x0, x1));
  } else if (f < 0.0 || f > e) {
    hi = -1.0;  // perpendicular directions and t*(s) outside [0, 1]: valley misses the square
  }

  if (lo <= hi) {
    // Step 2: parallel to rounding level. The midpoint is off the minimiser by at most the
    // overlap length along the valley, which costs D / max(a, e) in F (the drift of one
    // segment across the other over the overlap, squared). Accept it while that drift is below
    // 2 eps * scale, the rounding error that forming r + s d1 - t d2 makes anyway.
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    const double scale2 = r.squaredNorm() + a + e;  // [m^2]
    if (D <= 4.0 * kEps * kEps * scale2 * std::max(a, e)) {
      const double s = 0.5 * (lo + hi);
      const double t = clamp01((b * s + f) / e);
      return {s, t, dist2_at(r, d1, d2, s, t)};
    }
    // Step 3: line-line minimiser inside the valley interval.
    const double s_u = n.dot(d2.cross(r)) / D;
    if (s_u >= lo && s_u <= hi) {
      const double t = clamp01((b * s_u + f) / e);
      return {s_u, t, dist2_at(r, d1, d2, s_u, t)};
    }
  }

  // Step 4: minimum on the boundary; the best of the four edge minimisers. Ties keep the first.
  const double inv_a = 1.0 / a;  // [1/m^2]
  const double inv_e = 1.0 / e;  // [1/m^2]
  const double s_edge[4] = {0.0, 1.0, clamp01(-c * inv_a), clamp01((b - c) * inv_a)};
  const double t_edge[4] = {clamp01(f * inv_e), clamp01((b + f) * inv_e), 0.0, 1.0};
  SegmentClosest best{s_edge[0], t_edge[0], dist2_at(r, d1, d2, s_edge[0], t_edge[0])};
  for (int k = 1; k < 4; ++k) {
    const double d2k = dist2_at(r, d1, d2, s_edge[k], t_edge[k]);
    if (d2k < best.dist2) best = {s_edge[k], t_edge[k], d2k};
  }
  return best;
}

}  // namespace wirepack
