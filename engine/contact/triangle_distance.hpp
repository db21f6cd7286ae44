#pragma once
// Closest points between a point or a segment and a triangle (wire-shell contact).
#include <array>

#include "engine/types.hpp"

namespace wirepack {

struct TriangleClosest {
  std::array<double, 3> w{1, 0, 0};  // barycentric weights of the point on the triangle
  double s = 0;                      // parameter on the segment (0 for a point query)
  double dist2 = 0;                  // squared distance [m^2]
};

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 5.1.5,
// by Voronoi regions of the vertices, edges and face). Degenerate triangles are handled as
// segments.
TriangleClosest point_triangle_closest(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Closest points of segment [p0, p1] and triangle (a, b, c): the segment crossing the
// triangle (distance 0), or the best of the two end points against the triangle and the
// segment against the three edges.
TriangleClosest segment_triangle_closest(const Vec3& p0, const Vec3& p1, const Vec3& a,
                                         const Vec3& b, const Vec3& c);

}  // namespace wirepack
