#pragma once
// Reference frames of the discrete rod (Bergou et al. 2010): each edge carries a unit reference
// director ref1 normal to its tangent, carried along in time by parallel transport; the material
// frame is ref1 rotated by theta about the tangent. The reference twist at node i is the angle
// from the space-parallel transport of ref1_{i-1} onto edge i to ref1_i, about t_i.
#include <cmath>

#include "engine/state.hpp"

namespace wirepack {

// Parallel transport of u from unit tangent t0 to unit tangent t1 (rotation about t0 x t1).
// Inline: called twice per edge and step.
inline Vec3 parallel_transport(const Vec3& u, const Vec3& t0, const Vec3& b, double c);
inline Vec3 parallel_transport(const Vec3& u, const Vec3& t0, const Vec3& t1) {
  return parallel_transport(u, t0, t0.cross(t1), t0.dot(t1));
}

// The same with b = t0 x t1 and c = t0 . t1 given (Forces::node_cross, node_cos).
inline Vec3 parallel_transport(const Vec3& u, const Vec3& t0, const Vec3& b, double c) {
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

// Signed angle from a to b about the unit axis n, in (-pi, pi].
inline double signed_angle(const Vec3& a, const Vec3& b, const Vec3& n) {
  return std::atan2(a.cross(b).dot(n), a.dot(b));
}

// Transports every ref1 from its stored ref_tangent to the current edge tangent, stores the new
// tangent, and recomputes ref_twist (unwrapped against its previous value so that it is
// continuous in time). No-op when the state has no twist DOFs.
void update_reference_frames(State& s);
// The same with the current unit edge tangents of `work` (work.reset(s) computed them); uses
// work.scratch.
void update_reference_frames(State& s, Forces& work);

// Initialises ref1 / ref_tangent / ref_twist for edges [first, n-1) that have none yet
// (new edges added by the feeder), with a director normal to the tangent.
void init_reference_frames(State& s, int first_edge);

}  // namespace wirepack
