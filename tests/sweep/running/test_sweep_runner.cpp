// The sweep driver (docs/design.md §4.5, §3.6): runs, records, resume, failure isolation, shards,
// determinism across thread counts, longest-first order. Tiny rigid scenes (rho = 10, l <= 5,
// elements of 1 mm) keep each run in the 10 ms range.
#include "sweep/running/sweep_runner.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "sweep/config/json_file.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

Sweep tiny(const std::string& grid, const std::string& seeds = "2", double l_max = 2) {
  return parse_sweep(
      parse_json_text(R"({"name": "tiny", "base": {"rho": 10, "mu_s": 0, "shell": "rigid",
      "l_max": )" + std::to_string(l_max) +
                          R"(, "numerics": {"element_length": 1e-3}},
      "grid": )" + grid + R"(, "seeds": )" +
                          seeds + "}",
                      "tiny.json"),
      "tiny.json");
}

SweepOutcome run(const Sweep& sw, const std::string& dir, int threads = 2, Shard shard = {},
                 bool retry = false) {
  SweepOptions opt;
  opt.dir = dir;
  opt.threads = threads;
  opt.shard = shard;
  opt.retry_failed = retry;
  return run_sweep(sw, opt);
}

json manifest(const std::string& dir, Shard shard = {}) {
  return json::parse(read_text(manifest_path(dir, shard)));
}

// Lines of a joblog without the header.
std::vector<std::string> joblog_lines(const std::string& path) {
  std::istringstream in(read_text(path));
  std::vector<std::string> lines;
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "id,file,start,end,wall_s,status,reason,shard");
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// Bytes and modification time of a file, to show it was not touched.
struct Stamp {
  std::string bytes;
  fs::file_time_type mtime;
  bool operator==(const Stamp&) const = default;
};
Stamp stamp(const std::string& path) {
  return {read_text(path), fs::last_write_time(path)};
}

TEST(SweepRunner, RunsEveryRunAndRecordsIt) {
  TempDir dir;
  const Sweep sw = tiny(R"({"mu_s": [0, 0.5]})");
  const SweepOutcome o = run(sw, dir / "s");
  EXPECT_EQ(o.runs, 4u);
  EXPECT_EQ(o.complete, 4u);
  EXPECT_EQ(o.failed, 0u);
  EXPECT_EQ(o.ran, 4u);
  EXPECT_EQ(o.found, 0u);
  EXPECT_EQ(o.threads, 2);
  EXPECT_EQ(o.manifest, dir / "s/manifest.json");
  for (const auto& r : sw.runs) {
    const RunRecord rec = read_run_file(dir / ("s/" + r.file));
    EXPECT_EQ(rec.status, RunStatus::Complete) << r.file;
    EXPECT_EQ(canonical_json(rec.config), canonical_json(r.scene.resolved));
  }
  const json m = manifest(dir / "s");
  EXPECT_EQ(m["sweep"], sw.resolved);
  EXPECT_EQ(m["counts"]["complete"], 4);
  for (std::size_t i = 0; i < sw.runs.size(); ++i) {
    EXPECT_EQ(m["runs"][i]["id"], sw.runs[i].id);
    EXPECT_EQ(m["runs"][i]["status"], "complete");
    EXPECT_GT(m["runs"][i]["wall_s"].get<double>(), 0);
    EXPECT_FALSE(m["runs"][i]["started"].get<std::string>().empty());
  }
  const auto lines = joblog_lines(dir / "s/joblog.csv");
  ASSERT_EQ(lines.size(), 4u);
  for (const auto& l : lines) EXPECT_NE(l.find(",complete,,0/1"), std::string::npos) << l;
  // Nothing but the run files, the manifest, the joblog and the lock.
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "s")) names.insert(e.path().filename());
  EXPECT_EQ(names, (std::set<std::string>{".lock", "joblog.csv", "manifest.json", "runs"}));
}

