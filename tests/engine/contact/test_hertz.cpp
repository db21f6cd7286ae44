// Hertz's law and the contact barrier: force = dU/ddelta and stiffness = dF/ddelta by central
// differences, continuity at the barrier's onset, and growth without bound towards its limit.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/contact/hertz.hpp"

namespace wirepack {
namespace {

TEST(Hertz, DerivativesAndBarrier) {
  Hertz h = Hertz::from(1e6, 0.5e-3);
  const double D = 1e-3;
  h.with_barrier(D, 0.5);
  for (double delta : {1e-5, 2e-4, 4.9e-4, 5.1e-4, 7e-4, 9e-4, 9.9e-4}) {
    const double e = 1e-9;  // central differences: relative error ~ (e/delta)^2 ~ 1e-8
    const double dU = (h.energy(delta + e) - h.energy(delta - e)) / (2 * e);
    const double dF = (h.force(delta + e) - h.force(delta - e)) / (2 * e);
    EXPECT_NEAR(h.force(delta) / dU, 1.0, 1e-6) << delta;
    EXPECT_NEAR(h.stiffness(delta) / dF, 1.0, 1e-6) << delta;
  }
  // Below the onset it is Hertz exactly; at the onset the force is continuous.
  Hertz plain = Hertz::from(1e6, 0.5e-3);
  EXPECT_EQ(h.force(4e-4), plain.force(4e-4));
  EXPECT_NEAR(h.force(5e-4 + 1e-12) / plain.force(5e-4), 1.0, 1e-6);
  // Towards the limit the force grows without bound.
  EXPECT_GT(h.force(0.999 * D), 100 * plain.force(0.999 * D));
}

}  // namespace
}  // namespace wirepack
