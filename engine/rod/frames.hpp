#pragma once
// Reference frames of the discrete rod (Bergou et al. 2010): each edge carries a unit reference
// director ref1 normal to its tangent, carried along in time by parallel transport; the material
// frame is ref1 rotated by theta about the tangent. The reference twist at node i is the angle
// from the space-parallel transport of ref1_{i-1} onto edge i to ref1_i, about t_i.
#include "engine/rod/rod_state.hpp"

namespace wirepack {

// Parallel transport of u from unit tangent t0 to unit tangent t1 (rotation about t0 x t1).
Vec3 parallel_transport(const Vec3& u, const Vec3& t0, const Vec3& t1);

// Signed angle from a to b about the unit axis n, in (-pi, pi].
double signed_angle(const Vec3& a, const Vec3& b, const Vec3& n);

// Transports every ref1 from its stored ref_tangent to the current edge tangent, stores the new
// tangent, and recomputes ref_twist (unwrapped against its previous value so that it is
// continuous in time). No-op when the state has no twist DOFs.
void update_reference_frames(RodState& s);
// The same with the current unit edge tangents given (n-1; RodForces::edge_t after reset(s)).
void update_reference_frames(RodState& s, const Vec3List& edge_t);

// Initialises ref1 / ref_tangent / ref_twist for edges [first, n-1) that have none yet
// (new edges added by the feeder), with a director normal to the tangent.
void init_reference_frames(RodState& s, int first_edge);

}  // namespace wirepack