// Bitwise equality of every series but wall_s, and of the snapshots.
void expect_same_trajectory(const RunRecord& a, const RunRecord& b, const std::string& what) {
  ASSERT_EQ(a.series.size(), b.series.size()) << what;
  for (std::size_t c = 0; c < a.series.size(); ++c) {
    if (a.series[c].name == "wall_s") continue;
    const auto& x = a.series[c].values;
    const auto& y = b.series[c].values;
    ASSERT_EQ(x.size(), y.size()) << what << " " << a.series[c].name;
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0)
        << what << " " << a.series[c].name;
  }
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size()) << what;
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    const auto& p = a.snapshots[k].wire;
    const auto& q = b.snapshots[k].wire;
    ASSERT_EQ(p.size(), q.size()) << what;
    EXPECT_EQ(std::memcmp(p.data(), q.data(), p.size() * sizeof(p[0])), 0) << what << " " << k;
  }
}

TEST(SweepRunner, OneAndTwoThreadsGiveBitwiseIdenticalSeries) {
  TempDir dir;
  // Friction on and off (twist and no twist), three seeds, long enough for wall contact.
  const Sweep sw = tiny(R"({"mu_s": [0, 0.5]})", "3", 5);
  ASSERT_EQ(run(sw, dir / "one", 1).complete, 6u);
  ASSERT_EQ(run(sw, dir / "two", 2).complete, 6u);
  for (const auto& r : sw.runs) {
    const RunRecord a = read_run_file(dir / ("one/" + r.file));
    const RunRecord b = read_run_file(dir / ("two/" + r.file));
    expect_same_trajectory(a, b, r.file);
    EXPECT_GT(a.find_series("steps")->values.back(), 0);
  }
  // Different seeds give different trajectories (the seed reaches the engine).
  const RunRecord s1 = read_run_file(dir / ("one/" + sw.runs[0].file));
  const RunRecord s2 = read_run_file(dir / ("one/" + sw.runs[1].file));
  EXPECT_NE(s1.snapshots.back().wire, s2.snapshots.back().wire);
}

// Engine V: once every run has started, the idle cores go to the runs still going (their force
// loops get threads); a single elastic run (rho = 10, coarse, shell contact from l ~ 1.3) on a
// 2-thread sweep is bitwise the run of a 1-thread sweep.
TEST(SweepRunner, IdleCoresGoToTheLastRunsWithoutChangingThem) {
  TempDir dir;
  const Sweep sw =
      parse_sweep(parse_json_text(R"({"name": "elastic", "base": {"rho": 10, "xi": 10, "eps": 1000,
        "mu_s": 0.5, "shell": "elastic", "l_max": 2,
        "numerics": {"element_length": 1e-3, "shell_mesh_size": 1e-3}}, "grid": {}, "seeds": 1})",
                                  "elastic.json"),
                  "elastic.json");
  ASSERT_EQ(run(sw, dir / "one", 1).complete, 1u);
  ASSERT_EQ(run(sw, dir / "two", 2).complete, 1u);
  const RunRecord a = read_run_file(dir / ("one/" + sw.runs[0].file));
  const RunRecord b = read_run_file(dir / ("two/" + sw.runs[0].file));
  expect_same_trajectory(a, b, sw.runs[0].file);
  EXPECT_EQ(a.snapshots.back().shell_vertices, b.snapshots.back().shell_vertices);
}

TEST(SweepRunner, FailedRunIsRecordedAndTheOthersComplete) {
  TempDir dir;
  // E_w = 1e300 overflows the forces: the engine stops with a non-finite state.
  const Sweep sw = tiny(R"({"/wire/youngs_modulus": [1e9, 1e300]})", "2");
  const SweepOutcome o = run(sw, dir / "s");
  EXPECT_EQ(o.complete, 2u);
  EXPECT_EQ(o.failed, 2u);
  ASSERT_EQ(o.failures.size(), 2u);
  const json m = manifest(dir / "s");
  EXPECT_EQ(m["counts"]["failed"], 2);
  for (std::size_t i = 0; i < sw.runs.size(); ++i) {
    const bool bad = sw.runs[i].scene.engine.wire.youngs_modulus > 1e100;
    const RunRecord rec = read_run_file(dir / ("s/" + sw.runs[i].file));
    EXPECT_EQ(rec.status, bad ? RunStatus::Failed : RunStatus::Complete);
    EXPECT_EQ(m["runs"][i]["status"], bad ? "failed" : "complete");
    if (bad) {
      EXPECT_FALSE(rec.failure.empty());
      EXPECT_EQ(m["runs"][i]["reason"], rec.failure);
      EXPECT_EQ(o.failures[i - 2].first, sw.runs[i].file);
      EXPECT_EQ(o.failures[i - 2].second, rec.failure);
    }
  }
  std::size_t failed_lines = 0;
  for (const auto& l : joblog_lines(dir / "s/joblog.csv"))
    failed_lines += l.find(",failed,") != std::string::npos;
  EXPECT_EQ(failed_lines, 2u);
}

