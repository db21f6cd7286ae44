// Checkpoints of a simulation (docs/design.md §4.8): a Simulation restored from the bytes of
// another continues bitwise as that one does (every node, shell vertex, step size and energy,
// step by step), for each kind of state a scene carries: wire-wall and wire-wire friction
// springs, twist angles and reference frames, the wire-shell and shell-shell contact lists.
// Bytes of another scene, or cut short, are refused with a reason.
#include <gtest/gtest.h>

#include <string>

#include "engine/simulation.hpp"
#include "engine/state_archive.hpp"
#include "sanitizers.hpp"

namespace wirepack {
namespace {

SceneParams rigid_friction_twist() {
  SceneParams p;
  p.rho = 5;
  p.mu_s = 0.5;
  p.mu_d = 0.5;
  p.l_max = 12.8;
  p.numerics.twist = EffectMode::On;
  p.numerics.element_length = p.wire.radius;
  return p;
}

SceneParams elastic_friction_folds() {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = 10;
  p.xi = 10;
  p.eps = 1000;
  p.mu_s = 0.5;
  p.mu_d = 0.5;
  p.l_max = 3.3;
  p.numerics.element_length = 2 * p.wire.radius;
  p.numerics.shell_mesh_size = 2 * p.wire.radius;
  p.numerics.shell_self_contact = EffectMode::On;
  return p;
}

// Runs `p` to l_save, restores a second Simulation from its state and steps both to l_max,
// comparing them after every step; `compared`: the number of steps compared.
void expect_bitwise_continuation(const SceneParams& p, double l_save, int threads_after,
                                 long& compared, int& contacts_at_save) {
  Simulation original(p);
  original.advance_to(l_save);
  contacts_at_save = original.wire_contacts();
  const std::string bytes = original.save_state();
  Simulation resumed(p);
  resumed.restore_state(bytes);
  resumed.set_threads(threads_after);
  // What was restored is what was saved.
  EXPECT_TRUE(resumed.save_state() == bytes) << "the restored state saves other bytes";
  EXPECT_EQ(resumed.steps(), original.steps());
  EXPECT_EQ(resumed.l(), original.l());
  compared = 0;
  while (!original.finished()) {
    original.step();
    resumed.step();
    ++compared;
    ASSERT_EQ(resumed.time(), original.time()) << "step " << original.steps();
    ASSERT_EQ(resumed.dt(), original.dt()) << "step " << original.steps();
    const auto a = original.all_nodes(), b = resumed.all_nodes();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      ASSERT_EQ(a[i], b[i]) << "node " << i << ", step " << original.steps();
    const auto sa = original.shell_vertices(), sb = resumed.shell_vertices();
    for (std::size_t v = 0; v < sa.size(); ++v)
      ASSERT_EQ(sa[v], sb[v]) << "vertex " << v << ", step " << original.steps();
    const Energies ea = original.energies(), eb = resumed.energies();
    ASSERT_EQ(ea.U_b, eb.U_b);
    ASSERT_EQ(ea.U_contact, eb.U_contact);
    ASSERT_EQ(ea.E_kin, eb.E_kin);
    ASSERT_EQ(original.feeder_work(), resumed.feeder_work());
    ASSERT_EQ(original.wire_contacts(), resumed.wire_contacts());
  }
  EXPECT_EQ(resumed.rejected_steps(), original.rejected_steps());
}

// The rigid sphere with friction and twist, saved while the wire slides on the wall and on
// itself (friction springs of both contact types, released nodes drawn from the feeder's
// random stream after the restore). The wire first touches itself at l ~ 12 (12 s in Release);
// under the sanitizers the state is saved at l = 4, on the wall alone, and compared to 4.4.
TEST(Checkpoint, RigidFrictionTwistContinuesBitwise) {
  SceneParams p = rigid_friction_twist();
  const double l_save = testing::kUnderSanitizers ? 4.0 : 12.0;
  p.l_max = l_save + (testing::kUnderSanitizers ? 0.4 : 0.8);
  long n = 0;
  int contacts = 0;
  expect_bitwise_continuation(p, l_save, 1, n, contacts);
  if (!testing::kUnderSanitizers) {
    EXPECT_GT(contacts, 0) << "no self-contact at the save point";
  }
  EXPECT_GT(n, 1000);
}

// The elastic shell with friction and its own contact on: the wire-shell lists, the shell's
// vertices and velocities; resumed on 2 threads (the result does not depend on them).
TEST(Checkpoint, ElasticShellContinuesBitwiseOnOtherThreads) {
  const SceneParams p = elastic_friction_folds();
  long n = 0;
  int contacts = 0;
  expect_bitwise_continuation(p, 2.6, 2, n, contacts);
  EXPECT_GT(n, 500);
}

// A state saved at l = 0 (before any contact) continues too.
TEST(Checkpoint, SavedAtTheStart) {
  SceneParams p = rigid_friction_twist();
  p.l_max = 1.5;
  long n = 0;
  int contacts = 0;
  expect_bitwise_continuation(p, 0.0, 1, n, contacts);
  EXPECT_GT(n, 10);
}

TEST(Checkpoint, BytesOfAnotherSceneAreRefused) {
  const SceneParams p = rigid_friction_twist();
  Simulation original(p);
  original.advance_to(0.3);
  const std::string bytes = original.save_state();

  SceneParams no_friction = p;  // no friction history to restore into
  no_friction.mu_s = no_friction.mu_d = 0;
  Simulation a(no_friction);
  EXPECT_THROW(a.restore_state(bytes), CheckpointError);

  SceneParams elastic = elastic_friction_folds();  // other terms
  Simulation b(elastic);
  EXPECT_THROW(b.restore_state(bytes), CheckpointError);

  SceneParams no_twist = p;  // no twist angles
  no_twist.numerics.twist = EffectMode::Off;
  Simulation c(no_twist);
  EXPECT_THROW(c.restore_state(bytes), CheckpointError);
}

TEST(Checkpoint, TruncatedOrCorruptBytesAreRefused) {
  const SceneParams p = rigid_friction_twist();
  Simulation original(p);
  original.advance_to(0.3);
  const std::string bytes = original.save_state();
  for (std::size_t cut : {std::size_t{0}, std::size_t{3}, bytes.size() / 2, bytes.size() - 1}) {
    Simulation s(p);
    EXPECT_THROW(s.restore_state(std::string_view(bytes).substr(0, cut)), CheckpointError) << cut;
  }
  std::string longer = bytes + "x";
  Simulation s(p);
  EXPECT_THROW(s.restore_state(longer), CheckpointError);
  try {
    Simulation t(p);
    t.restore_state(std::string_view(bytes).substr(0, bytes.size() / 2));
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint state at byte"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace wirepack
