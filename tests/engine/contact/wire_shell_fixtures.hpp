#pragma once
// Shared by the wire-shell contact tests: a wire of radius r = 0.5 mm on a shell of
// half-thickness 0.25 mm, E_w = 1 GPa against E_s = 1 MPa (nu = 1/3 both), a skin of r / 2,
// equal node and vertex masses of 0.1 g, no damping, no friction.
#include "engine/contact/wire_shell.hpp"

namespace wirepack::testing {

inline WireShellParams wire_shell_params() {
  constexpr double r = 0.5e-3, h = 0.25e-3, Ew = 1e9, Es = 1e6, nu = 1.0 / 3.0;
  WireShellParams p;
  p.r = r;
  p.half_thickness = h;
  p.E_star = 1.0 / ((1 - nu * nu) / Ew + (1 - nu * nu) / Es);
  p.skin = 0.5 * r;
  p.node_mass = 1e-4;
  p.vertex_mass = 1e-4;
  return p;
}

}  // namespace wirepack::testing
