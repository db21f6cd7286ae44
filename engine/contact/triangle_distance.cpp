#include "engine/contact/triangle_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/contact/segment_distance.hpp"

namespace wirepack {

TriangleClosest point_triangle_closest(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  TriangleClosest r;
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  auto finish = [&](double wa, double wb, double wc) {
    r.w = {wa, wb, wc};
    r.dist2 = (p - (wa * a + wb * b + wc * c)).squaredNorm();
    return r;
  };
  // Degenerate (zero-area) triangle: the closest of its three edges.
  if (ab.cross(ac).squaredNorm() <= 1e-30 * ab.squaredNorm() * ac.squaredNorm()) {
    TriangleClosest best;
    best.dist2 = std::numeric_limits<double>::infinity();
    const Vec3* v[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      const Vec3 &q0 = *v[k], &q1 = *v[(k + 1) % 3];
      const Vec3 d = q1 - q0;
      const double dd = d.squaredNorm();
      const double t = dd > 0 ? std::clamp((p - q0).dot(d) / dd, 0.0, 1.0) : 0.0;
      const double d2 = (p - (q0 + t * d)).squaredNorm();
      if (d2 < best.dist2) {
        best.dist2 = d2;
        best.w = {0, 0, 0};
        best.w[k] += 1.0 - t;
        best.w[(k + 1) % 3] += t;
      }
    }
    return best;
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return finish(1, 0, 0);  // vertex a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return finish(0, 1, 0);  // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {  // edge ab
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return finish(0, 0, 1);  // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {  // edge ac
    const double w = d2 / (d2 - d6);
    return finish(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - w, w);
  }
  const double denom = 1.0 / (va + vb + vc);  // face interior
  const double v = vb * denom, w = vc * denom;
  return finish(1 - v - w, v, w);
}

TriangleClosest segment_triangle_closest(const Vec3& p0, const Vec3& p1, const Vec3& a,
                                         const Vec3& b, const Vec3& c) {
  // Does the segment cross the triangle? Solve p0 + s d = a + v ab + w ac.
  const Vec3 d = p1 - p0, ab = b - a, ac = c - a;
  const Vec3 n = ab.cross(ac);
  const double denom = d.dot(n);
  if (std::abs(denom) > 1e-300) {
    const double s = (a - p0).dot(n) / denom;
    if (s >= 0.0 && s <= 1.0) {
      const Vec3 q = p0 + s * d - a;
      // Barycentric coordinates of q in the triangle's plane.
      const double nn = n.squaredNorm();
      const double v = q.cross(ac).dot(n) / nn;
      const double w = ab.cross(q).dot(n) / nn;
      if (v >= 0 && w >= 0 && v + w <= 1) {
        TriangleClosest r;
        r.w = {1 - v - w, v, w};
        r.s = s;
        r.dist2 = 0.0;
        return r;
      }
    }
  }
  TriangleClosest best = point_triangle_closest(p0, a, b, c);
  best.s = 0.0;
  TriangleClosest e1 = point_triangle_closest(p1, a, b, c);
  if (e1.dist2 < best.dist2) {
    best = e1;
    best.s = 1.0;
  }
  const Vec3* v[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const SegmentClosest sc = segment_segment_closest(p0, p1, *v[k], *v[(k + 1) % 3]);
    if (sc.dist2 < best.dist2) {
      best.dist2 = sc.dist2;
      best.s = sc.s;
      best.w = {0, 0, 0};
      best.w[k] = 1.0 - sc.t;
      best.w[(k + 1) % 3] = sc.t;
    }
  }
  return best;
}

}  // namespace wirepack
