// Engine V, threads inside one run: the parallel assembly of the shell terms gives bitwise the
// sums of the serial loops it replaces, whatever the thread count; a whole elastic run with
// friction is bitwise the same on 1 and 2 threads.
#include <gtest/gtest.h>

#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>

#include "engine/elastic_runs.hpp"
#include "engine/shell/bending.hpp"
#include "engine/shell/membrane.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/scatter_plan.hpp"
#include "engine/shell/shell_fixtures.hpp"
#include "engine/simulation.hpp"

namespace wirepack {
namespace {

using testing::paper_material;
using testing::perturbed;

// Runs f with n OpenMP threads, restoring the setting after.
template <class F>
void with_threads(int n, F&& f) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(n);
  f();
  omp_set_num_threads(saved);
}

bool bitwise_equal(const Vec3List& a, const Vec3List& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (std::memcmp(&a[i][k], &b[i][k], sizeof(double)) != 0) return false;
    }
  }
  return true;
}

// Random slots (some without a target) and values over 12 orders of magnitude, where the
// order of the additions shows in the last bits.
TEST(ScatterPlan, GathersInTheSerialLoopsOrderBitwise) {
  std::mt19937_64 rng(7);
  const int width = 4, elements = 3000, n_targets = 500;
  std::uniform_int_distribution<int> target(-1, n_targets - 1);
  std::uniform_real_distribution<double> u(-1.0, 1.0), e(-6.0, 6.0);
  std::vector<int> targets(width * elements);
  Vec3List values(targets.size());
  for (size_t s = 0; s < targets.size(); ++s) {
    targets[s] = target(rng);
    values[s] = std::pow(10.0, e(rng)) * Vec3(u(rng), u(rng), u(rng));
  }
  Vec3List serial(n_targets);
  for (auto& v : serial) v = Vec3(u(rng), u(rng), u(rng));
  const Vec3List start = serial;
  for (size_t s = 0; s < targets.size(); ++s) {
    if (targets[s] >= 0) serial[targets[s]] += values[s];
  }
  const ScatterPlan plan(targets, width, n_targets);
  EXPECT_EQ(plan.elements(), elements);
  for (int threads : {1, 2, 3}) {
    Vec3List out = start;
    with_threads(threads, [&] { plan.gather_add(values, out); });
    EXPECT_TRUE(bitwise_equal(out, serial)) << threads << " threads";
  }
  // gather_set starts from zero.
  Vec3List zero_start(n_targets, Vec3::Zero()), set(n_targets, Vec3::Ones());
  for (size_t s = 0; s < targets.size(); ++s) {
    if (targets[s] >= 0) zero_start[targets[s]] += values[s];
  }
  plan.gather_set(values, set);
  EXPECT_TRUE(bitwise_equal(set, zero_start));
  EXPECT_THROW(ScatterPlan({0, 1, 2}, 2, 3), std::invalid_argument);
  EXPECT_THROW(ScatterPlan({0, 5}, 2, 3), std::invalid_argument);
}

// The membrane's serial loop as it was before the parallel assembly (paper Eqs. (2)-(3)).
double membrane_serial(const ShellMesh& mesh, const ShellMaterial& m, const Vec3List& x,
                       Vec3List& f) {
  const double M = m.M(), nu = m.nu;
  double U = 0.0;
  for (const auto& v : mesh.faces) {
    const Vec3 r1 = mesh.rest[v[1]] - mesh.rest[v[0]], r2 = mesh.rest[v[2]] - mesh.rest[v[0]];
    Eigen::Matrix2d abar;
    abar << r1.dot(r1), r1.dot(r2), r1.dot(r2), r2.dot(r2);
    const Eigen::Matrix2d ai = abar.inverse();
    const double area = 0.5 * std::sqrt(abar.determinant());
    const Vec3 e1 = x[v[1]] - x[v[0]], e2 = x[v[2]] - x[v[0]];
    const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
    Eigen::Matrix2d alpha;
    alpha << a11 - abar(0, 0), a12 - abar(0, 1), a12 - abar(1, 0), a22 - abar(1, 1);
    alpha *= 0.5;
    const Eigen::Matrix2d A = ai * alpha;
    const double tr = A.trace();
    U += 0.5 * M * area * (nu * tr * tr + (1.0 - nu) * (A * A).trace());
    const Eigen::Matrix2d S = M * area * (nu * tr * ai + (1.0 - nu) * A * ai);
    const Vec3 g1 = S(0, 0) * e1 + S(0, 1) * e2;
    const Vec3 g2 = S(1, 0) * e1 + S(1, 1) * e2;
    f[v[0]] += g1 + g2;
    f[v[1]] -= g1;
    f[v[2]] -= g2;
  }
  return U;
}

TEST(ParallelAssembly, MembraneIsBitwiseTheSerialLoopOnAnyThreadCount) {
  const ShellMesh mesh = sphere_with_hole(10e-3, 1e-3, 0.6e-3, 1e-3);
  const ShellMaterial mat = paper_material();
  const Vec3List x = perturbed(mesh.rest, 0.2e-3, 3);
  // Forces added onto what the terms before it left (not zero).
  const Vec3List f0 = perturbed(Vec3List(x.size(), Vec3::Zero()), 1e-3, 4);
  Vec3List f_ref = f0;
  const double U_ref = membrane_serial(mesh, mat, x, f_ref);
  for (int threads : {1, 2}) {
    MembraneTerm term(mesh, mat);
    Vec3List f = f0;
    double U = 0.0;
    with_threads(threads, [&] { U = term.accumulate(x, f); });
    EXPECT_EQ(std::memcmp(&U, &U_ref, sizeof U), 0) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(f, f_ref)) << threads << " threads";
  }
}

