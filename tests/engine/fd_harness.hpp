#pragma once
// One finite-difference harness for every energy term and every DOF type (docs/design.md §6.5):
// wire node positions, twist angles and shell vertex positions. It compares the generalised
// forces from Term::accumulate (or ShellTerm::accumulate) with central differences of the energy
// over several step sizes, so a test sees the error trend (O(h^2) until round-off) and not one
// lucky number.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "engine/rod/frames.hpp"
#include "engine/shell/shell_term.hpp"
#include "engine/term.hpp"

namespace wirepack::testing {

struct FdReport {
  std::vector<double> h;    // step sizes, as fractions of the length scale
  std::vector<double> err;  // max |F + dU/dq| / max |F| at each step size
  double best() const { return *std::min_element(err.begin(), err.end()); }
};

namespace fd_detail {

// Largest |component| of a force list.
inline double max_abs(const Vec3List& f) {
  double m = 0.0;
  for (const auto& v : f) m = std::max(m, v.cwiseAbs().maxCoeff());
  return m;
}

// max over the coordinates of points[i] of |force[i][k] + dU/dx|, dU/dx by central differences
// with step h, each coordinate moved in place and restored; `energy()` reads the moved state.
template <class Energy>
double max_point_error(Vec3List& points, const Vec3List& force, double h, Energy&& energy) {
  double err = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double keep = points[i][k];
      points[i][k] = keep + h;
      const double up = energy();
      points[i][k] = keep - h;
      const double dn = energy();
      points[i][k] = keep;
      err = std::max(err, std::abs(force[i][k] + (up - dn) / (2 * h)));
    }
  }
  return err;
}

}  // namespace fd_detail

// Random, generic rod: n nodes, edges of length ~ ell with random directions (a crumpled
// curve with moderate turning angles), rest lengths perturbed by a few percent, random theta.
inline State random_rod(int n, double ell, bool twist, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  State s;
  s.x.push_back(Vec3::Zero());
  Vec3 dir(0, 0, 1);
  for (int i = 1; i < n; ++i) {
    dir = (dir + 0.6 * Vec3(g(rng), g(rng), g(rng))).normalized();
    s.x.push_back(s.x.back() + ell * (1.0 + 0.1 * u(rng)) * dir);
  }
  s.v.assign(n, Vec3::Zero());
  for (int j = 0; j + 1 < n; ++j) s.rest_length.push_back(ell * (1.0 + 0.05 * u(rng)));
  s.n_free = n;
  if (twist) {
    s.theta.resize(n - 1);
    s.omega.assign(n - 1, 0.0);
    for (auto& t : s.theta) t = 0.5 * u(rng);
    init_reference_frames(s, 0);
    // Give the reference frames a random twist history, then make them current.
    for (int j = 0; j + 1 < n; ++j) {
      const Vec3 t = s.ref_tangent[j];
      const double a = 0.7 * u(rng);
      const Vec3 d1 = s.ref1[j];
      s.ref1[j] = std::cos(a) * d1 + std::sin(a) * t.cross(d1);
    }
    std::fill(s.ref_twist.begin(), s.ref_twist.end(), 0.0);
    update_reference_frames(s);
  }
  return s;
}

// Central differences of term.energy in every coordinate of every wire node, every theta (when
// the state has twist) and every shell vertex (when it has an elastic shell), at steps
// h * length_scale (angles: h rad) for each h in `steps`. Torques enter as torque / length_scale.
inline FdReport fd_check(Term& term, const State& s0, double length_scale,
                         const std::vector<double>& steps) {
  State s = s0;
  Forces f;
  f.reset(s);
  term.accumulate(s, f);
  double fmax = 0.0;
  for (const auto& v : f.f) fmax = std::max(fmax, v.cwiseAbs().maxCoeff());
  for (double t : f.torque) fmax = std::max(fmax, std::abs(t) / length_scale);
  fmax = std::max({fmax, fd_detail::max_abs(f.shell_f), 1e-300});
  FdReport rep;
  for (double hrel : steps) {
    const double h = hrel * length_scale;
    double err = 0.0;
    for (int i = 0; i < s.num_nodes(); ++i) {
      for (int k = 0; k < 3; ++k) {
        State p = s0, m = s0;
        p.x[i][k] += h;
        m.x[i][k] -= h;
        const double dU = (term.energy(p) - term.energy(m)) / (2 * h);
        err = std::max(err, std::abs(f.f[i][k] + dU));
      }
    }
    const double ha = hrel;  // angle step [rad]
    for (size_t j = 0; j < s.theta.size(); ++j) {
      State p = s0, m = s0;
      p.theta[j] += ha;
      m.theta[j] -= ha;
      const double dU = (term.energy(p) - term.energy(m)) / (2 * ha);
      err = std::max(err, std::abs(f.torque[j] + dU) / length_scale);
    }
    State q = s0;
    err = std::max(
        err, fd_detail::max_point_error(q.shell_x, f.shell_f, h, [&] { return term.energy(q); }));
    rep.h.push_back(hrel);
    rep.err.push_back(err / fmax);
  }
  return rep;
}

// The same for a shell term alone (engine/shell/shell_term.hpp): every coordinate of every
// vertex of x0, steps h * length_scale.
inline FdReport fd_check(ShellTerm& term, const Vec3List& x0, double length_scale,
                         const std::vector<double>& steps) {
  Vec3List f(x0.size(), Vec3::Zero());
  term.accumulate(x0, f);
  const double fmax = std::max(fd_detail::max_abs(f), 1e-300);
  FdReport rep;
  Vec3List x = x0;
  for (double hrel : steps) {
    const double err =
        fd_detail::max_point_error(x, f, hrel * length_scale, [&] { return term.energy(x); });
    rep.h.push_back(hrel);
    rep.err.push_back(err / fmax);
  }
  return rep;
}

// Logs the error ladder, so a failing (or suspiciously perfect) check shows its trend.
inline void print_report(const FdReport& r) {
  std::printf("  fd:");
  for (size_t k = 0; k < r.h.size(); ++k) std::printf(" h=%.0e:%.2e", r.h[k], r.err[k]);
  std::printf("\n");
}

// Logs the observed orders log10(err_k / err_k+1) between successive steps.
inline void print_orders(const FdReport& r) {
  std::printf("  orders:");
  for (size_t k = 0; k + 1 < r.err.size(); ++k)
    std::printf(" %.2f", std::log10(r.err[k] / r.err[k + 1]));
  std::printf("\n");
}

inline std::vector<double> default_fd_steps() {
  return {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
}

}  // namespace wirepack::testing
