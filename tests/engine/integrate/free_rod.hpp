#pragma once
// A free rod (no guide) of n nodes under stretch and bend, bent into a gentle random arc (radius
// 50 l plus noise of 0.02 l) and released at rest, integrated by the predictor-corrector with a
// given mass model (lumped: beta = 0, or selective) and damping. Shared by the dynamics tests.
#include <algorithm>
#include <cmath>
#include <random>

#include "engine/integrate/damping.hpp"
#include "engine/integrate/predictor_corrector.hpp"
#include "engine/integrate/wire_mass.hpp"
#include "engine/rod/bend.hpp"
#include "engine/rod/material.hpp"
#include "engine/rod/stretch.hpp"

namespace wirepack::rigs {

struct FreeRod {
  RodMaterial mat = RodMaterial::from(WireParams{});
  double ell = 0.5e-3;  // [m]
  WireMass mass;
  StretchTerm stretch{mat.EA()};
  BendTerm bend{mat.EI()};
  RodDamping damping;
  State s;
  Forces f;

  FreeRod(int n, const WireMass& m, const DampingParams& d) : mass(m), damping(d) {
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
    mass.factorise(n, false);
  }
  // Step control of the dynamics tests: tolerance 1e-4 r, damping ratio zeta, no floor.
  StepControl control(double zeta) const {
    StepControl c;
    c.tolerance = 1e-4 * mat.r;
    c.damping_ratio = zeta;
    c.dt_floor = 1e-15;
    return c;
  }
  // Node mass rho A l at a density [kg].
  double node_mass(double density) const { return density * mat.A * ell; }
  double evaluate(State& st, Vec3List& a, std::vector<double>& alpha, Vec3List&) {
    f.reset(st);
    stretch.accumulate(st, f);
    bend.accumulate(st, f);
    damping.add_forces(st, f);
    mass.solve(f.f, a);
    alpha.clear();
    const RodInertia in{mass.mode_mass(), 0.0};
    return stretch.omega_max_sq(in) + bend.omega_max_sq(in);
  }
  double total_energy() {
    return mass.kinetic_energy(s.v, s.n_free) + stretch.energy(s) + bend.energy(s);
  }

  // Takes `steps` steps; every 1000 steps compares the energy with the start. Returns the largest
  // relative drift; `increases` (if given) counts rises of the energy between checks while it is
  // above 1e-3 of the start (below that the O(dt^2) oscillation of the discrete energy is as
  // large as what is left), `left` (if given) the final energy over the start.
  // `elapsed` (if given) receives the time the steps covered [s].
  double run(const StepControl& c, int steps, int* increases = nullptr, double* left = nullptr,
             double* elapsed = nullptr) {
    PredictorCorrector pc(c, mat.r);
    auto eval = [&](State& st, Vec3List& a, std::vector<double>& al, Vec3List& sa) {
      return evaluate(st, a, al, sa);
    };
    auto moved = [](State&) {};
    pc.initialise(s, eval, moved);
    const double E0 = total_energy();
    double worst = 0.0, prev = E0, t = 0.0;
    for (int k = 1; k <= steps; ++k) {
      t += pc.step(s, eval, moved);
      if (k % 1000 != 0 && k != steps) continue;
      const double E = total_energy();
      worst = std::max(worst, std::abs(E - E0) / E0);
      if (increases && E > prev * (1 + 1e-9) && prev > 1e-3 * E0) ++*increases;
      prev = E;
    }
    if (left) *left = prev / E0;
    if (elapsed) *elapsed = t;
    return worst;
  }
};

}  // namespace wirepack::rigs
