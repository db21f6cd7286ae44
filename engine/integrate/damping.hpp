#pragma once
// Subcritical viscous damping that keeps the injected wire close to static equilibrium
// without resisting the injection itself (paper, section "Model"; docs/design.md §3.4):
//  - transverse: F_i = -gamma m (v_i - (v_i . tau_i) tau_i) with tau_i the node tangent, so a
//    wire sliding along its own axis (as it does when fed into a coil) feels no drag, while
//    sideways motion is damped at gamma = 2 zeta omega_0, omega_0 = sqrt(E I / (rho A R^4)) the
//    bending frequency scale of a wire curved on the cavity radius;
//  - absolute (DampingForm::Absolute, instead of the transverse part): F_i = -gamma m v_i and
//    a spin drag -gamma I_theta omega_e on every edge: mass-proportional damping of the whole
//    motion. The wire sliding into the cavity at the feed speed v is dragged by gamma m v per
//    node, a compressive load gamma rho A v L at the hole that grows with the injected length L;
//  - axial: a dashpot on the stretch rate of every edge, eta = zeta sqrt(2 k m), k = E A / l,
//    i.e. ratio zeta for the highest axial mode;
//  - twist: a dashpot on the relative spin of neighbouring edges, same rule with G J / l, I_theta;
//  - bending rate (selective mass only): a dashpot on the transverse part of the second
//    difference of the velocities, dissipation 1/2 eta sum_i |P_i (v_{i-1} - 2 v_i + v_{i+1})|^2
//    with P_i = I - tau_i tau_i^T, i.e. on the rate of change of the discrete curvature. Zero
//    for a rigid translation and for the wire sliding along a fixed circle (the second difference
//    is then tangential), so the sliding coil feels no drag; a mode with Laplacian eigenvalue
//    lambda is damped at the rate eta lambda^2 / (m_p + beta lambda): the element-scale
//    zig-zag (lambda = 4) at a set ratio (scene.hpp, kZigZagDamping), the slow, long modes at
//    next to nothing. With the Laplacian mass (integrate/wire_mass.hpp) the transverse rate
//    above acts on the slow modes' mass only; this term damps the element-scale modes that
//    carry the scaled mass, which sliding contacts keep exciting.
#include "engine/term.hpp"

namespace wirepack {

struct DampingParams {
  double c_transverse = 0;           // gamma m per node [N s/m]
  bool absolute = false;             // drag on the whole velocity (DampingForm::Absolute)
  double c_spin = 0;                 // gamma I_theta per edge, absolute form only [N m s]
  double eta_axial = 0;              // [N s/m]
  double eta_twist = 0;              // [N m s]
  double eta_bending = 0;            // eta of the bending-rate dashpot [N s/m]
  bool twist_free_at_guide = false;  // swivel at the hole: no twist dashpot at the joint node
};

class RodDamping {
 public:
  explicit RodDamping(const DampingParams& p) : p_(p) {}
  // Adds the damping forces of the dynamic nodes/edges into `out` (uses s.v and s.omega).
  void add_forces(const State& s, Forces& out) const;
  const DampingParams& params() const { return p_; }

 private:
  DampingParams p_;
  mutable Vec3List tau_;  // work space: node tangents of the last add_forces (n)
};

}  // namespace wirepack
