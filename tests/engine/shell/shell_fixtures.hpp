#pragma once
// Shared by the shell and wire-shell tests: the paper's shell material, randomly perturbed
// states, a straight wire over a mesh.
#include <random>

#include "engine/shell/shell_term.hpp"
#include "engine/state.hpp"

namespace wirepack::testing {

// Paper shell: R = 10 mm, t = R / xi with xi = 10, E_s = E_w / eps with eps = 1e3, nu_s = 1/3.
inline ShellMaterial paper_material() {
  ShellMaterial m;
  m.E = 1e6;
  m.nu = 1.0 / 3.0;
  m.t = 1e-3;
  return m;
}

// x with every point moved by amplitude * (u, v, w), u, v, w uniform in [-1, 1] [m].
inline Vec3List perturbed(const Vec3List& x, double amplitude, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec3List y = x;
  for (Vec3& p : y) p += amplitude * Vec3(u(rng), u(rng), u(rng));
  return y;
}

// A straight wire of n nodes from a to b (all dynamic, at rest) over a shell mesh at rest.
inline State wire_over(const ShellMesh& mesh, const Vec3& a, const Vec3& b, int n) {
  State s;
  for (int i = 0; i < n; ++i) s.x.push_back(a + (b - a) * (double(i) / (n - 1)));
  s.v.assign(n, Vec3::Zero());
  for (int j = 0; j + 1 < n; ++j) s.rest_length.push_back((s.x[j + 1] - s.x[j]).norm());
  s.n_free = n;
  s.shell_x = mesh.rest;
  s.shell_v.assign(mesh.rest.size(), Vec3::Zero());
  return s;
}

}  // namespace wirepack::testing
