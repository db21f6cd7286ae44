#pragma once
// Shared by the shell tests: the paper's shell material and randomly perturbed states.
#include <random>

#include "engine/shell/shell_term.hpp"

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

}  // namespace wirepack::testing