TEST(SweepRunner, RunFileThatCannotBeWrittenIsAFailedRun) {
  TempDir dir;
  const Sweep sw = tiny(R"({"mu_s": [0]})", "2");
  // A directory where the run file should go: the rename of the finished .part fails.
  fs::create_directories(dir / ("s/" + sw.runs[1].file));
  const SweepOutcome o = run(sw, dir / "s");
  EXPECT_EQ(o.complete, 1u);
  ASSERT_EQ(o.failed, 1u);
  EXPECT_EQ(o.failures[0].first, sw.runs[1].file);
  EXPECT_NE(o.failures[0].second.find("run file not written"), std::string::npos)
      << o.failures[0].second;
  EXPECT_EQ(manifest(dir / "s")["runs"][1]["status"], "failed");
  EXPECT_FALSE(fs::exists(dir / ("s/" + sw.runs[1].file + ".part")));
}

TEST(SweepRunner, ResumeKeepsFinishedRunsAndRedoesPartLeftovers) {
  TempDir dir;
  const Sweep sw = tiny(R"({"mu_s": [0, 0.5]})");
  ASSERT_EQ(run(sw, dir / "s").complete, 4u);
  // A killed run: its final file missing, a partial file left.
  const std::string lost = dir / ("s/" + sw.runs[2].file);
  fs::remove(lost);
  std::ofstream(lost + ".part") << "half a file";
  std::map<std::string, Stamp> before;
  for (const auto& r : sw.runs)
    if (r.index != 2) before[r.file] = stamp(dir / ("s/" + r.file));

  const SweepOutcome o = run(sw, dir / "s");
  EXPECT_EQ(o.ran, 1u);
  EXPECT_EQ(o.found, 3u);
  EXPECT_EQ(o.parts_removed, 1u);
  EXPECT_EQ(o.complete, 4u);
  EXPECT_FALSE(fs::exists(lost + ".part"));
  EXPECT_EQ(read_run_file(lost).status, RunStatus::Complete);
  for (const auto& [file, s] : before) EXPECT_TRUE(stamp(dir / ("s/" + file)) == s) << file;
  EXPECT_EQ(joblog_lines(dir / "s/joblog.csv").size(), 5u);  // 4 + the redone one

  // Nothing left to do: no run, no joblog line, every run still complete.
  const SweepOutcome again = run(sw, dir / "s");
  EXPECT_EQ(again.ran, 0u);
  EXPECT_EQ(again.complete, 4u);
  EXPECT_EQ(joblog_lines(dir / "s/joblog.csv").size(), 5u);
  EXPECT_EQ(manifest(dir / "s")["counts"]["complete"], 4);
}

TEST(SweepRunner, RetryFailedRerunsOnlyTheFailed) {
  TempDir dir;
  const Sweep sw = tiny(R"({"/wire/youngs_modulus": [1e9, 1e300]})", "1");
  ASSERT_EQ(run(sw, dir / "s").failed, 1u);
  const Stamp good = stamp(dir / ("s/" + sw.runs[0].file));
  const SweepOutcome kept = run(sw, dir / "s");
  EXPECT_EQ(kept.ran, 0u);
  EXPECT_EQ(kept.failed, 1u);  // still failed: exit code 1 for the CLI
  EXPECT_EQ(manifest(dir / "s")["runs"][1]["reason"], kept.failures[0].second);
  const SweepOutcome retried = run(sw, dir / "s", 2, {}, true);
  EXPECT_EQ(retried.ran, 1u);
  EXPECT_EQ(retried.failed, 1u);  // fails again, deterministically
  EXPECT_TRUE(stamp(dir / ("s/" + sw.runs[0].file)) == good);
}

