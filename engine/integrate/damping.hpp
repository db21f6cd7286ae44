#pragma once
// Subcritical viscous damping that keeps the injected wire close to static equilibrium
// without resisting the injection itself (paper, section "Model"; DESIGN §3):
//  - transverse: F_i = -gamma m (v_i - (v_i . tau_i) tau_i) with tau_i the node tangent, so a
//    wire sliding along its own axis (as it does when fed into a coil) feels no drag, while
//    sideways motion is damped at gamma = 2 zeta omega_0, omega_0 = sqrt(E I / (rho A R^4)) the
//    bending frequency scale of a wire curved on the cavity radius;
//  - axial: a dashpot on the stretch rate of every edge, eta = zeta sqrt(2 k m), k = E A / l,
//    i.e. ratio zeta for the highest axial mode;
//  - twist: a dashpot on the relative spin of neighbouring edges, same rule with G J / l, I_theta.
#include "engine/term.hpp"

namespace wirepack {

struct DampingParams {
  double c_transverse = 0;  // gamma m per node [N s/m]
  double eta_axial = 0;     // [N s/m]
  double eta_twist = 0;     // [N m s]
};

class RodDamping {
 public:
  explicit RodDamping(const DampingParams& p) : p_(p) {}
  // Adds the damping forces of the dynamic nodes/edges into `out` (uses s.v and s.omega).
  void add_forces(const RodState& s, RodForces& out) const;
  const DampingParams& params() const { return p_; }

 private:
  DampingParams p_;
};

}  // namespace wirepack
