// Full-size elastic-shell hard cases (label "slow", not in CI): rho = 20 with the default
// numerics, to l = 5 (past the head-on contact at l ~ 2 and the first loops). Same checks as
// test_simulation_elastic.cpp: no NaN, every released node inside the deformed shell (the
// run checks it with the winding number), bounded energy.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/elastic_runs.hpp"

namespace wirepack {
namespace {

using testing::run_and_check;

SceneParams full_scene(double xi, double eps, double mu_s) {
  return testing::elastic_scene(20, xi, eps, mu_s, 5);
}

TEST(ElasticSimulationFullSize, SoftThinShellStrongFriction) {
  run_and_check(full_scene(200, 1e4, 1.0));
}
TEST(ElasticSimulationFullSize, StiffThickShell) {
  run_and_check(full_scene(10, 1, 0));
}
TEST(ElasticSimulationFullSize, HeadOnIntoAVerySoftShell) {
  run_and_check(full_scene(10, 1e4, 0));
}

}  // namespace
}  // namespace wirepack
