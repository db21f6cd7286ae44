// Run file (docs/design.md §4.3): write/read round trip, write-then-rename, failures leave nothing.
#include "sweep/run_file.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::TempDir;

RunRecord sample_record() {
  RunRecord r;
  r.config = {{"rho", 20.0}, {"shell", "elastic"}, {"wire", {{"radius", 5e-4}}}};
  r.status = RunStatus::Failed;
  r.failure = "step collapse at t = 1e-3 s";
  r.version = "0.1.0";
  r.git = "abc123";
  r.started = "2024-05-01T12:00:00Z";
  r.finished = "2024-05-01T12:01:00Z";
  // Deliberately not in alphabetical order: the file keeps recording order.
  r.series = {
      {"l", {0.0, 0.1, 0.2}}, {"U_b_hat", {1.0, std::nan(""), 3.0}}, {"D", {0.5, 0.25, 0.125}}};
  Snapshot s0;
  s0.l = 0;
  Snapshot s1;
  s1.l = 0.2;
  s1.wire = {{0, 0, -1e-2}, {0, 1e-3, -9e-3}, {1e-3, 2e-3, -8e-3}};
  s1.curvature = {0, 12.5, 0};
  s1.shell_vertices = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  s1.shell_triangles = {{0, 1, 2}, {0, 2, 3}};
  r.snapshots = {s0, s1};
  // Snapshot indices above 9 must still come back in numeric order.
  for (int k = 2; k < 12; ++k) {
    Snapshot s;
    s.l = 0.1 * k;
    s.wire = {{0, 0, 0}, {0, 0, 1e-3 * k}};
    s.curvature = {0, 0};
    r.snapshots.push_back(s);
  }
  return r;
}

TEST(RunFile, RoundTrip) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  const RunRecord r = sample_record();
  write_run_file(r, path);
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));

  const RunRecord b = read_run_file(path);
  EXPECT_EQ(b.config, r.config);
  EXPECT_EQ(b.status, RunStatus::Failed);
  EXPECT_EQ(b.failure, r.failure);
  EXPECT_EQ(b.version, r.version);
  EXPECT_EQ(b.git, r.git);
  EXPECT_EQ(b.started, r.started);
  EXPECT_EQ(b.finished, r.finished);
  ASSERT_EQ(b.series.size(), 3u);
  EXPECT_EQ(b.series[0].name, "l");
  EXPECT_EQ(b.series[1].name, "U_b_hat");
  EXPECT_EQ(b.series[2].name, "D");
  EXPECT_EQ(b.series[0].values, r.series[0].values);
  EXPECT_TRUE(std::isnan(b.series[1].values[1]));
  EXPECT_EQ(b.series[1].values[2], 3.0);
  ASSERT_NE(b.find_series("D"), nullptr);
  EXPECT_EQ(b.find_series("D")->values, r.series[2].values);
  EXPECT_EQ(b.find_series("nope"), nullptr);

  ASSERT_EQ(b.snapshots.size(), r.snapshots.size());
  for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
    EXPECT_EQ(b.snapshots[k].l, r.snapshots[k].l) << k;
    EXPECT_EQ(b.snapshots[k].wire, r.snapshots[k].wire) << k;
    EXPECT_EQ(b.snapshots[k].curvature, r.snapshots[k].curvature) << k;
    EXPECT_EQ(b.snapshots[k].shell_vertices, r.snapshots[k].shell_vertices) << k;
    EXPECT_EQ(b.snapshots[k].shell_triangles, r.snapshots[k].shell_triangles) << k;
  }
  EXPECT_TRUE(b.snapshots[0].wire.empty());
}

TEST(RunFile, StatusStrings) {
  for (RunStatus s : {RunStatus::Running, RunStatus::Complete, RunStatus::Failed})
    EXPECT_EQ(run_status_from_string(to_string(s)), s);
  EXPECT_EQ(to_string(RunStatus::Complete), "complete");
  EXPECT_THROW(run_status_from_string("done"), RunFileError);
}

TEST(RunFile, OverwriteReplaces) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  RunRecord r = sample_record();
  write_run_file(r, path);
  r.status = RunStatus::Complete;
  r.failure = "";
  r.snapshots.clear();
  write_run_file(r, path);
  const RunRecord b = read_run_file(path);
  EXPECT_EQ(b.status, RunStatus::Complete);
  EXPECT_TRUE(b.snapshots.empty());
}

TEST(RunFile, UnwritablePathLeavesNothing) {
  TempDir dir;
  // A path below a regular file fails even for root.
  const std::string file = dir.write("plain", "x");
  EXPECT_THROW(write_run_file(sample_record(), file + "/run.h5"), RunFileError);
  EXPECT_THROW(write_run_file(sample_record(), dir / "missing/run.h5"), RunFileError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(RunFile, ReadOnlyDirectoryLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "permission bits do not stop root";
  TempDir dir;
  const fs::path ro = dir.path() / "ro";
  fs::create_directory(ro);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  try {
    write_run_file(sample_record(), (ro / "run.h5").string());
    ADD_FAILURE() << "no exception";
  } catch (const RunFileError& e) {
    EXPECT_NE(std::string(e.what()).find("run.h5.part"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(ro));
}

TEST(RunFile, FailedWriteKeepsPreviousFile) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  write_run_file(sample_record(), path);
  RunRecord bad = sample_record();
  bad.status = RunStatus::Complete;
  bad.series[1].values.pop_back();  // ragged series: refused mid-write
  EXPECT_THROW(write_run_file(bad, path), RunFileError);
  EXPECT_FALSE(fs::exists(path + ".part"));
  EXPECT_EQ(read_run_file(path).status, RunStatus::Failed);
}

TEST(RunFile, ReadErrors) {
  TempDir dir;
  EXPECT_THROW(read_run_file(dir / "none.h5"), RunFileError);
  const std::string junk = dir.write("junk.h5", "not hdf5");
  try {
    read_run_file(junk);
    ADD_FAILURE() << "no exception";
  } catch (const RunFileError& e) {
    EXPECT_NE(std::string(e.what()).find(junk), std::string::npos) << e.what();
  }
}

TEST(RunFile, ConcurrentWritersAndReaders) {
  TempDir dir;
  const RunRecord r = sample_record();
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      const std::string path = dir / ("run" + std::to_string(t) + ".h5");
      for (int i = 0; i < 5; ++i) {
        write_run_file(r, path);
        EXPECT_EQ(read_run_file(path).snapshots.size(), r.snapshots.size());
      }
    });
  for (auto& th : threads) th.join();
}

}  // namespace
}  // namespace wirepack::sweep
