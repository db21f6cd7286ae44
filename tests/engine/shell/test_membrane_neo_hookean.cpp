// The neo-Hookean membrane (ShellMaterialLaw::NeoHookean, engine/shell/membrane.hpp): its
// agreement with the linear law at small strain, the exact energy of a uniform dilation, the
// inflated sphere's pressure-stretch curve with its limit point (from the forces), and the
// explicit step's bound in tension and compression. Its finite-difference gradient is checked
// beside the linear law's (MembraneFd in test_membrane.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/shell/membrane.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/shell_fixtures.hpp"
#include "engine/shell/static_solve.hpp"

namespace wirepack {
namespace {

using testing::paper_material;
using testing::perturbed;

ShellMaterial neo_material() {
  ShellMaterial m = paper_material();
  m.law = ShellMaterialLaw::NeoHookean;
  return m;
}

double rest_area(const ShellMesh& m) {
  double a = 0.0;
  for (const auto& f : m.faces)
    a += 0.5 * (m.rest[f[1]] - m.rest[f[0]]).cross(m.rest[f[2]] - m.rest[f[0]]).norm();
  return a;
}

double rest_volume(const ShellMesh& m) {  // closed mesh, outward faces [m^3]
  double v = 0.0;
  for (const auto& f : m.faces) v += m.rest[f[0]].dot(m.rest[f[1]].cross(m.rest[f[2]])) / 6.0;
  return v;
}

// Energy density of an equibiaxial stretch lam, C = lam^2 I: W = mu (lam^2 - 1 - 2 ln lam) +
// 2 lambda (ln lam)^2, and its derivative dW/dlam [N/m] (mu, lambda: the 2-D Lame moduli).
struct Equibiaxial {
  double mu, lambda;
  explicit Equibiaxial(const ShellMaterial& m)
      : mu(0.5 * m.M() * (1.0 - m.nu)), lambda(m.M() * m.nu) {}
  double W(double s) const {
    return mu * (s * s - 1.0 - 2.0 * std::log(s)) + 2.0 * lambda * std::log(s) * std::log(s);
  }
  double dW(double s) const { return 2.0 * mu * (s - 1.0 / s) + 4.0 * lambda * std::log(s) / s; }
};

// The two laws agree to second order in the strain e: energies and forces differ by a relative
// O(e). At vertex noise 1e-4 and 1e-3 of an edge (strains of that order) the relative
// differences are below 10x the noise, and they shrink ~10x with it (ratio 5-20).
TEST(NeoHookeanMembrane, EqualsTheLinearLawAtSmallStrain) {
  const ShellMesh mesh = sphere_with_hole(10e-3, 2e-3, 1e-3, 0.5e-3);
  MembraneTerm lin(mesh, paper_material());
  MembraneTerm neo(mesh, neo_material());
  const double edge = mesh_quality(mesh).edge_mean;
  std::vector<double> rel_energy, rel_force;
  for (double amp : {1e-3, 1e-4}) {
    const Vec3List x = perturbed(mesh.rest, amp * edge, 11);
    Vec3List fl(x.size(), Vec3::Zero()), fn(x.size(), Vec3::Zero());
    const double ul = lin.accumulate(x, fl), un = neo.accumulate(x, fn);
    double df = 0.0, fmax = 0.0;
    for (size_t v = 0; v < x.size(); ++v) {
      df = std::max(df, (fn[v] - fl[v]).norm());
      fmax = std::max(fmax, fl[v].norm());
    }
    rel_energy.push_back(std::abs(un / ul - 1.0));
    rel_force.push_back(df / fmax);
    std::printf("  noise %.0e edge: |U_neo / U_lin - 1| = %.2e, max |df| / max |f| = %.2e\n", amp,
                rel_energy.back(), rel_force.back());
    EXPECT_LT(rel_energy.back(), 10.0 * amp);
    EXPECT_LT(rel_force.back(), 10.0 * amp);
  }
  EXPECT_GT(rel_force[0] / rel_force[1], 5.0);
  EXPECT_LT(rel_force[0] / rel_force[1], 20.0);
}

// A uniform dilation x -> s x gives every face C = s^2 I, so the discrete energy is exactly the
// rest area times W(s), in compression and in tension, to round-off (1e-12 relative).
TEST(NeoHookeanMembrane, UniformDilationEnergyIsExact) {
  const ShellMaterial mat = neo_material();
  const ShellMesh mesh = geodesic_sphere(10e-3, 2e-3);
  MembraneTerm term(mesh, mat);
  const Equibiaxial law(mat);
  const double area = rest_area(mesh);
  for (double s : {0.5, 0.9, 1.01, 1.5, 3.0}) {
    Vec3List x = mesh.rest;
    for (Vec3& p : x) p *= s;
    const double expected = area * law.W(s);
    EXPECT_NEAR(term.energy(x) / expected, 1.0, 1e-12) << "stretch " << s;
  }
}

// The inflated sphere. Along the uniform inflation x = s X the pressure that holds the membrane
// is p(s) = (dU/ds) / (dV/ds) (virtual work), and dU/ds = -sum_v f_v . X_v from the term's own
// forces. Analytic: p(s) = A W'(s) / (3 s^2 V) with the mesh's rest area A and volume V; for
// the continuum sphere (A = 4 pi R^2, V = 4/3 pi R^3) p(s) = W'(s) / (R s^2), the classical
// curve that rises, peaks (the limit point: a balloon that blows up at constant pressure) and
// falls. The force-based curve matches the analytic one to 1e-9, its peak the analytic peak
// (root of d/ds [W'(s) / s^2], by bisection) to 1e-6 in s; the linear law has no peak on
// s <= 3 (it stiffens in tension).
TEST(NeoHookeanMembrane, InflatedSpherePressureStretchHasTheLimitPoint) {
  const ShellMaterial mat = neo_material();
  const double R = 10e-3;
  const ShellMesh mesh = geodesic_sphere(R, 2e-3);
  MembraneTerm neo(mesh, mat);
  MembraneTerm lin(mesh, paper_material());
  const Equibiaxial law(mat);
  const double A = rest_area(mesh), V = rest_volume(mesh);
  const auto pressure = [&](MembraneTerm& term, double s) {
    Vec3List x = mesh.rest, f(mesh.rest.size(), Vec3::Zero());
    for (Vec3& p : x) p *= s;
    term.accumulate(x, f);
    double dU = 0.0;
    for (size_t v = 0; v < x.size(); ++v) dU -= f[v].dot(mesh.rest[v]);
    return dU / (3.0 * s * s * V);
  };
  const auto analytic = [&](double s) { return A * law.dW(s) / (3.0 * s * s * V); };
  for (double s : {1.001, 1.2, 1.5, 2.0, 3.0})
    EXPECT_NEAR(pressure(neo, s) / analytic(s), 1.0, 1e-9) << "stretch " << s;
  // The analytic peak: d/ds [W'(s) / s^2] = (s W'' - 2 W') / s^3 changes sign once on (1, 3).
  const auto slope = [&](double s) {
    const double h = 1e-6 * s;
    return (law.dW(s + h) / ((s + h) * (s + h)) - law.dW(s - h) / ((s - h) * (s - h))) / (2 * h);
  };
  double lo = 1.0 + 1e-9, hi = 3.0;
  ASSERT_GT(slope(lo), 0.0);
  ASSERT_LT(slope(hi), 0.0);
  for (int it = 0; it < 60; ++it) (slope(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double s_star = 0.5 * (lo + hi);
  // The force-based curve's peak: golden-section search on (1, 3).
  double a = 1.0, b = 3.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    (pressure(neo, c) > pressure(neo, d) ? b : a) = (pressure(neo, c) > pressure(neo, d) ? d : c);
  }
  const double s_peak = 0.5 * (a + b);
  const double p_star_continuum = law.dW(s_star) / (R * s_star * s_star);
  std::printf(
      "  limit point: stretch %.6f (analytic %.6f), p = %.4g Pa (continuum sphere %.4g Pa; "
      "mesh area / 4 pi R^2 = %.4f)\n",
      s_peak, s_star, pressure(neo, s_peak), p_star_continuum, A / (4.0 * M_PI * R * R));
  EXPECT_NEAR(s_peak, s_star, 1e-6);
  EXPECT_NEAR(pressure(neo, s_peak) / p_star_continuum, 1.0, 0.02);  // the mesh's facets
  EXPECT_GT(pressure(neo, 1.1), 0.0);
  EXPECT_LT(pressure(neo, 3.0), pressure(neo, s_star));  // falls beyond the peak
  for (double s = 1.1; s < 3.0; s += 0.1) EXPECT_GT(pressure(lin, s + 0.1), pressure(lin, s));
}

// omega_max^2 m bounds the largest eigenvalue of the FD stiffness at rest, in 10 % and 100 %
// dilation, in 30 % compression (where the law stiffens), at random +-20 % strains and with
// one vertex pushed in by 0.4 edges; and at rest by no more than a factor 4.
TEST(NeoHookeanMembrane, OmegaBoundsTheLargestStiffnessEigenvalue) {
  const ShellMaterial mat = neo_material();
  const ShellMesh mesh = sphere_with_hole(10e-3, 4e-3, 3e-3, 1e-3);
  MembraneTerm term(mesh, mat);
  const double edge = mesh_quality(mesh).edge_mean;
  std::vector<Vec3List> states{
      mesh.rest, mesh.rest, mesh.rest, mesh.rest, perturbed(mesh.rest, 0.1 * edge, 7), mesh.rest};
  for (Vec3& p : states[1]) p *= 1.1;
  for (Vec3& p : states[2]) p *= 2.0;
  for (Vec3& p : states[3]) p *= 0.7;
  const int pushed = static_cast<int>(mesh.rest.size()) / 2;
  states[5][pushed] -= 0.4 * edge * mesh.rest[pushed].normalized();
  for (size_t k = 0; k < states.size(); ++k) {
    const auto [lmax, bound] = testing::step_bound(term, mesh, states[k]);
    std::printf("  state %zu: lambda_max(K) = %.4g N/m, bound %.4g N/m (ratio %.2f)\n", k, lmax,
                bound, bound / lmax);
    EXPECT_GE(bound, lmax) << "state " << k;
    if (k == 0) {
      EXPECT_LT(bound, 4.0 * lmax);
    }
  }
}

// A face of zero area has no neo-Hookean energy (ln det C = -inf): the term stops the run with a
// reason that names the face, where the linear law gives a finite energy for the same state.
TEST(NeoHookeanMembrane, ACollapsedFaceStopsTheRunNamingIt) {
  const ShellMesh mesh = sphere_with_hole(10e-3, 4e-3, 3e-3, 1e-3);
  Vec3List x = mesh.rest;
  const auto& f0 = mesh.faces[0];
  x[f0[0]] = x[f0[1]];  // face 0's first edge shrunk to nothing: area exactly 0
  MembraneTerm neo(mesh, neo_material());
  Vec3List f(x.size(), Vec3::Zero());
  for (int pass = 0; pass < 2; ++pass) {
    try {
      if (pass == 0) neo.accumulate(x, f);
      if (pass == 1) neo.energy(x);
      ADD_FAILURE() << "pass " << pass << ": no error";
    } catch (const SimulationError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("face 0 (vertices " + std::to_string(f0[0])), std::string::npos) << what;
      EXPECT_NE(what.find("has collapsed (area 0"), std::string::npos) << what;
    }
  }
  MembraneTerm lin(mesh, paper_material());
  EXPECT_TRUE(std::isfinite(lin.accumulate(x, f)));
  EXPECT_TRUE(std::isfinite(lin.energy(x)));
  // The term is not left broken: at rest it gives what a fresh one gives (~0, rounding only).
  MembraneTerm fresh(mesh, neo_material());
  EXPECT_EQ(neo.energy(mesh.rest), fresh.energy(mesh.rest));
}

}  // namespace
}  // namespace wirepack
