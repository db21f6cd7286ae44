#pragma once
// Builders of simple rod states for the analytic tests of the rod energies and contacts
// (straight rods, circular arcs, helices, polylines through waypoints), small force
// helpers, and a dynamic-relaxation driver (damped dynamics to static equilibrium) built on
// the engine's PredictorCorrector. Header-only, namespace wirepack::testing like the FD harness.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "engine/integrate/predictor_corrector.hpp"
#include "engine/rod/bend.hpp"
#include "engine/rod/frames.hpp"
#include "engine/rod/material.hpp"
#include "engine/rod/stretch.hpp"
#include "engine/term.hpp"

namespace wirepack::testing {

// Default wire (r = 0.5 mm, E = 1 GPa, nu = 1/3) as a section/material.
inline RodMaterial default_material() {
  return RodMaterial::from(WireParams{});
}

// Rod through the given node positions, at rest: zero velocities, rest lengths equal to the
// current edge lengths (so it is stress free in stretching), every node dynamic. With
// `twist`, theta = 0 and reference frames by space-parallel transport from edge 0
// (reference twist 0).
inline State rod_through(const Vec3List& x, bool twist = false) {
  State s;
  s.x = x;
  const int n = static_cast<int>(x.size());
  s.v.assign(n, Vec3::Zero());
  for (int j = 0; j + 1 < n; ++j) s.rest_length.push_back((x[j + 1] - x[j]).norm());
  s.n_free = n;
  if (twist) {
    s.theta.assign(n - 1, 0.0);
    s.omega.assign(n - 1, 0.0);
    init_reference_frames(s, 0);
  }
  return s;
}

// Straight rod of n nodes spaced ell along the unit direction dir, starting at origin.
inline State straight_rod(int n, double ell, const Vec3& dir = Vec3::UnitX(), bool twist = false,
                          const Vec3& origin = Vec3::Zero()) {
  Vec3List x;
  for (int i = 0; i < n; ++i) x.push_back(origin + (i * ell) * dir);
  return rod_through(x, twist);
}

// Nodes on the circle of radius a in the xy plane centred at the origin, at polar angles
// k * dphi for k = 0 .. n - 1 (so edges are chords 2 a sin(dphi / 2)).
inline Vec3List arc_points(double a, double dphi, int n) {
  Vec3List x;
  for (int k = 0; k < n; ++k) x.emplace_back(a * std::cos(k * dphi), a * std::sin(k * dphi), 0.0);
  return x;
}

// Helix of radius a and pitch 2 pi c about z: node k at polar angle k * dphi.
inline Vec3List helix_points(double a, double c, double dphi, int n) {
  Vec3List x;
  for (int k = 0; k < n; ++k) {
    const double p = k * dphi;
    x.emplace_back(a * std::cos(p), a * std::sin(p), c * p);
  }
  return x;
}

// Polyline through the waypoints, each leg split into ceil(|leg| / max_len) equal edges.
inline Vec3List polyline(const Vec3List& waypoints, double max_len) {
  Vec3List x{waypoints.front()};
  for (size_t k = 1; k < waypoints.size(); ++k) {
    const Vec3 a = waypoints[k - 1], b = waypoints[k];
    const int m = std::max(1, static_cast<int>(std::ceil((b - a).norm() / max_len - 1e-9)));
    for (int i = 1; i <= m; ++i) x.push_back(a + (static_cast<double>(i) / m) * (b - a));
  }
  return x;
}

// Generalised forces of one term at a state (fresh accumulator).
inline Forces forces_of(Term& term, const State& s, double* energy = nullptr) {
  Forces f;
  f.reset(s);
  const double U = term.accumulate(s, f);
  if (energy) *energy = U;
  return f;
}

inline Vec3 sum_of(const Vec3List& f) {
  Vec3 t = Vec3::Zero();
  for (const Vec3& v : f) t += v;
  return t;
}

// Total moment about the origin of the nodal forces plus the material torques about the
// edge tangents: sum_i x_i x f_i + sum_j tau_j t_j. Zero for any energy invariant under rigid
// rotations (with theta following the material frame, see test_twist.cpp) [N m].
inline Vec3 moment_of(const State& s, const Forces& f) {
  Vec3 m = Vec3::Zero();
  for (int i = 0; i < s.num_nodes(); ++i) m += s.x[i].cross(f.f[i]);
  for (size_t j = 0; j < f.torque.size(); ++j) {
    m += f.torque[j] * (s.x[j + 1] - s.x[j]).normalized();
  }
  return m;
}

// ------------------------------------------------------------------------------------------
// Dynamic relaxation: the rod's terms plus test-specific loads, an isotropic viscous drag
// -c v on every node and kinematic constraints, integrated by the engine's predictor-corrector
// until the static residual (forces without the drag, after the constraints) is small. This is
// honest physics: the end state is a static equilibrium of the energies under the loads.
struct Relaxation {
  std::vector<Term*> terms;
  double node_mass = 0;  // lumped node mass [kg]
  double drag = 0;       // c = gamma m per node [N s/m]
  // Extra loads (external forces) added into the forces at a state.
  std::function<void(const State&, Forces&)> load = [](const State&, Forces&) {};
  // Zeroes the constrained components of node i's acceleration (guide nodes i >= n_free are
  // always held).
  std::function<void(int, Vec3&)> constrain = [](int, Vec3&) {};

