#pragma once
// Validated parameters -> the set of effects this scene needs (docs/design.md §2.8, effects on
// demand). A rigid shell builds no mesh; mu_s = 0 builds no friction; twist DOFs exist only when
// the scene's twist mode asks for them. The cost of an effect that is off is zero because it is
// simply not in the list.
#include <memory>
#include <vector>

#include "engine/contact/self_contact.hpp"
#include "engine/contact/sphere_wall.hpp"
#include "engine/contact/wire_shell.hpp"
#include "engine/feeder.hpp"
#include "engine/integrate/damping.hpp"
#include "engine/integrate/predictor_corrector.hpp"
#include "engine/integrate/wire_mass.hpp"
#include "engine/params.hpp"
#include "engine/rod/material.hpp"
#include "engine/shell/shell_term.hpp"
#include "engine/term.hpp"

namespace wirepack {

// Numerical constants of ours (documented in docs/design.md and docs/reference.md).
struct SceneConstants {
  static constexpr double kHoleClearance = 0.1;  // hole radius r_h = (1 + 0.1) r
  static constexpr double kSkin = 0.5;           // Verlet skin of the self-contact list / r
  // Verlet skin of the shell's own contact list / r. Its rebuild scans every mesh edge and face
  // (most pairs then excluded as rest neighbours) while its candidates are only folded pieces,
  // so a wider skin than the wire's trades a few more candidates for 4x fewer rebuilds.
  static constexpr double kShellSelfSkin = 2.0;
  static constexpr double kDtFloorFraction = 1e-6;  // step collapse below this x initial stable dt
  // In the rigid sphere, a released node this far below the hole's rim plane / r has been
  // pushed back out: a jam. Released nodes stay on or above the plane in normal rigid runs
  // (rho = 5 to l = 40: never below); the jam the hard-scene suite found put one 0.42 r below.
  static constexpr double kJamDepth = 0.25;
  static constexpr double kShellPoisson = 1.0 / 3.0;  // nu_s (paper)
  // Damping ratio of the wire's element-scale zig-zag, over damping_ratio (selective mass; the
  // bending-rate dashpot of integrate/damping.hpp). 1/10: enough to keep the element-scale
  // vibration that sliding contacts excite below 1 % of U_b; at 1 the extra dissipation in
  // frictional slips moved U_b of rigid mu_s = 1 packings 12 % off the near-physical reference.
  static constexpr double kZigZagDamping = 0.1;
};

struct Assembly {
  RodMaterial material;
  double density_scaled = 0;  // rho_eff = E_w q^2 / v^2 (mass scaling) [kg/m^3]
  WireMass mass;              // the wire's translational mass matrix (nodes)
  WireMass twist_mass;        // the same for the twist angles (edges) [kg m^2]
  RodInertia inertia;         // of the zig-zag modes (mass.mode_mass(), twist_mass.mode_mass())
  DampingParams damping;
  FeederParams feeder;
  StepControl control;
  std::vector<std::unique_ptr<Term>> terms;
  SphereWallTerm* wall = nullptr;  // owned by `terms` (rigid shell)
  SelfContactTerm* self_contact = nullptr;

  // Elastic shell (Engine III); empty for a rigid sphere.
  std::unique_ptr<ShellMesh> mesh;  // rest mesh, shared read-only by the shell terms
  ShellMaterial shell_material;
  std::vector<double> vertex_mass;      // lumped, rho_s t_m A / 3 (nv) [kg]
  double shell_damping_rate = 0;        // gamma_s of the vertex damping [1/s]
  WireShellTerm* wire_shell = nullptr;  // owned by `terms`
  WireShellParams wire_shell_params;    // its parameters (for read-only probes)
};

// Thickness whose inertia the shell's vertices carry [m]: t_m = max(t, min(c r, t rho_w / rho_s))
// with t = R / xi, c = numerics.shell_inertia_factor, rho_s = E_s q^2 / v^2 the scaled
// shell density and rho_w the wire's physical density: a thin shell (t < c r) gets heavier
// vertices, but never heavier than a physical shell of the wire's density (scene.cpp).
double shell_mass_thickness(const SceneParams& p);

// Throws std::invalid_argument for scenes this engine cannot simulate.
Assembly assemble(const SceneParams& p);

}  // namespace wirepack
