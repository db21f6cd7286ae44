// The run loop (docs/design.md §4.3, §5.7): a short rigid-shell run end to end, and a run that
// fails.
#include "sweep/running/run.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "analysis/observables.hpp"
#include "sweep/runfile/wire_profile.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using wirepack::testing::TempDir;

Scene short_rigid(double l_max) {
  return parse_scene({{"rho", 20},
                      {"mu_s", 0},
                      {"shell", "rigid"},
                      {"l_max", l_max},
                      {"numerics", {{"element_length", 1e-3}}},
                      {"output", {{"every_l", 0.1}, {"snapshots_every_l", 0.5}}}},
                     "short.json");
}

TEST(Run, SeriesNames) {
  const std::vector<std::string> expected = {
      "l", "U_b_hat", "U_b", "U_t", "U_s", "U_m",    "U_sb",  "E_kin",   "K",       "N",    "S",
      "D", "R_t",     "R_x", "R_y", "dt",  "wall_s", "steps", "S_kappa", "D_chord", "chord"};
  EXPECT_EQ(series_names(), expected);
}

TEST(Run, ShortRigidRun) {
  TempDir dir;
  const Scene scene = short_rigid(1.0);
  std::ostringstream progress;
  const std::string path = dir / "run.h5";
  const RunOutcome out = run_scene(scene, path, &progress);
  ASSERT_EQ(out.status, RunStatus::Complete) << out.failure;
  EXPECT_GE(out.l, 1.0);
  EXPECT_GT(out.steps, 0);
  EXPECT_NE(progress.str().find("done"), std::string::npos) << progress.str();
  EXPECT_FALSE(fs::exists(path + ".part"));

  const RunRecord r = read_run_file(path);
  EXPECT_EQ(r.status, RunStatus::Complete);
  EXPECT_EQ(r.failure, "");
  EXPECT_EQ(r.config, scene.resolved);
  EXPECT_FALSE(r.started.empty());
  EXPECT_FALSE(r.finished.empty());
  EXPECT_FALSE(r.version.empty());

  ASSERT_EQ(r.series.size(), series_names().size());
  for (std::size_t c = 0; c < r.series.size(); ++c) EXPECT_EQ(r.series[c].name, series_names()[c]);
  const auto& l = r.find_series("l")->values;
  const auto& steps = r.find_series("steps")->values;
  for (const auto& s : r.series) EXPECT_EQ(s.values.size(), l.size()) << s.name;
  // Rows every 0.1 in l from the start to the end: about 10 of them, the last at l >= 1.
  EXPECT_GE(l.size(), 9u);
  EXPECT_LE(l.size(), 13u);
  EXPECT_GE(l.back(), 1.0);
  for (std::size_t i = 1; i < l.size(); ++i) {
    EXPECT_GT(l[i], l[i - 1]);
    EXPECT_GE(steps[i], steps[i - 1]);
    EXPECT_LT(l[i] - l[i - 1], 0.1 + 0.05) << i;
  }
  for (double x : r.find_series("D")->values) EXPECT_TRUE(x >= 0 && x <= 1) << x;
  for (double x : r.find_series("U_m")->values) EXPECT_EQ(x, 0);  // rigid: no shell energy
  for (double x : r.find_series("dt")->values) EXPECT_GT(x, 0);
  for (const char* name : {"R_t", "R_x", "R_y"})
    for (double x : r.find_series(name)->values) EXPECT_TRUE(std::isnan(x) || x >= 0) << name;
  for (double x : r.find_series("S_kappa")->values) EXPECT_TRUE(x >= -1 && x <= 1) << x;

  // Snapshots at the start, every 0.5 and at the end.
  ASSERT_GE(r.snapshots.size(), 3u);
  EXPECT_EQ(r.snapshots.front().l, l.front());
  EXPECT_GE(r.snapshots.back().l, 1.0);
  const Snapshot& last = r.snapshots.back();
  EXPECT_GT(last.wire.size(), 2u);
  EXPECT_EQ(last.curvature.size(), last.wire.size());
  EXPECT_TRUE(last.shell_vertices.empty());
  // The wire inside stays within the sphere of radius R = 10 mm (plus the wire radius).
  for (const auto& x : last.wire)
    EXPECT_LT(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), 10.5e-3);
  // The last row and the last snapshot are the same state: S_kappa is that of its wire.
  ASSERT_EQ(last.l, l.back());
  std::vector<Vec3> wire;
  for (const auto& x : last.wire) wire.emplace_back(x[0], x[1], x[2]);
  EXPECT_EQ(r.find_series("S_kappa")->values.back(), analysis::curvature_weighted_order(wire).S);
  // And D_chord and the chord's length are those of the same wire in the rigid sphere.
  const OrderVariants o = order_variants(wire, scene.engine, {}, {});
  EXPECT_EQ(r.find_series("D_chord")->values.back(), o.D_chord);
  EXPECT_NEAR(r.find_series("chord")->values.back(), o.chord_length_R, 1e-12);
  for (double x : r.find_series("D_chord")->values) EXPECT_TRUE(x >= 0 && x <= 1) << x;
}

TEST(Run, FailedRunStillWritesFile) {
  TempDir dir;
  // Forces overflow a double: the engine stops with a non-finite state.
  json j = short_rigid(1.0).resolved;
  j["wire"]["youngs_modulus"] = 1e300;
  const Scene scene = parse_scene(j, "overflow.json");
  const std::string path = dir / "run.h5";
  const RunOutcome out = run_scene(scene, path, nullptr);
  ASSERT_EQ(out.status, RunStatus::Failed);
  EXPECT_FALSE(out.failure.empty());
  const RunRecord r = read_run_file(path);
  EXPECT_EQ(r.status, RunStatus::Failed);
  EXPECT_EQ(r.failure, out.failure);
  EXPECT_EQ(r.series.size(), series_names().size());
  EXPECT_FALSE(fs::exists(path + ".part"));
}

TEST(Run, UnwritableOutputThrowsAfterRun) {
  TempDir dir;
  const std::string file = dir.write("plain", "x");
  EXPECT_THROW(run_scene(short_rigid(0.3), file + "/run.h5", nullptr), RunFileError);
}

}  // namespace
}  // namespace wirepack::sweep
