#include "engine/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/contact/shell_self_contact.hpp"
#include "engine/rod/bend.hpp"
#include "engine/rod/stretch.hpp"
#include "engine/rod/twist.hpp"
#include "engine/shell/bending.hpp"
#include "engine/shell/membrane.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/shell_adapter.hpp"

namespace wirepack {

double shell_mass_thickness(const SceneParams& p) {
  const double t = p.R() / p.xi;
  const double q = p.numerics.quasistatic_ratio, v = p.injection_speed;
  const double rho_s = p.wire.youngs_modulus / p.eps * q * q / (v * v);  // [kg/m^3]
  // Never above the physical inertia, the shell taken at the wire's density (both polymers).
  const double t_physical = t * std::max(1.0, p.wire.density / rho_s);
  return std::max(t, std::min(p.numerics.shell_inertia_factor * p.wire.radius, t_physical));
}

Assembly assemble(const SceneParams& p) {
  Assembly a;
  const WireParams& w = p.wire;
  const double r = w.radius;
  const double R = p.R();
  const double ell = p.numerics.element_length;
  const double v = p.injection_speed;
  const double zeta = p.numerics.damping_ratio;
  a.material = RodMaterial::from(w);
  const RodMaterial& m = a.material;

  // Mass scaling: quasistatic_ratio q = v / c_axial with c_axial = sqrt(E / rho_eff), for every
  // mode (uniform) or for the element-scale modes only (selective; see integrate/wire_mass.hpp).
  const double q = p.numerics.quasistatic_ratio;
  a.density_scaled = m.E * q * q / (v * v);
  const bool selective = p.numerics.mass_scaling == MassScaling::Selective;
  const double m_scaled = a.density_scaled * m.A * ell;
  // Density of the slow modes [kg/m^3]: physical (selective), else the scaled one.
  const double rho_slow = selective ? w.density : a.density_scaled;
  const double m_slow = rho_slow * m.A * ell;
  a.mass = WireMass(m_slow, selective ? std::max(0.0, 0.25 * (m_scaled - m_slow)) : 0.0);
  a.inertia.node_mass = selective ? a.mass.mode_mass() : m_scaled;
  // Twist: the same model along the chain of edges (spin inertia rho J l per edge).
  const double I_scaled = a.density_scaled * m.J * ell;
  const double I_slow = rho_slow * m.J * ell;
  a.twist_mass = WireMass(I_slow, selective ? std::max(0.0, 0.25 * (I_scaled - I_slow)) : 0.0);
  a.inertia.edge_twist_inertia = selective ? a.twist_mass.mode_mass() : I_scaled;

  // Damping (see integrate/damping.hpp); the transverse rate refers to the slow modes' mass.
  const double omega0 = std::sqrt(m.EI() / (rho_slow * m.A * std::pow(R, 4)));
  a.damping.c_transverse = 2.0 * zeta * omega0 * m_slow;
  a.damping.absolute = p.numerics.damping_form == DampingForm::Absolute;
  if (a.damping.absolute) a.damping.c_spin = 2.0 * zeta * omega0 * I_slow;
  a.damping.eta_axial = zeta * std::sqrt(2.0 * m.EA() / ell * a.inertia.node_mass);
  a.damping.eta_twist = zeta * std::sqrt(2.0 * m.GJ() / ell * a.inertia.edge_twist_inertia);
  // Bending-rate dashpot (selective mass): the zig-zag mode (mass m_s, Laplacian eigenvalue 4,
  // omega_zz^2 = 16 E I / (l^3 m_s)) gets the ratio kZigZagDamping zeta: eta 16 / m_s =
  // 2 kZigZagDamping zeta omega_zz.
  if (selective && a.mass.beta() > 0.0) {
    const double m_zz = a.mass.mode_mass();
    const double omega_zz = std::sqrt(16.0 * m.EI() / (ell * ell * ell * m_zz));
    a.damping.eta_bending = 2.0 * SceneConstants::kZigZagDamping * zeta * omega_zz * m_zz / 16.0;
  }

  const bool twist = p.twist_enabled();
  a.feeder.R = R;
  a.feeder.r = r;
  a.feeder.hole_radius = (1.0 + SceneConstants::kHoleClearance) * r;
  a.feeder.element_length = ell;
  a.feeder.speed = v;
  a.feeder.deflection = p.perturbation_deflection * r;
  a.feeder.release_noise = p.perturbation_release_noise * r;
  a.feeder.offset = p.perturbation_offset * r;
  a.feeder.seed = p.seed;
  a.feeder.twist = twist;
  a.feeder.spin_free = twist && p.feeder_spin == FeederSpin::Free;
  a.damping.twist_free_at_guide = a.feeder.spin_free;

  a.control.tolerance = p.numerics.tolerance * r;
  a.control.damping_ratio = zeta;

  // Wire elasticity.
  a.terms.push_back(std::make_unique<StretchTerm>(m.EA()));
  a.terms.push_back(std::make_unique<BendTerm>(m.EI()));
  if (twist) a.terms.push_back(std::make_unique<TwistTerm>(m.GJ(), a.feeder.spin_free));

  // Coulomb friction, shared by every contact type (off when mu_s = 0).
  FrictionParams fp;
  fp.mu_s = p.mu_s;
  fp.mu_d = p.mu_d;
  fp.stiffness_ratio = p.friction_stiffness_ratio > 0.0
                           ? p.friction_stiffness_ratio
                           : 2.0 * (1.0 - w.poisson_ratio) / (2.0 - w.poisson_ratio);  // Mindlin
  fp.damping_ratio = zeta;

  if (p.shell == ShellKind::Rigid) {
    // Rigid sphere wall.
    SphereWallParams wp;
    wp.R = R;
    wp.r = r;
    wp.hole_radius = a.feeder.hole_radius;
    wp.E_star = effective_modulus(w.youngs_modulus, w.poisson_ratio,
                                  std::numeric_limits<double>::infinity(), 0.0);
    wp.damping_ratio = zeta;
    wp.node_mass = a.mass.point_mass();
    wp.friction = fp;
    auto wall = std::make_unique<SphereWallTerm>(wp);
    a.wall = wall.get();
    a.terms.push_back(std::move(wall));
  } else {
    // Elastic shell: mid-surface radius R, thickness t = R / xi, E_s = E_w / eps.
    ShellMaterial& sm = a.shell_material;
    sm.law = p.shell_material;
    sm.E = w.youngs_modulus / p.eps;
    sm.nu = SceneConstants::kShellPoisson;
    sm.t = R / p.xi;
    const double h = 0.5 * sm.t;
    // The hole lets the wire through with the same clearance as the rigid sphere's: the
    // capsule of the wire clears the rim's slab by 0.1 r.
    const double hole = (1.0 + SceneConstants::kHoleClearance) * r + h;
    const double mesh_size = p.numerics.shell_mesh_size;
    a.mesh = std::make_unique<ShellMesh>(sphere_with_hole(R, mesh_size, hole, mesh_size));
    const ShellMesh& mesh = *a.mesh;
    a.feeder.hole_radius = R * std::sin(sphere_hole_radius(mesh_size, hole) / R);
    // Masses: the shell gets the wire's quasistatic ratio, v / c_s = q with the membrane
    // wave speed c_s = sqrt(E_s / rho_s), i.e. rho_s = E_s q^2 / v^2. Scaling the shell's
    // physical density by the wire's factor instead would give a soft shell (eps = 1e3) a
    // breathing period as long as the time to inject R, v / c_s ~ 0.3: a heavy shell that
    // lags the wire, where the paper's is quasistatic (v / c_s ~ 0.016).
    const double rho_s = sm.E * q * q / (v * v);
    // Thin shells carry the inertia of thickness t_m = shell_mass_thickness(p) >= t: up to
    // c r (c = numerics.shell_inertia_factor), never above the physical inertia. A contact
    // stiffens a vertex by ~2 E* sqrt(r delta) whatever t, while the membrane's stiffness and
    // the vertex mass go as t: below t ~ r the contacts, not the membrane waves, set the step.
    const double t_mass = shell_mass_thickness(p);
    a.vertex_mass.assign(mesh.num_vertices(), 0.0);
    for (const auto& f : mesh.faces) {
      const double area =
          0.5 * (mesh.rest[f[1]] - mesh.rest[f[0]]).cross(mesh.rest[f[2]] - mesh.rest[f[0]]).norm();
      for (int v : f) a.vertex_mass[v] += rho_s * t_mass * area / 3.0;
    }
    double m_min = std::numeric_limits<double>::infinity();
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      if (!mesh.clamped[v]) m_min = std::min(m_min, a.vertex_mass[v]);
    }
    // Vertex damping at 2 zeta omega_b, the membrane breathing frequency of the sphere,
    // omega_b^2 = 2 E_s / (rho_s R^2 (1 - nu_s)): the mode the injected wire drives.
    // The rate refers to the mass of thickness t: the drag per vertex, rate x mass, does not
    // grow with the extra inertia of a thin shell (t_mass > t), so slow (overdamped) motions of
    // the shell relax as before.
    a.shell_damping_rate = 2.0 * zeta * std::sqrt(2.0 * sm.E / (rho_s * R * R * (1.0 - sm.nu)));
    if (t_mass > sm.t) a.shell_damping_rate *= sm.t / t_mass;
    a.terms.push_back(
        std::make_unique<ShellTermAdapter>(std::make_unique<MembraneTerm>(mesh, sm), m_min));
    a.terms.push_back(
        std::make_unique<ShellTermAdapter>(std::make_unique<BendingTerm>(mesh, sm), m_min));
    WireShellParams ws;
    ws.r = r;
    ws.half_thickness = h;
    ws.E_star = effective_modulus(w.youngs_modulus, w.poisson_ratio, sm.E, sm.nu);
    ws.skin = SceneConstants::kSkin * r;
    ws.damping_ratio = zeta;
    ws.node_mass = a.mass.point_mass();
    ws.vertex_mass = m_min;
    ws.friction = fp;
    // The guide outside the hole is a contact body, ten radii of feed axis below the rim's
    // plane (wire_shell.hpp): a soft shell pushed out below the rim must not wrap the wire
    // still outside (it reaches 1.7 R below the pole at eps = 1e4, xi = 30, l = 50).
    const double hr = a.feeder.hole_radius;
    ws.guide = true;
    ws.guide_bottom_z = -std::sqrt(R * R - hr * hr) - 10.0 * R;
    a.wire_shell_params = ws;
    auto contact = std::make_unique<WireShellTerm>(mesh, ws);
    a.wire_shell = contact.get();
    a.terms.push_back(std::move(contact));
    if (p.shell_self_contact_enabled()) {
      // Shell on itself: E* = E_s / (2 (1 - nu_s^2)); pairs within 2 t + one mesh edge of
      // each other on the rest sphere never touch (only folded-over pieces do).
      ShellSelfContactParams ss;
      ss.half_thickness = h;
      ss.E_star = effective_modulus(sm.E, sm.nu, sm.E, sm.nu);
      ss.skin = SceneConstants::kShellSelfSkin * r;
      ss.damping_ratio = zeta;
      ss.vertex_mass = m_min;
      ss.friction = fp;
      ss.exclusion = ShellSelfContactTerm::suggested_exclusion(mesh, h);
      a.terms.push_back(std::make_unique<ShellSelfContactTerm>(mesh, ss));
    }
  }

  // Wire self-contact.
  SelfContactParams sp;
  sp.r = r;
  sp.E_star =
      effective_modulus(w.youngs_modulus, w.poisson_ratio, w.youngs_modulus, w.poisson_ratio);
  sp.element_length = ell;
  sp.skin = SceneConstants::kSkin * r;
  sp.damping_ratio = zeta;
  sp.node_mass = a.mass.point_mass();
  sp.friction = fp;
  auto self = std::make_unique<SelfContactTerm>(sp);
  a.self_contact = self.get();
  a.terms.push_back(std::move(self));
  return a;
}

}  // namespace wirepack
