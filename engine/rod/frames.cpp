#include "engine/rod/frames.hpp"

#include <cmath>

namespace wirepack {

Vec3 parallel_transport(const Vec3& u, const Vec3& t0, const Vec3& t1) {
  const Vec3 b = t0.cross(t1);
  const double c = t0.dot(t1);
  if (b.squaredNorm() < 1e-30) {
    if (c > 0) return u;
    // Antiparallel: any half-turn about an axis normal to t0 works; pick one normal to u too.
    Vec3 axis = t0.cross(u);
    if (axis.squaredNorm() < 1e-30) axis = t0.unitOrthogonal();
    axis.normalize();
    return 2.0 * axis.dot(u) * axis - u;
  }
  // Rodrigues with unnormalised axis b = sin(phi) k: R u = c u + b x u + (b.u) b / (1 + c).
  return c * u + b.cross(u) + (b.dot(u) / (1.0 + c)) * b;
}

double signed_angle(const Vec3& a, const Vec3& b, const Vec3& n) {
  return std::atan2(a.cross(b).dot(n), a.dot(b));
}

void update_reference_frames(RodState& s) {
  if (!s.has_twist()) return;
  RodForces scratch;
  scratch.reset(s);
  update_reference_frames(s, scratch.edge_t);
}

void update_reference_frames(RodState& s, const Vec3List& edge_t) {
  if (!s.has_twist()) return;
  const int ne = s.num_edges();
  for (int j = 0; j < ne; ++j) {
    const Vec3& t = edge_t[j];
    Vec3 d = parallel_transport(s.ref1[j], s.ref_tangent[j], t);
    d -= d.dot(t) * t;  // remove round-off drift out of the normal plane
    s.ref1[j] = d.normalized();
    s.ref_tangent[j] = t;
  }
  for (int i = 1; i < ne; ++i) {
    const Vec3& t0 = s.ref_tangent[i - 1];
    const Vec3& t1 = s.ref_tangent[i];
    const Vec3 p = parallel_transport(s.ref1[i - 1], t0, t1);
    const double angle = signed_angle(p, s.ref1[i], t1);
    // Unwrap: the new value is the old one plus the wrapped change.
    double delta = angle - s.ref_twist[i];
    delta -= 2.0 * M_PI * std::round(delta / (2.0 * M_PI));
    s.ref_twist[i] += delta;
  }
}

void init_reference_frames(RodState& s, int first_edge) {
  if (!s.has_twist()) return;
  const int ne = s.num_edges();
  s.ref1.resize(ne);
  s.ref_tangent.resize(ne);
  s.ref_twist.resize(s.x.size(), 0.0);
  for (int j = first_edge; j < ne; ++j) {
    const Vec3 t = (s.x[j + 1] - s.x[j]).normalized();
    Vec3 d;
    if (j > 0) {
      // Continue the neighbour's frame so the new reference twist is zero.
      d = parallel_transport(s.ref1[j - 1], s.ref_tangent[j - 1], t);
    } else {
      d = t.unitOrthogonal();
    }
    d -= d.dot(t) * t;
    s.ref1[j] = d.normalized();
    s.ref_tangent[j] = t;
    if (j > 0) {
      s.ref_twist[j] =
          signed_angle(parallel_transport(s.ref1[j - 1], s.ref_tangent[j - 1], t), s.ref1[j], t);
    }
  }
}

}  // namespace wirepack
