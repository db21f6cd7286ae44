#pragma once
// Closest points between two segments (capsule axes). Robust for parallel, nearly parallel,
// crossing, skew and degenerate (zero-length) segments.
#include "engine/types.hpp"

namespace wirepack {

struct SegmentClosest {
  double s = 0;      // parameter on [p0, p1]: point p0 + s (p1 - p0), s in [0, 1]
  double t = 0;      // parameter on [q0, q1]: point q0 + t (q1 - q0), t in [0, 1]
  double dist2 = 0;  // squared distance between the two closest points [m^2]
};

SegmentClosest segment_segment_closest(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                       const Vec3& q1);

}  // namespace wirepack
