// Twin-run comparison of run records (report/twin.hpp) on synthetic snapshots with known answers.
#include "report/twin.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace wirepack::report {
namespace {

constexpr double kR = 0.5e-3;  // wire radius [m]

// A run whose snapshot k (l = k) holds a planar arc of 50 nodes, tip first, rotated by phi
// about z, with the tip node pushed by lift(k) along z.
sweep::RunRecord run(double phi, double (*lift)(int)) {
  sweep::RunRecord r;
  r.config = {{"wire", {{"radius", kR}}}};
  for (int k = 0; k < 6; ++k) {
    sweep::Snapshot s;
    s.l = k + 1e-4 * phi;            // recorded l differs by a rounding's worth between twins
    for (int i = 49; i >= 0; --i) {  // tip first
      const double a = 0.05 * i, x = 0.01 * std::sin(a), y = 0.01 * (1 - std::cos(a));
      const double z = -0.01 + 1e-4 * i + (i == 49 ? lift(k) : 0.0);
      s.wire.push_back(
          {std::cos(phi) * x - std::sin(phi) * y, std::sin(phi) * x + std::cos(phi) * y, z});
    }
    r.snapshots.push_back(s);
  }
  return r;
}

double none(int) {
  return 0.0;
}
double grows(int k) {
  return 0.4 * kR * k;
}  // 0.4 r per snapshot: > r from k = 3

TEST(Twin, RotatedTwinsNeverPart) {
  const TwinComparison c = compare_twins(run(0.0, none), run(1.3, none));
  ASSERT_EQ(c.l.size(), 6u);
  for (double s : c.separation_r) EXPECT_NEAR(s, 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(c.parting_l));
  EXPECT_EQ(twin_csv(c).substr(0, 21), "l,separation_r,rms_r\n");
  EXPECT_TRUE(std::isnan(c.parting_rms_l));
}

TEST(Twin, PartingLIsTheFirstSnapshotBeyondTheThreshold) {
  const TwinComparison c = compare_twins(run(0.0, none), run(0.7, grows));
  ASSERT_EQ(c.separation_r.size(), 6u);
  EXPECT_NEAR(c.separation_r[2], 0.8, 1e-6);             // the tip's lift, in r
  EXPECT_NEAR(c.rms_r[2], 0.8 / std::sqrt(50.0), 1e-6);  // one node of 50
  EXPECT_TRUE(std::isnan(c.parting_rms_l));
  EXPECT_NEAR(c.parting_l, 3.0, 1e-3);
  EXPECT_NEAR(compare_twins(run(0.0, none), run(0.7, grows), 1.9).parting_l, 5.0, 1e-3);
}

TEST(Twin, SnapshotsAtOtherLStopTheComparison) {
  sweep::RunRecord b = run(0.0, none);
  b.snapshots[4].l += 0.5;
  EXPECT_EQ(compare_twins(run(0.0, none), b).l.size(), 4u);
  EXPECT_THROW(compare_twins(sweep::RunRecord{}, b), sweep::RunFileError);
}

}  // namespace
}  // namespace wirepack::report