  Forces f;             // scratch
  double residual = 0;  // largest static force component on a dynamic DOF at the last eval [N]
  double t = 0;         // simulated time [s]
  long steps = 0;       // accepted steps

  // Accelerations for the predictor-corrector; the residual excludes the drag.
  double evaluate(State& s, Vec3List& a, std::vector<double>& alpha, Vec3List&) {
    f.reset(s);
    double omega2 = 0;
    for (Term* term : terms) {
      term->accumulate(s, f);
      omega2 += term->omega_max_sq(RodInertia{node_mass, 0.0});
    }
    load(s, f);
    a.assign(s.x.size(), Vec3::Zero());
    residual = 0;
    for (int i = 0; i < s.n_free; ++i) {
      Vec3 fs = f.f[i];
      constrain(i, fs);
      residual = std::max(residual, fs.cwiseAbs().maxCoeff());
      a[i] = (f.f[i] - drag * s.v[i]) / node_mass;
      constrain(i, a[i]);
    }
    alpha.assign(s.theta.size(), 0.0);
    return omega2;
  }

  // Integrates until `done(state)` returns true (checked every `every` steps) or the time
  // exceeds t_max [s]. tolerance: local position error per step [m]. Returns true if done.
  bool run(State& s, double tolerance, double t_max, const std::function<bool(const State&)>& done,
           int every = 100) {
    StepControl c;
    c.tolerance = tolerance;
    c.damping_ratio = 0.0;  // the drag damps the fastest modes only weakly
    c.dt_floor = 1e-15;
    PredictorCorrector pc(c, 1.0);
    auto eval = [this](State& st, Vec3List& a, std::vector<double>& al, Vec3List& sa) {
      return evaluate(st, a, al, sa);
    };
    auto moved = [](State&) {};
    pc.initialise(s, eval, moved);
    while (t < t_max) {
      t += pc.step(s, eval, moved);
      ++steps;
      if (steps % every == 0 && done(s)) return true;
    }
    return done(s);
  }
};

// ------------------------------------------------------------------------------------------
// Pinned-pinned column for the Euler buckling tests: N edges of rest length l = L / N along +x,
// StretchTerm + BendTerm, a dead axial load P at node 0 pushing towards node N (+x). Node N is
// a guide node (fixed pin), node 0 slides along x only (roller: its transverse acceleration is
// zeroed). The straight state is pre-compressed to the equilibrium strain -P / E A and given the
// imperfection y_k = A0 sin(pi k / N), the exact first eigenvector of the linearised discrete
// problem (the sine modes diagonalise the second differences with y_0 = y_N = 0), so only that
// mode is excited. Mass per length from the default wire density, drag gamma = zeta_1 * 2
// omega_1 per unit mass (omega_1 the first bending frequency of the unloaded column).
struct PinnedColumn {
  RodMaterial mat = default_material();
  int N = 40;         // edges
  double L = 0;       // length [m]
  double l = 0;       // rest edge length [m]
  double P_c = 0;     // continuum Euler load pi^2 E I / L^2 [N]
  double omega1 = 0;  // (pi / L)^2 sqrt(E I / mu) [1/s]
  double gamma = 0;   // drag rate c / m [1/s]
  StretchTerm stretch{mat.EA()};
  BendTerm bend{mat.EI()};
  State s;
  Relaxation relax;

  PinnedColumn(int n_edges, double length, double zeta1) {
    N = n_edges;
    L = length;
    l = L / N;
    P_c = M_PI * M_PI * mat.EI() / (L * L);
    const double mu = WireParams{}.density * mat.A;
    omega1 = (M_PI / L) * (M_PI / L) * std::sqrt(mat.EI() / mu);
    gamma = 2.0 * zeta1 * omega1;
    relax.terms = {&stretch, &bend};
    relax.node_mass = mu * l;
    relax.drag = gamma * relax.node_mass;
    relax.constrain = [](int i, Vec3& a) {
      if (i == 0) a[1] = a[2] = 0.0;
    };
  }

  // Resets the state for load P [N] and imperfection amplitude A0 [m].
  void reset(double P, double A0) {
    Vec3List x;
    const double shrink = 1.0 - P / mat.EA();
    for (int k = 0; k <= N; ++k) {
      x.emplace_back(k * l * shrink, A0 * std::sin(M_PI * k / N), 0.0);
    }
    s = rod_through(x);
    s.rest_length.assign(N, l);
    s.n_free = N;  // node N is the fixed pin
    relax.load = [P](const State&, Forces& f) { f.f[0][0] += P; };
    relax.t = 0;
    relax.steps = 0;
  }

  // Amplitude of the first buckling mode: projection of y on sin(pi k / N) [m].
  double mode_amplitude() const {
    double q = 0;
    for (int k = 1; k < N; ++k) q += s.x[k][1] * std::sin(M_PI * k / N);
    return 2.0 * q / N;
  }
  double max_deflection() const {
    double d = 0;
    for (const Vec3& p : s.x) d = std::max(d, std::abs(p[1]));
    return d;
  }
};

}  // namespace wirepack::testing
