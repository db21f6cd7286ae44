// The friction history itself: rotation into the tangent plane, stick/slip bounds, transfer of
// the spring when a contact moves to a neighbouring element pair, and transactions.
#include <gtest/gtest.h>

#include <vector>

#include "engine/contact/friction.hpp"

namespace wirepack {
namespace {

FrictionParams params() {
  FrictionParams p;
  p.mu_s = 0.5;
  p.mu_d = 0.45;
  p.stiffness_ratio = 0.8;
  p.damping_ratio = 0.0;
  return p;
}

const Vec3 kN(0, 0, 1);  // contact normal
constexpr double kFn = 1.0, kKn = 1000.0, kM = 1e-3;

// Loads contact `k` with a tangential spring force by sliding at v for one step of dt.
Vec3 step(FrictionHistory& h, ContactKey k, const Vec3& v, double dt, double Fn = kFn,
          const std::vector<ContactKey>& nb = {}) {
  h.begin_trial(dt);
  h.mark(k);
  h.finish_marking();
  const Vec3 f = h.force(k, kN, Fn, kKn, v, kM, nb.data(), static_cast<int>(nb.size()));
  h.commit();
  return f;
}

TEST(FrictionHistory, SpringSticksThenSlipsAtTheDynamicBound) {
  FrictionHistory h(params());
  const ContactKey k{1, 5};
  // k_t v dt = 800 * 1e-4 * 1 = 0.08 N per step along -x.
  Vec3 f;
  for (int i = 0; i < 6; ++i) f = step(h, k, Vec3(1e-4, 0, 0), 1.0);
  EXPECT_NEAR(f[0], -0.48, 1e-12);        // still below mu_s F_n = 0.5: stick
  f = step(h, k, Vec3(1e-4, 0, 0), 1.0);  // 0.56 > 0.5: slip at mu_d F_n
  EXPECT_NEAR(f[0], -0.45, 1e-12);
  EXPECT_EQ(h.slipping(), 1);
  f = step(h, k, Vec3(1e-4, 0, 0), 1.0);  // still sliding: bound mu_d
  EXPECT_NEAR(f[0], -0.45, 1e-12);
  f = step(h, k, Vec3(-1e-4, 0, 0), 1.0);  // reversal: spring relaxes below mu_d, sticks
  EXPECT_NEAR(f[0], -0.37, 1e-12);
  EXPECT_EQ(h.slipping(), 0);
}

TEST(FrictionHistory, RotatesIntoTheNewTangentPlaneKeepingMagnitude) {
  FrictionHistory h(params());
  const ContactKey k{1, 5};
  step(h, k, Vec3(1e-4, 0, 0), 1.0);  // F = (-0.08, 0, 0)
  h.begin_trial(0.0);
  h.mark(k);
  h.finish_marking();
  const Vec3 n = Vec3(1, 0, 1).normalized();  // the normal has tilted by 45 degrees
  const Vec3 f = h.force(k, n, kFn, kKn, Vec3::Zero(), kM, nullptr, 0);
  EXPECT_NEAR(f.dot(n), 0.0, 1e-15);
  EXPECT_NEAR(f.norm(), 0.08, 1e-12);
}

TEST(FrictionHistory, ContactMovingToANeighbourPairKeepsItsSpring) {
  FrictionHistory h(params());
  for (int i = 0; i < 3; ++i) step(h, ContactKey{1, 5}, Vec3(1e-4, 0, 0), 1.0);  // F = -0.24
  // (1,5) has opened and (1,6) touches: the spring moves over; a zero-length step adds nothing.
  const Vec3 f = step(h, ContactKey{1, 6}, Vec3::Zero(), 0.0, kFn, {{1, 5}, {1, 7}});
  EXPECT_NEAR(f[0], -0.24, 1e-12);
  EXPECT_EQ(h.size(), 1u);  // the opened contact is gone
  // Without a neighbour entry, a new contact starts relaxed.
  const Vec3 g = step(h, ContactKey{9, 20}, Vec3::Zero(), 0.0);
  EXPECT_EQ(g.norm(), 0.0);
}

TEST(FrictionHistory, NewPairBesideATouchingOneSharesItsStateByLoad) {
  FrictionHistory h(params());
  for (int i = 0; i < 3; ++i) step(h, ContactKey{1, 5}, Vec3(1e-4, 0, 0), 1.0);  // F = -0.24
  h.begin_trial(0.0);
  h.mark(ContactKey{1, 5});
  h.mark(ContactKey{1, 6});
  h.finish_marking();
  const ContactKey nb[1] = {{1, 5}};
  // The new pair carries a quarter of the old pair's normal load: a quarter of its spring.
  const Vec3 f6 = h.force(ContactKey{1, 6}, kN, 0.25 * kFn, kKn, Vec3::Zero(), kM, nb, 1);
  EXPECT_NEAR(f6[0], -0.06, 1e-12);
}

TEST(FrictionHistory, RejectedTrialsLeaveNoTrace) {
  FrictionHistory h(params());
  step(h, ContactKey{1, 5}, Vec3(1e-4, 0, 0), 1.0);  // F = -0.08, committed
  // A trial that is not committed (a rejected step), then the accepted one.
  h.begin_trial(1.0);
  h.mark(ContactKey{1, 5});
  h.finish_marking();
  h.force(ContactKey{1, 5}, kN, kFn, kKn, Vec3(1e-3, 0, 0), kM, nullptr, 0);
  const Vec3 f = step(h, ContactKey{1, 5}, Vec3(1e-4, 0, 0), 1.0);
  EXPECT_NEAR(f[0], -0.16, 1e-12);
}

// Many contacts (the table grows several times, keys spread over both element ids and the wall's
// -1), then most of them open: each survivor keeps its own spring, an opened one is gone and
// starts relaxed when it touches again.
TEST(FrictionHistory, ManyContactsKeepTheirOwnSpringsAcrossGrowthAndDrops) {
  FrictionHistory h(params());
  std::vector<ContactKey> keys;
  for (int i = 0; i < 700; ++i) keys.push_back({i % 97 + 1000 * (i / 97), i % 3 == 0 ? -1 : i});
  // Contact i is loaded at speed (i + 1) 1e-7 along x for one step: F_i = -8e-5 (i + 1) N (k_t =
  // 800 N/m, dt = 1 s).
  h.begin_trial(1.0);
  for (const auto& k : keys) h.mark(k);
  h.finish_marking();
  for (size_t i = 0; i < keys.size(); ++i)
    h.force(keys[i], kN, kFn, kKn, Vec3((i + 1) * 1e-7, 0, 0), kM, nullptr, 0);
  h.commit();
  EXPECT_EQ(h.size(), keys.size());
  // Only every fifth contact stays closed (a zero-length step reads the springs back).
  h.begin_trial(0.0);
  for (size_t i = 0; i < keys.size(); i += 5) h.mark(keys[i]);
  h.finish_marking();
  for (size_t i = 0; i < keys.size(); i += 5) {
    const Vec3 f = h.force(keys[i], kN, kFn, kKn, Vec3::Zero(), kM, nullptr, 0);
    EXPECT_NEAR(f[0], -8e-5 * (i + 1), 1e-15) << "contact " << i;
  }
  h.commit();
  EXPECT_EQ(h.size(), (keys.size() + 4) / 5);
  // After the drop (the table rebuilt) the survivors still hold their springs, and an opened
  // contact that touches again starts relaxed.
  h.begin_trial(0.0);
  for (size_t i = 0; i < keys.size(); i += 5) h.mark(keys[i]);
  h.mark(keys[1]);
  h.finish_marking();
  for (size_t i = 0; i < keys.size(); i += 5) {
    const Vec3 f = h.force(keys[i], kN, kFn, kKn, Vec3::Zero(), kM, nullptr, 0);
    EXPECT_NEAR(f[0], -8e-5 * (i + 1), 1e-15) << "contact " << i;
  }
  EXPECT_EQ(h.force(keys[1], kN, kFn, kKn, Vec3::Zero(), kM, nullptr, 0).norm(), 0.0);
}

// The table marks free slots with the key of the pair (-1, -1). Asked for that key (the wall's
// tip node 0 named node -1 as its neighbour), the table returned the first free slot it probed,
// with whatever entry that slot had last held: a new contact inherited the spring of a contact
// long gone, which a run restored from a checkpoint (its free slots empty) did not, so the two
// parted (found by the kill campaign, app.KillCampaign, under load). Here every slot that held
// one of many springs is freed but one contact stays (the table is not empty); a new contact
// whose neighbours name (-1, -1) must start relaxed, as one without neighbours does.
TEST(FrictionHistory, TheFreeSlotsKeyIsNeverAContact) {
  FrictionHistory h(params());
  std::vector<ContactKey> keys;
  for (int i = 1; i <= 300; ++i) keys.push_back({i, -1});
  h.begin_trial(1.0);
  for (const auto& k : keys) h.mark(k);
  h.finish_marking();
  for (const auto& k : keys) h.force(k, kN, kFn, kKn, Vec3(1e-4, 0, 0), kM, nullptr, 0);
  h.commit();  // 300 springs of -0.08 N in x
  h.begin_trial(1.0);
  h.mark(keys.back());
  h.finish_marking();
  h.force(keys.back(), kN, kFn, kKn, Vec3::Zero(), kM, nullptr, 0);
  h.commit();  // all but the last opened: their slots free again
  ASSERT_EQ(h.size(), 1u);
  h.begin_trial(0.0);
  h.mark(keys.back());
  h.mark(ContactKey{0, -1});
  h.mark(ContactKey{299, -1});
  h.finish_marking();
  const ContactKey sentinel[1] = {{-1, -1}};
  const Vec3 f = h.force(ContactKey{0, -1}, kN, kFn, kKn, Vec3::Zero(), kM, sentinel, 1);
  EXPECT_EQ(f.norm(), 0.0) << "a new contact inherited " << f.transpose() << " N from a free slot";
  // With a real neighbour after it, the new contact takes that one's state (still touching:
  // scaled by load, here equal), not the free slot's.
  const ContactKey nb[2] = {{-1, -1}, keys.back()};
  const Vec3 g = h.force(ContactKey{299, -1}, kN, kFn, kKn, Vec3::Zero(), kM, nb, 2);
  EXPECT_NEAR(g[0], -0.08, 1e-12);
}

}  // namespace
}  // namespace wirepack
