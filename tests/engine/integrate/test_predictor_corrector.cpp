// Dynamics of the predictor-corrector on a free rod (no contact): energy conservation without
// damping, monotone decay with damping.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/integrate/damping.hpp"
#include "engine/integrate/predictor_corrector.hpp"
#include "engine/rod/bend.hpp"
#include "engine/rod/material.hpp"
#include "engine/rod/stretch.hpp"

namespace wirepack {
namespace {

// A free rod of n nodes (no guide), bent into a gentle random shape and released at rest.
struct FreeRod {
  RodMaterial mat = RodMaterial::from(WireParams{});
  double ell = 0.5e-3;
  double mass;
  StretchTerm stretch{mat.EA()};
  BendTerm bend{mat.EI()};
  RodDamping damping;
  RodState s;
  RodForces f;

  FreeRod(int n, double zeta, double density)
      : mass(density * mat.A * ell), damping(make_damping(zeta, density)) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int i = 0; i < n; ++i) {
      const double a = 0.02 * i;  // arc of radius 50 l (chords ~ l) plus noise
      s.x.push_back(Vec3(50 * ell * std::sin(a), 50 * ell * (1 - std::cos(a)), 0.0) +
                    0.02 * ell * Vec3(g(rng), g(rng), g(rng)));
    }
    s.v.assign(n, Vec3::Zero());
    s.rest_length.assign(n - 1, ell);
    s.n_free = n;
  }
  DampingParams make_damping(double zeta, double density) const {
    DampingParams d;
    const double m = density * mat.A * ell;
    d.eta_axial = zeta * std::sqrt(2.0 * mat.EA() / ell * m);
    d.c_transverse = 2.0 * zeta * 200.0 * m;
    return d;
  }
  double evaluate(RodState& st, Vec3List& a, std::vector<double>& alpha, Vec3List&) {
    f.reset(st);
    stretch.accumulate(st, f);
    bend.accumulate(st, f);
    damping.add_forces(st, f);
    a.resize(st.x.size());
    for (size_t i = 0; i < st.x.size(); ++i) a[i] = f.f[i] / mass;
    alpha.clear();
    return stretch.omega_max_sq({mass, 0}) + bend.omega_max_sq({mass, 0});
  }
  double total_energy() {
    double k = 0;
    for (const auto& v : s.v) k += 0.5 * mass * v.squaredNorm();
    return k + stretch.energy(s) + bend.energy(s);
  }
};

TEST(PredictorCorrector, ConservesEnergyWithoutDamping) {
  FreeRod rod(40, 0.0, 4e5);
  StepControl c;
  c.tolerance = 1e-4 * rod.mat.r;
  c.dt_floor = 1e-15;
  PredictorCorrector pc(c, rod.mat.r);
  auto eval = [&](RodState& s, Vec3List& a, std::vector<double>& al, Vec3List& sa) {
    return rod.evaluate(s, a, al, sa);
  };
  auto moved = [](RodState&) {};
  pc.initialise(rod.s, eval, moved);
  const double E0 = rod.total_energy();
  ASSERT_GT(E0, 0.0);
  double worst = 0.0;
  for (int k = 0; k < 100000; ++k) {
    pc.step(rod.s, eval, moved);
    if (k % 1000 == 0) worst = std::max(worst, std::abs(rod.total_energy() - E0) / E0);
  }
  worst = std::max(worst, std::abs(rod.total_energy() - E0) / E0);
  std::printf("  relative energy drift over 1e5 steps: %.3e\n", worst);
  // Second-order, time-reversible scheme with a step that changes only in clear jumps: the
  // discrete energy oscillates at O(dt^2) and drifts slowly (measured 0.8 % over 1e5 steps with
  // the noise exciting the highest modes); 2 % bounds it.
  EXPECT_LT(worst, 2e-2);
}

TEST(PredictorCorrector, DampingDissipatesEnergy) {
  FreeRod rod(40, 0.5, 4e5);
  StepControl c;
  c.tolerance = 1e-4 * rod.mat.r;
  c.damping_ratio = 0.5;
  c.dt_floor = 1e-15;
  PredictorCorrector pc(c, rod.mat.r);
  auto eval = [&](RodState& s, Vec3List& a, std::vector<double>& al, Vec3List& sa) {
    return rod.evaluate(s, a, al, sa);
  };
  auto moved = [](RodState&) {};
  pc.initialise(rod.s, eval, moved);
  const double E0 = rod.total_energy();
  double prev = E0;
  int increases = 0;
  for (int k = 0; k < 20; ++k) {
    for (int j = 0; j < 2000; ++j) pc.step(rod.s, eval, moved);
    const double E = rod.total_energy();
    // Below 1e-3 E0 the O(dt^2) oscillation of the discrete energy is as large as what is left.
    if (E > prev * (1 + 1e-9) && prev > 1e-3 * E0) ++increases;
    prev = E;
  }
  std::printf("  energy after 4e4 damped steps: %.3e of the initial\n", prev / E0);
  EXPECT_EQ(increases, 0);
  EXPECT_LT(prev, 0.5 * E0);
}

}  // namespace
}  // namespace wirepack
