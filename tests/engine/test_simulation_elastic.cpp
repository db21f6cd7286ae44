// Whole runs with the elastic shell (Engine III): the hard cases of the issue at a reduced
// size that fits the test suite (rho = 10, coarse elements; the full-size runs are in
// slow_simulation_elastic.cpp): no NaN, every released node inside the deformed shell (the
// run itself checks it with the winding number and fails otherwise), bounded energy.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/elastic_runs.hpp"
#include "engine/scene.hpp"

namespace wirepack {
namespace {

using testing::run_and_check;

SceneParams elastic_scene(double xi, double eps, double mu_s, double l_max) {
  SceneParams p = testing::elastic_scene(10, xi, eps, mu_s, l_max);
  p.numerics.element_length = 2 * p.wire.radius;
  p.numerics.shell_mesh_size = 2 * p.wire.radius;
  return p;
}

TEST(ElasticSimulation, StiffThickShellHeadOn) {
  run_and_check(elastic_scene(10, 1, 0, 3));
}

TEST(ElasticSimulation, VerySoftThinShellWithStrongFriction) {
  run_and_check(elastic_scene(200, 1e4, 1.0, 3));
}

TEST(ElasticSimulation, HeadOnTipIntoAVerySoftShell) {
  run_and_check(elastic_scene(10, 1e4, 0, 3));
}

// Effects on demand: an elastic frictional scene assembles every term, and each switch
// that is off removes its term.
TEST(ElasticSimulation, SceneAssemblesShellTermsAndNoWall) {
  SceneParams p = elastic_scene(10, 1000, 0.5, 1);
  Simulation sim(p);
  EXPECT_EQ(sim.term_names(),
            (std::vector<std::string>{"stretch", "bend", "twist", "membrane", "shell_bending",
                                      "wire_shell", "shell_self", "self_contact", "friction"}));
  EXPECT_FALSE(sim.shell_vertices().empty());
  EXPECT_FALSE(sim.shell_triangles().empty());
  p.numerics.shell_self_contact = EffectMode::Off;
  p.numerics.twist = EffectMode::Off;
  EXPECT_EQ(Simulation(p).term_names(),
            (std::vector<std::string>{"stretch", "bend", "membrane", "shell_bending", "wire_shell",
                                      "self_contact", "friction"}));
  p.mu_s = p.mu_d = 0;
  p.numerics.twist = EffectMode::Auto;
  EXPECT_EQ(Simulation(p).term_names(),
            (std::vector<std::string>{"stretch", "bend", "membrane", "shell_bending", "wire_shell",
                                      "self_contact"}));
}

// The stick stiffness reaches the contacts: Mindlin's 2 (1 - nu) / (2 - nu) = 0.8 at the
// default nu_w = 1/3 unless the scene sets friction_stiffness_ratio.
TEST(ElasticSimulation, FrictionStiffnessRatioIsMindlinsUnlessSet) {
  SceneParams p = elastic_scene(10, 1000, 0.5, 1);
  EXPECT_NEAR(assemble(p).wire_shell_params.friction.stiffness_ratio, 0.8, 1e-15);
  p.wire.poisson_ratio = 0.25;
  EXPECT_NEAR(assemble(p).wire_shell_params.friction.stiffness_ratio, 1.5 / 1.75, 1e-15);
  p.friction_stiffness_ratio = 0.2;
  EXPECT_EQ(assemble(p).wire_shell_params.friction.stiffness_ratio, 0.2);
}

}  // namespace
}  // namespace wirepack
