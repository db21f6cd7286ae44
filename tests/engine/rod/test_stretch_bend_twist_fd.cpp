// Finite-difference checks of the rod energies at random states (docs/design.md §6.5).
#include <gtest/gtest.h>

#include "engine/fd_harness.hpp"
#include "engine/rod/bend.hpp"
#include "engine/rod/material.hpp"
#include "engine/rod/stretch.hpp"
#include "engine/rod/twist.hpp"

namespace wirepack {
namespace {

using testing::default_fd_steps;
using testing::fd_check;
using testing::random_rod;

// Central differences: the relative error falls ~100x per decade of h until round-off
// (~1e-16 / h relative) takes over, so the best of the ladder must be below 1e-6 and the
// error must fall by >= 10x between h = 1e-2 and h = 1e-3 (trend, not one lucky value).
void expect_consistent(const testing::FdReport& r) {
  testing::print_report(r);
  EXPECT_LT(r.best(), 1e-6);
  EXPECT_LT(r.err[1], 0.1 * r.err[0] + 1e-9);
}

TEST(RodFd, StretchGradientMatchesFiniteDifferences) {
  const auto mat = RodMaterial::from(WireParams{});
  for (unsigned seed = 1; seed <= 3; ++seed) {
    StretchTerm term(mat.EA());
    expect_consistent(
        fd_check(term, random_rod(12, 0.5e-3, false, seed), 0.5e-3, default_fd_steps()));
  }
}

TEST(RodFd, BendGradientMatchesFiniteDifferences) {
  const auto mat = RodMaterial::from(WireParams{});
  for (unsigned seed = 1; seed <= 3; ++seed) {
    BendTerm term(mat.EI());
    expect_consistent(
        fd_check(term, random_rod(12, 0.5e-3, false, seed), 0.5e-3, default_fd_steps()));
  }
}

TEST(RodFd, TwistGradientMatchesFiniteDifferences) {
  const auto mat = RodMaterial::from(WireParams{});
  for (unsigned seed = 1; seed <= 3; ++seed) {
    TwistTerm term(mat.GJ());
    expect_consistent(
        fd_check(term, random_rod(12, 0.5e-3, true, seed), 0.5e-3, default_fd_steps()));
  }
}

// With a swivel at the hole (FeederSpin::Free) the sum stops before the node joining the last
// free edge to the guide: the gradient of the shorter sum, on a rod whose last three nodes are
// kinematic.
TEST(RodFd, TwistWithASwivelAtTheGuideMatchesFiniteDifferences) {
  const auto mat = RodMaterial::from(WireParams{});
  for (unsigned seed = 1; seed <= 3; ++seed) {
    TwistTerm term(mat.GJ(), true);
    State s = random_rod(12, 0.5e-3, true, seed);
    s.n_free = 9;
    expect_consistent(fd_check(term, s, 0.5e-3, default_fd_steps()));
  }
}

}  // namespace
}  // namespace wirepack
