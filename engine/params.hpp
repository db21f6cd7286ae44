#pragma once
// Resolved, validated scene parameters (SI units). Built by sweep/scene_config from the JSON
// scene; the engine never parses files. Immutable once a Simulation is constructed.
#include <cstdint>

namespace wirepack {

enum class ShellKind { Rigid, Elastic };
// An effect a scene may leave out (docs/design.md §2.8, effects on demand). Auto: on where the
// scene has it (twist: iff friction is on, mu_s > 0, since only friction applies torques about the
// centerline; shell self-contact: iff the shell is elastic, since a rigid sphere cannot fold).
enum class EffectMode { Auto, On, Off };
// Mass model of the wire (integrate/wire_mass.hpp): every mode at the scaled density (uniform),
// or only the element-scale modes, the slow ones at the physical density (selective).
enum class MassScaling { Uniform, Selective };
// How the feeder holds the wire's cross-section at the hole (docs/design.md §2.7): Held, the
// guide clamps the material frame (no spin about the feed axis; friction's torques wind twist up
// against it); Free, a swivel: the wire may spin about its axis at the hole and no twisting
// moment is transmitted there. Acts only with twist DOFs.
enum class FeederSpin { Held, Free };
// What the wire's viscous drag acts on (integrate/damping.hpp): Relative, the transverse part of
// each node's velocity (sliding along the wire's own axis is free) plus dashpots on relative
// motion; Absolute, the whole velocity of every node and the spin of every edge (mass-
// proportional damping, C = gamma M_physical: the injected wire sliding along itself is
// dragged too), the same dashpots beside it.
enum class DampingForm { Relative, Absolute };
// The shell membrane's constitutive law: the paper's linear (St. Venant-Kirchhoff) one, or a
// compressible neo-Hookean one equal to it at small strain (engine/shell/membrane.hpp).
enum class ShellMaterialLaw { Linear, NeoHookean };

struct WireParams {
  double radius = 0.5e-3;            // r [m]
  double youngs_modulus = 1e9;       // E_w [Pa]
  double poisson_ratio = 1.0 / 3.0;  // nu_w [-]
  double density = 1140.0;           // physical density [kg/m^3] (polyamide)
};

struct NumericsParams {
  double element_length = 0.5e-3;   // rest length of a wire element [m]
  double shell_mesh_size = 1.0e-3;  // target shell triangle edge [m] (elastic shell only)
  double quasistatic_ratio = 0.01;  // v / c_axial of the element-scale modes; mass scaling [-]
  MassScaling mass_scaling = MassScaling::Selective;
  double tolerance = 1e-3;      // local position error per step, in units of r [-]
  double damping_ratio = 0.05;  // subcritical damping ratio zeta [-]
  DampingForm damping_form = DampingForm::Relative;
  EffectMode twist = EffectMode::Auto;
  EffectMode shell_self_contact = EffectMode::Auto;  // needs an elastic shell
  // c: the shell's vertex masses are those of thickness max(t, min(c r, t rho_w / rho_s)), c in
  // wire radii r (0: t), capped at a physical shell of the wire's density rho_w; its drag keeps
  // the mass of thickness t (scene.hpp, shell_mass_thickness). Scene key
  // numerics/shell_inertia_thickness (kept: it is in run ids) [-].
  double shell_inertia_factor = 1.0;
};

struct SceneParams {
  double rho = 20.0;       // R / r
  double xi = 10.0;        // R / t
  double eps = 1000.0;     // E_w / E_s
  double mu_s = 0.0;       // static friction coefficient
  double mu_d = 0.0;       // dynamic friction coefficient (0.9 mu_s unless set)
  double l_max = 50.0;     // final injected length / R
  std::uint64_t seed = 1;  // seeds the initial transverse perturbation
  ShellKind shell = ShellKind::Elastic;
  ShellMaterialLaw shell_material = ShellMaterialLaw::Linear;
  double injection_speed = 0.5;  // v [m/s]
  FeederSpin feeder_spin = FeederSpin::Held;
  // k_t / k_n of a sticking contact; 0: Mindlin's 2 (1 - nu_w) / (2 - nu_w) [-].
  double friction_stiffness_ratio = 0.0;
  // The imperfections that break the symmetry about the feed axis (feeder.hpp), in units of r:
  // rms tip deflection of the initial wire, rms offset of each released node, and a fixed
  // offset of the initial wire along x (s_rel^2 shape; 0 by default): two runs of one seed whose
  // offsets differ by 1e-6 are twins for the decorrelation diagnostic.
  double perturbation_deflection = 0.05;
  double perturbation_release_noise = 1e-3;
  double perturbation_offset = 0.0;
  WireParams wire;
  NumericsParams numerics;

  double R() const { return rho * wire.radius; }  // sphere radius [m]
  bool twist_enabled() const {
    if (numerics.twist == EffectMode::On) return true;
    if (numerics.twist == EffectMode::Off) return false;
    return mu_s > 0.0;
  }
  bool shell_self_contact_enabled() const {
    return shell == ShellKind::Elastic && numerics.shell_self_contact != EffectMode::Off;
  }
};

}  // namespace wirepack