TEST(SweepRunner, ChangedSweepAddsPointsWithoutTouchingFinishedOnes) {
  TempDir dir;
  const Sweep small = tiny(R"({"mu_s": [0]})");
  ASSERT_EQ(run(small, dir / "s").complete, 2u);
  std::map<std::string, Stamp> before;
  for (const auto& r : small.runs) before[r.file] = stamp(dir / ("s/" + r.file));
  const Sweep grown = tiny(R"({"mu_s": [0, 0.5]})", "3");
  const SweepOutcome o = run(grown, dir / "s");
  EXPECT_EQ(o.found, 2u);
  EXPECT_EQ(o.ran, 4u);
  EXPECT_EQ(o.complete, 6u);
  for (const auto& [file, s] : before) EXPECT_TRUE(stamp(dir / ("s/" + file)) == s) << file;
}

TEST(SweepRunner, ShardsTogetherGiveExactlyTheUnshardedSet) {
  TempDir dir;
  const Sweep sw = tiny(R"({"mu_s": [0, 0.5], "rho": [8, 10]})", "2");  // 8 runs
  std::multiset<std::string> files;
  std::size_t lines = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const Shard shard{k, 3};
    const SweepOutcome o = run(sw, dir / "s", 1, shard);
    EXPECT_EQ(o.complete, o.runs);
    const json m = manifest(dir / "s", shard);
    EXPECT_EQ(m["shard"], shard.text());
    for (const auto& r : m["runs"]) {
      EXPECT_EQ(r["index"].get<std::size_t>() % 3, k);
      files.insert(r["file"].get<std::string>());
    }
    lines += joblog_lines(joblog_path(dir / "s", shard)).size();
  }
  std::multiset<std::string> expected;
  for (const auto& r : sw.runs) expected.insert(r.file);
  EXPECT_EQ(files, expected);  // disjoint (a multiset would show repeats) and complete
  EXPECT_EQ(lines, sw.runs.size());
  std::size_t on_disk = 0;
  for (const auto& e : fs::directory_iterator(dir / "s/runs"))
    on_disk += e.path().extension() == ".h5";
  EXPECT_EQ(on_disk, sw.runs.size());
  // The unsharded sweep then finds everything done and writes the combined manifest.
  const SweepOutcome all = run(sw, dir / "s");
  EXPECT_EQ(all.ran, 0u);
  EXPECT_EQ(manifest(dir / "s")["counts"]["complete"], 8);
}

TEST(SweepRunner, LongestExpectedRunsStartFirst) {
  TempDir dir;
  const Sweep sw = tiny(R"({"l_max": [1, 3, 2]})", "1");
  ASSERT_EQ(run(sw, dir / "s", 1).complete, 3u);
  const auto lines = joblog_lines(dir / "s/joblog.csv");
  ASSERT_EQ(lines.size(), 3u);
  // One thread: the joblog order is the start order, l_max 3, 2, 1.
  EXPECT_EQ(lines[0].find(sw.runs[1].id), 0u);
  EXPECT_EQ(lines[1].find(sw.runs[2].id), 0u);
  EXPECT_EQ(lines[2].find(sw.runs[0].id), 0u);
}

TEST(SweepRunner, ProgressLinesAndLockedShard) {
  TempDir dir;
  const Sweep sw = tiny(R"({"mu_s": [0]})");
  std::ostringstream progress;
  SweepOptions opt;
  opt.dir = dir / "s";
  opt.threads = 1;
  opt.progress = &progress;
  opt.progress_interval_s = 0;
  ASSERT_EQ(run_sweep(sw, opt).complete, 2u);
  const std::string text = progress.str();
  EXPECT_NE(text.find("sweep tiny: 2 runs, 0 already complete; running 2 on 1 thread into"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("sweep tiny: 2/2 done, 0 failed, 0 running, elapsed"), std::string::npos)
      << text;
  EXPECT_NE(text.find("ETA 0:00:00"), std::string::npos) << text;

  DirLock held(lock_path(dir / "s", Shard{}));
  EXPECT_THROW(run(sw, dir / "s"), InputError);
  EXPECT_NO_THROW(run(sw, dir / "s", 1, Shard{0, 2}));  // another shard has its own lock
}

TEST(SweepRunner, UnusableDirectoryIsAnInputError) {
  TempDir dir;
  std::ofstream(dir / "file") << "x";
  const Sweep sw = tiny(R"({"mu_s": [0]})", "1");
  EXPECT_THROW(run(sw, dir / "file"), InputError);
  EXPECT_THROW(run(sw, dir / "file/sub"), InputError);
}

}  // namespace
}  // namespace wirepack::sweep
