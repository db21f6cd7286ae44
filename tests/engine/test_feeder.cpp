// The feeder's hold on the wire's spin at the hole (FeederSpin, docs/design.md §2.7): held (the
// guide clamps the cross-section) against free (a swivel). Tested on the twist chain alone: a
// straight wire on the feed axis driven by a torque at its tip, where the two boundary
// conditions have textbook answers (a twisted shaft clamped at one end; a free body spun up by
// an external torque), and on the release of guide nodes, which must not create twist.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/feeder.hpp"
#include "engine/integrate/damping.hpp"
#include "engine/integrate/wire_mass.hpp"
#include "engine/rod/frames.hpp"
#include "engine/rod/material.hpp"
#include "engine/rod/twist.hpp"

namespace wirepack {
namespace {

// Straight wire on +z: nodes [0, n_free) free, then `guide` kinematic nodes, theta = 0.
State wire_with_guide(int n_free, int guide, double ell) {
  State s;
  const int n = n_free + guide;
  for (int i = 0; i < n; ++i) s.x.push_back(Vec3(0.0, 0.0, -i * ell));
  s.v.assign(n, Vec3::Zero());
  s.rest_length.assign(n - 1, ell);
  s.n_free = n_free;
  s.theta.assign(n - 1, 0.0);
  s.omega.assign(n - 1, 0.0);
  init_reference_frames(s, 0);
  return s;
}

// Held: the static twist under a tip torque T is a shaft clamped at the hole, theta_j =
// T (n_free - 1 - j) l / G J (n_free - 1 springs G J / l between the tip edge and the kinematic
// edge): every free edge is in balance and the wire passes T on to the guide. With a swivel the
// same state is not in balance: nothing holds the last free edge, which feels the full T. Tolerance
// 1e-12 relative: a straight wire has zero reference twist, the torques are sums of a few products.
TEST(FeederSpin, StaticTwistUnderATipTorqueNeedsTheHeldGuide) {
  const auto mat = RodMaterial::from(WireParams{});
  const double ell = 0.5e-3, T = 1e-6;  // [m], [N m]
  const int nf = 12;
  State s = wire_with_guide(nf, 3, ell);
  for (int j = 0; j + 1 < nf; ++j) s.theta[j] = T * (nf - 1 - j) * ell / mat.GJ();
  for (bool free : {false, true}) {
    SCOPED_TRACE(free ? "swivel" : "held");
    TwistTerm term(mat.GJ(), free);
    Forces f;
    f.reset(s);
    term.accumulate(s, f);
    f.torque[0] += T;  // the applied tip torque
    for (int j = 0; j + 1 < nf - 1; ++j) EXPECT_LT(std::abs(f.torque[j]), 1e-12 * T) << j;
    if (free) {
      EXPECT_NEAR(f.torque[nf - 2] / T, 1.0, 1e-12);
      EXPECT_EQ(f.torque[nf - 1], 0.0);
    } else {
      EXPECT_LT(std::abs(f.torque[nf - 2]), 1e-12 * T);
      EXPECT_NEAR(f.torque[nf - 1] / T, 1.0, 1e-12);  // passed on to the clamp
    }
  }
}

// Spin-up under a tip torque T, integrated (velocity Verlet on the angles, positions fixed) with
// the twist term, the twist dashpot and the selective twist mass as the simulation assembles
// them. The swivel transmits nothing to the guide: the free edges' angular momentum
// sum_j (M omega)_j = sum_j I_p omega_j (the Laplacian rows sum to zero without the joint) grows
// as T t, exactly up to round-off. Held, the guide takes the torque back: the momentum stays
// bounded by the shaft's oscillation, far below T t.
TEST(FeederSpin, ASwivelLetsTheTipTorqueSpinTheWholeWire) {
  const auto mat = RodMaterial::from(WireParams{});
  const double ell = 0.5e-3, T = 1e-7;
  const int nf = 20, ne_free = nf - 1;
  const double I_p = 1140.0 * mat.J * ell;  // physical spin inertia per edge [kg m^2]
  const double I_s = 1e4 * I_p;             // scaled (mode) inertia
  const double beta = 0.25 * (I_s - I_p);
  const double eta = 0.05 * std::sqrt(2.0 * mat.GJ() / ell * I_s);  // as engine/scene.cpp
  const double w_max = std::sqrt(4.0 * mat.GJ() / (ell * I_s));
  const double dt = 0.5 / w_max;
  const int steps = 4000;
  for (bool free : {false, true}) {
    SCOPED_TRACE(free ? "swivel" : "held");
    State s = wire_with_guide(nf, 3, ell);
    TwistTerm term(mat.GJ(), free);
    DampingParams dp;
    dp.eta_twist = eta;
    dp.twist_free_at_guide = free;
    RodDamping damping(dp);
    WireMass M(I_p, beta);
    M.factorise(ne_free, !free);
    std::vector<double> alpha;
    Forces f;
    auto accel = [&] {
      f.reset(s);
      term.accumulate(s, f);
      damping.add_forces(s, f);
      f.torque[0] += T;
      M.solve(f.torque, alpha);
    };
    accel();
    for (int k = 0; k < steps; ++k) {
      for (int j = 0; j < ne_free; ++j) s.omega[j] += 0.5 * dt * alpha[j];
      for (int j = 0; j < ne_free; ++j) s.theta[j] += dt * s.omega[j];
      accel();
      for (int j = 0; j < ne_free; ++j) s.omega[j] += 0.5 * dt * alpha[j];
    }
    double L = 0.0;  // sum_j (M omega)_j over the free edges [N m s]
    for (int j = 0; j < ne_free; ++j) L += I_p * s.omega[j];
    if (!free) L += beta * s.omega[ne_free - 1];  // the joint's Laplacian row, guide at rest
    const double Tt = T * steps * dt;
    if (free) {
      EXPECT_NEAR(L / Tt, 1.0, 1e-9);
      for (int j = ne_free; j < s.num_edges(); ++j) EXPECT_EQ(s.theta[j], 0.0);
    } else {
      EXPECT_LT(std::abs(L), 0.1 * Tt);
    }
  }
}

FeederParams feeder_params(bool spin_free) {
  FeederParams p;
  p.R = 10e-3;
  p.r = 0.5e-3;
  p.hole_radius = 0.51e-3;
  p.element_length = 0.5e-3;
  p.speed = 0.5;
  p.twist = true;
  p.spin_free = spin_free;
  return p;  // no deflection, no release noise: a straight wire on the axis
}

// Twist energy of the rod with the given boundary condition at the hole [J].
double twist_energy(const State& s, bool free) {
  const auto mat = RodMaterial::from(WireParams{});
  TwistTerm term(mat.GJ(), free);
  Forces f;
  f.reset(s);
  return term.accumulate(s, f);
}

// The wire has spun (a twist gradient along it, and a rigid spin on top). Feeding one element
// releases one guide node. With a swivel the edge that becomes free continues the spun wire
// (m = 0 at the new joint, same spin rate), so the twist energy is unchanged by the release (to
// round-off of the sums, 1e-12 relative); had it kept the kinematic angle 0, the new node would
// add G J (theta_{j-1})^2 / 2 l. Held, the freed edge keeps the clamp's angle 0 and rate 0: the
// twist against the clamp moves one node inward, again with the energy unchanged.
TEST(FeederSpin, ReleaseContinuesTheSpunWireWithASwivel) {
  for (bool free : {false, true}) {
    SCOPED_TRACE(free ? "swivel" : "held");
    Feeder feeder(feeder_params(free));
    State s = feeder.initial_state();
    const int nf0 = s.n_free;
    ASSERT_GE(nf0, 3);
    for (int j = 0; j + 1 < nf0; ++j) {
      s.theta[j] = 2.0 + 0.3 * j;
      s.omega[j] = 40.0;
    }
    const double U0 = twist_energy(s, free);
    // Feed one element: the whole wire moves up by l (a straight wire: frames unchanged).
    for (Vec3& x : s.x) x[2] += 0.5e-3;
    update_reference_frames(s);
    ASSERT_EQ(feeder.release(s), 1);
    ASSERT_EQ(s.n_free, nf0 + 1);
    const int j = nf0 - 1;  // the edge that became free
    const double U1 = twist_energy(s, free);
    if (free) {
      EXPECT_DOUBLE_EQ(s.theta[j], s.theta[j - 1] - s.ref_twist[j]);
      EXPECT_EQ(s.omega[j], s.omega[j - 1]);
      EXPECT_NEAR(U1, U0, 1e-12 * U0);
    } else {
      EXPECT_EQ(s.theta[j], 0.0);
      EXPECT_EQ(s.omega[j], 0.0);
      EXPECT_NEAR(U1, U0, 1e-12 * U0);
    }
  }
}

}  // namespace
}  // namespace wirepack
