#include "engine/rod/frames.hpp"

#include <algorithm>
#include <cmath>

namespace wirepack {

void update_reference_frames(State& s) {
  if (!s.has_twist()) return;
  Forces scratch;
  scratch.reset(s);
  update_reference_frames(s, scratch);
}

void update_reference_frames(State& s, Forces& work) {
  if (!s.has_twist()) return;
  const Vec3List& edge_t = work.edge_t;
  const int ne = s.num_edges();
  // Reference twist in two passes: the atan2 arguments of every node (independent short
  // iterations), then the angles; the same arithmetic as one loop, but the processor overlaps
  // the iterations instead of waiting on one atan2 at a time. Each loop in parallel (threads
  // over edges or nodes, each writing its own entries).
  std::vector<double>& yx = work.scratch;
  yx.resize(2 * static_cast<size_t>(std::max(ne, 1)));
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (int j = 0; j < ne; ++j) {
      const Vec3& t = edge_t[j];
      Vec3 d = parallel_transport(s.ref1[j], s.ref_tangent[j], t);
      d -= d.dot(t) * t;  // remove round-off drift out of the normal plane
      s.ref1[j] = d.normalized();
      s.ref_tangent[j] = t;
    }
#pragma omp for schedule(static)
    for (int i = 1; i < ne; ++i) {
      const Vec3& t0 = s.ref_tangent[i - 1];
      const Vec3& t1 = s.ref_tangent[i];
      const Vec3 p = parallel_transport(s.ref1[i - 1], t0, work.node_cross[i], work.node_cos[i]);
      yx[2 * i] = p.cross(s.ref1[i]).dot(t1);
      yx[2 * i + 1] = p.dot(s.ref1[i]);
    }
#pragma omp for schedule(static)
    for (int i = 1; i < ne; ++i) {
      const double angle = std::atan2(yx[2 * i], yx[2 * i + 1]);  // signed_angle(p, ref1_i, t_i)
      // Unwrap: the new value is the old one plus the wrapped change.
      double delta = angle - s.ref_twist[i];
      // round() is 0 for |delta| < pi (nearly always: delta is the change over one step).
      if (!(std::abs(delta) < 3.0)) delta -= 2.0 * M_PI * std::round(delta / (2.0 * M_PI));
      s.ref_twist[i] += delta;
    }
  }
}

void init_reference_frames(State& s, int first_edge) {
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
