#include "engine/scene.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/rod/bend.hpp"
#include "engine/rod/stretch.hpp"
#include "engine/rod/twist.hpp"

namespace wirepack {

Assembly assemble(const SceneParams& p) {
  if (p.shell == ShellKind::Elastic) {
    throw std::invalid_argument(
        "shell = \"elastic\" is not available yet (Engine III); use \"rigid\"");
  }
  Assembly a;
  const WireParams& w = p.wire;
  const double r = w.radius;
  const double R = p.R();
  const double ell = p.numerics.element_length;
  const double v = p.injection_speed;
  const double zeta = p.numerics.damping_ratio;
  a.material = RodMaterial::from(w);
  const RodMaterial& m = a.material;

  // Mass scaling: quasistatic_ratio q = v / c_axial with c_axial = sqrt(E / rho_eff).
  const double q = p.numerics.quasistatic_ratio;
  a.density_scaled = m.E * q * q / (v * v);
  a.inertia.node_mass = a.density_scaled * m.A * ell;
  a.inertia.edge_twist_inertia = a.density_scaled * m.J * ell;

  // Damping (see integrate/damping.hpp).
  const double omega0 = std::sqrt(m.EI() / (a.density_scaled * m.A * std::pow(R, 4)));
  a.damping.c_transverse = 2.0 * zeta * omega0 * a.inertia.node_mass;
  a.damping.eta_axial = zeta * std::sqrt(2.0 * m.EA() / ell * a.inertia.node_mass);
  a.damping.eta_twist = zeta * std::sqrt(2.0 * m.GJ() / ell * a.inertia.edge_twist_inertia);

  const bool twist = p.twist_enabled();
  a.feeder.R = R;
  a.feeder.r = r;
  a.feeder.hole_radius = (1.0 + SceneConstants::kHoleClearance) * r;
  a.feeder.element_length = ell;
  a.feeder.speed = v;
  a.feeder.deflection = SceneConstants::kDeflection * r;
  a.feeder.release_noise = SceneConstants::kReleaseNoise * r;
  a.feeder.seed = p.seed;
  a.feeder.twist = twist;

  a.control.tolerance = p.numerics.tolerance * r;
  a.control.damping_ratio = zeta;

  // Wire elasticity.
  a.terms.push_back(std::make_unique<StretchTerm>(m.EA()));
  a.terms.push_back(std::make_unique<BendTerm>(m.EI()));
  if (twist) a.terms.push_back(std::make_unique<TwistTerm>(m.GJ()));

  // Coulomb friction, shared by every contact type (off when mu_s = 0).
  FrictionParams fp;
  fp.mu_s = p.mu_s;
  fp.mu_d = p.mu_d;
  fp.stiffness_ratio = 2.0 * (1.0 - w.poisson_ratio) / (2.0 - w.poisson_ratio);  // Mindlin
  fp.damping_ratio = zeta;

  // Rigid sphere wall.
  SphereWallParams wp;
  wp.R = R;
  wp.r = r;
  wp.hole_radius = a.feeder.hole_radius;
  wp.E_star = effective_modulus(w.youngs_modulus, w.poisson_ratio,
                                std::numeric_limits<double>::infinity(), 0.0);
  wp.damping_ratio = zeta;
  wp.node_mass = a.inertia.node_mass;
  wp.friction = fp;
  auto wall = std::make_unique<SphereWallTerm>(wp);
  a.wall = wall.get();
  a.terms.push_back(std::move(wall));

  // Wire self-contact.
  SelfContactParams sp;
  sp.r = r;
  sp.E_star =
      effective_modulus(w.youngs_modulus, w.poisson_ratio, w.youngs_modulus, w.poisson_ratio);
  sp.element_length = ell;
  sp.skin = SceneConstants::kSkin * r;
  sp.damping_ratio = zeta;
  sp.node_mass = a.inertia.node_mass;
  sp.friction = fp;
  auto self = std::make_unique<SelfContactTerm>(sp);
  a.self_contact = self.get();
  a.terms.push_back(std::move(self));
  return a;
}

}  // namespace wirepack