// Bending: forces on 1, 2 and 3 threads bitwise equal; the energy is bitwise the serial sum of
// energy(), which still loops over the faces serially.
TEST(ParallelAssembly, BendingIsBitwiseTheSameOnAnyThreadCount) {
  const ShellMesh mesh = sphere_with_hole(10e-3, 1e-3, 0.6e-3, 1e-3);
  const ShellMaterial mat = paper_material();
  const Vec3List x = perturbed(mesh.rest, 0.2e-3, 5);
  const Vec3List f0 = perturbed(Vec3List(x.size(), Vec3::Zero()), 1e-3, 6);
  BendingTerm serial(mesh, mat);
  const double U_energy = serial.energy(x);
  Vec3List f1 = f0;
  double U1 = 0.0;
  with_threads(1, [&] { U1 = serial.accumulate(x, f1); });
  EXPECT_EQ(std::memcmp(&U1, &U_energy, sizeof U1), 0);
  for (int threads : {2, 3}) {
    BendingTerm term(mesh, mat);
    Vec3List f = f0;
    double U = 0.0;
    with_threads(threads, [&] { U = term.accumulate(x, f); });
    EXPECT_EQ(std::memcmp(&U, &U1, sizeof U), 0) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(f, f1)) << threads << " threads";
  }
}

// Steps `one` on 1 thread and `two` on 2 in lockstep to the end: every step's time, and at the
// end the step count, energies, contact count, wire nodes and shell vertices bitwise equal.
void expect_the_same_on_one_and_two_threads(Simulation& one, Simulation& two) {
  one.set_threads(1);
  two.set_threads(2);
  while (!one.finished()) {
    one.step();
    two.step();
    ASSERT_EQ(one.time(), two.time()) << "step " << one.steps();
  }
  ASSERT_EQ(one.steps(), two.steps());
  EXPECT_EQ(one.wire_contacts(), two.wire_contacts());
  const Energies a = one.energies(), b = two.energies();
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  const auto xa = one.all_nodes(), xb = two.all_nodes();
  EXPECT_TRUE(bitwise_equal(Vec3List(xa.begin(), xa.end()), Vec3List(xb.begin(), xb.end())));
  const auto sa = one.shell_vertices(), sb = two.shell_vertices();
  EXPECT_TRUE(bitwise_equal(Vec3List(sa.begin(), sa.end()), Vec3List(sb.begin(), sb.end())));
}

// A whole elastic run with friction and twist, shell contact and self-contact on (rho = 10,
// coarse elements, to l = 2: the wire touches the shell from l ~ 1.3): every state bitwise the
// same on 1 and 2 threads.
TEST(ParallelAssembly, ElasticRunIsBitwiseTheSameOnOneAndTwoThreads) {
  SceneParams p = testing::elastic_scene(10, 10, 1e3, 0.5, 2.0);
  p.numerics.element_length = 2 * p.wire.radius;
  p.numerics.shell_mesh_size = 2 * p.wire.radius;
  p.numerics.shell_self_contact = EffectMode::On;
  Simulation one(p), two(p);
  expect_the_same_on_one_and_two_threads(one, two);
}

// The wire's own loops on two threads: the rigid sphere (rho = 10) with wire-wall and wire-wire
// friction and twist, where the wire touches itself (from l ~ 9): run on one thread to l = 8.8,
// then on one and on two to l = 10, every step's time and at the end every node, energy and
// contact count bitwise the same. (The other tests run one thread unless they ask: ctest sets
// OMP_NUM_THREADS=1 and a passive wait, with which two threads on this small wire cost ~300 us
// per step, hence the short stretch.)
TEST(ParallelAssembly, RigidFrictionRunIsBitwiseTheSameOnOneAndTwoThreads) {
  SceneParams p;
  p.shell = ShellKind::Rigid;
  p.rho = 10;
  p.mu_s = 0.3;
  p.mu_d = 0.27;
  p.l_max = 10;
  p.numerics.twist = EffectMode::On;
  Simulation one(p), two(p);
  one.advance_to(8.8);
  two.advance_to(8.8);
  expect_the_same_on_one_and_two_threads(one, two);
  EXPECT_GT(one.wire_contacts(), 0) << "the wire never touched itself";
}

// The threads of this process (Linux: one entry per thread in /proc/self/task).
int process_threads() {
  int n = 0;
  for ([[maybe_unused]] const auto& t : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

// A run set to one thread uses one, also where the caller allows more: building the simulation,
// its steps and the recorder's energy evaluations between steps start no OpenMP team (they
// did: a --threads 1 run kept a second thread spinning, and each run of a sweep started nested
// teams of all the machine's threads for its recorder). In a fresh process (gtest re-executes
// the binary for the death test), where no team has run yet.
TEST(ParallelAssembly, ARunOnOneThreadStartsNoOtherThread) {
  ::testing::GTEST_FLAG(death_test_style) = "threadsafe";
  EXPECT_EXIT(
      {
        // Threads the process had before (a sanitizer may keep one of its own).
        const int before = process_threads();
        omp_set_num_threads(4);  // what the caller allows
        SceneParams p = testing::elastic_scene(10, 10, 1e3, 0.5, 1.4);
        p.numerics.element_length = 2 * p.wire.radius;
        p.numerics.shell_mesh_size = 2 * p.wire.radius;
        Simulation sim(p);
        sim.set_threads(1);
        while (!sim.finished()) sim.step();
        const Energies e = sim.energies();
        std::fprintf(stderr, "threads %d more U_m %g\n", process_threads() - before, e.U_m);
        std::exit(process_threads() == before && sim.steps() > 0 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "threads 0 more");
}

}  // namespace
}  // namespace wirepack
