// `wirepack sweep` and `wirepack validate` on sweep files, end to end (docs/design.md §6.2, §4.5):
// exit codes, nothing written on bad input, resume after SIGKILL, shards from SLURM's environment.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli_runner.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

using Result = wirepack::testing::CliResult;

// Runs `wirepack ARGS` in `dir` (cli_runner.hpp).
Result wirepack(const TempDir& dir, const std::string& args, const std::string& env = "") {
  return wirepack::testing::run_wirepack(dir, args, env);
}

// A tiny sweep: rigid, rho = 10, elements of 1 mm.
std::string tiny_sweep(const std::string& grid, int seeds, double l_max = 2,
                       double element_length = 1e-3) {
  std::ostringstream s;
  s << R"({"name": "tiny", "base": {"rho": 10, "mu_s": 0, "shell": "rigid", "l_max": )" << l_max
    << R"(, "numerics": {"element_length": )" << element_length << R"(}}, "grid": )" << grid
    << R"(, "seeds": )" << seeds << "}";
  return s.str();
}

sweep::Sweep parsed(const std::string& text) {
  return sweep::parse_sweep(json::parse(text), "s.json");
}

TEST(CliSweep, BadSweepsExit2AndWriteNothing) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {tiny_sweep(R"({"mu_s": []})", 2), "s.json: /grid/mu_s: an axis must list at least one"},
      {tiny_sweep(R"({"bogus": [1]})", 2), "s.json: /grid/bogus: unknown scene key"},
      {tiny_sweep(R"({"mu_s": [0, 0.5, -1]})", 2), "s.json: /grid/mu_s/2: must be >= 0"},
      {tiny_sweep(R"({"mu_s": 0.5})", 2), "s.json: /grid/mu_s: an axis must be a list"},
      {tiny_sweep(R"({"mu_s": [0, 0]})", 2), "s.json: /grid/mu_s/1: duplicate value"},
      {tiny_sweep(R"({"mu_s": [0]})", 0), "s.json: /seeds: a seed count must be in"},
      {R"({"name": "t", "base": {"rho": 10}, "grid": {"mu_s": [0]}, "name": "u"})",
       "s.json: /name: duplicate key"},
      {"{\"name\": \"t\",\n \"grid\": }", "s.json: line 2, column"},
  };
  for (const auto& [text, message] : cases) {
    SCOPED_TRACE(text);
    TempDir dir;
    dir.write("s.json", text);
    for (const std::string cmd : {"sweep s.json --out out", "validate s.json"}) {
      const Result r = wirepack(dir, cmd);
      EXPECT_EQ(r.code, 2) << cmd << ": " << r.err;
      EXPECT_NE(r.err.find(message), std::string::npos) << cmd << ": " << r.err;
      EXPECT_EQ(r.out, "");
      EXPECT_FALSE(fs::exists(dir / "out"));
      EXPECT_FALSE(fs::exists(dir / "sweeps"));
    }
  }
}

TEST(CliSweep, UsageErrorsExit2) {
  TempDir dir;
  dir.write("s.json", tiny_sweep(R"({"mu_s": [0]})", 1));
  for (const std::string args :
       {"sweep s.json --threads 0", "sweep s.json --shard 3/3", "sweep s.json --shard x",
        "sweep missing.json", "sweep s.json --out s.json"}) {
    SCOPED_TRACE(args);
    EXPECT_EQ(wirepack(dir, args).code, 2);
  }
  EXPECT_EQ(wirepack(dir, "sweep s.json", "SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_COUNT=2").code,
            2);
  EXPECT_FALSE(fs::exists(dir / "sweeps"));
}

TEST(CliSweep, ValidatePrintsTheResolvedSweepAndItsRuns) {
  TempDir dir;
  const std::string text = tiny_sweep(R"({"mu_s": [0, 0.5]})", 2);
  dir.write("s.json", text);
  const Result r = wirepack(dir, "validate s.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const sweep::Sweep sw = parsed(text);
  EXPECT_EQ(j["sweep"], sw.resolved);
  ASSERT_EQ(j["runs"].size(), 4u);
  EXPECT_EQ(j["runs"][3]["file"], sw.runs[3].file);
  EXPECT_EQ(j["runs"][3]["id"], sw.runs[3].id);
  EXPECT_FALSE(fs::exists(dir / "sweeps"));
  // Every committed sweep file (examples, the elastic D(mu_s) curve, the accuracy study).
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(WIREPACK_SOURCE_DIR "/scenes")) {
    const std::string file = e.path().string();
    if (file.size() < 11 || file.substr(file.size() - 11) != ".sweep.json") continue;
    ++files;
    const Result d = wirepack(dir, "validate '" + file + "'");
    EXPECT_EQ(d.code, 0) << file << ": " << d.err;
  }
  EXPECT_GE(files, 14);
}

TEST(CliSweep, CompleteSweepExit0FailedRunExit1) {
  TempDir dir;
  dir.write("ok.json", tiny_sweep(R"({"mu_s": [0, 0.5]})", 1));
  Result r = wirepack(dir, "sweep ok.json --threads 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "sweeps/tiny/manifest.json\n");  // default directory sweeps/<name>
  EXPECT_NE(r.err.find("sweep tiny: 2 runs, 2 complete, 0 failed"), std::string::npos) << r.err;
  EXPECT_EQ(json::parse(read_text(dir / "sweeps/tiny/manifest.json"))["counts"]["complete"], 2);

  dir.write("bad.json", tiny_sweep(R"({"/wire/youngs_modulus": [1e9, 1e300]})", 1));
  r = wirepack(dir, "sweep bad.json --out b");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("1 complete, 1 failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("failed: b/runs/youngs_modulus-1e300_s1_"), std::string::npos) << r.err;
  // Rerun: the failed run is kept (still exit 1) unless --retry-failed.
  r = wirepack(dir, "sweep bad.json --out b");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--retry-failed"), std::string::npos) << r.err;
  r = wirepack(dir, "sweep bad.json --out b --retry-failed");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("(1 run now"), std::string::npos) << r.err;
}

// --only runs a subset by axis values and seeds; the manifest keeps every run (the rest pending),
// the runs are those of the whole sweep (the same wires), and later invocations run the rest. A
// condition that cannot select (form, unknown axis, a value no run has) is bad input: exit 2,
// nothing written.
TEST(CliSweep, OnlyRunsTheSelectedRunsAndKeepsTheWholeManifest) {
  TempDir dir;
  dir.write("s.json", tiny_sweep(R"({"mu_s": [0, 0.5]})", 2));
  for (const std::string bad : {"--only mu_s", "--only =0.5", "--only mu_s=0.5,", "--only eps=1000",
                                "--only mu_s=0.3", "--only seed=3"}) {
    SCOPED_TRACE(bad);
    const Result r = wirepack(dir, "sweep s.json --out o " + bad);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--only"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "o"));
  }
  Result r = wirepack(dir, "sweep s.json --out o --only mu_s=0.5 --only seed=2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("running 1 on 1 thread into o (3 more to do, left out by --only)"),
            std::string::npos)
      << r.err;
  json m = json::parse(read_text(dir / "o/manifest.json"));
  EXPECT_EQ(m["counts"]["complete"], 1);
  EXPECT_EQ(m["counts"]["pending"], 3);
  const sweep::Sweep sw = parsed(tiny_sweep(R"({"mu_s": [0, 0.5]})", 2));
  ASSERT_EQ(sw.runs[3].seed, 2u);
  EXPECT_TRUE(fs::exists(dir / ("o/" + sw.runs[3].file)));

  r = wirepack(dir, "sweep s.json --out o --only mu_s=0,0.5 --only seed=1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("1 already complete; running 2"), std::string::npos) << r.err;
  r = wirepack(dir, "sweep s.json --out o");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("3 already complete; running 1 on"), std::string::npos) << r.err;
  m = json::parse(read_text(dir / "o/manifest.json"));
  EXPECT_EQ(m["counts"]["complete"], 4);

  // The same runs as one unfiltered sweep writes (the wire at the end, bitwise).
  ASSERT_EQ(wirepack(dir, "sweep s.json --out whole").code, 0);
  for (const auto& run : sw.runs)
    EXPECT_EQ(sweep::read_run_file(dir / ("o/" + run.file)).snapshots.back().wire,
              sweep::read_run_file(dir / ("whole/" + run.file)).snapshots.back().wire)
        << run.file;
}

TEST(CliSweep, ShardFromSlurmEnvironment) {
  TempDir dir;
  const std::string text = tiny_sweep(R"({"mu_s": [0, 0.5]})", 2);
  dir.write("s.json", text);
  // --array=1-3: task 2 is shard 1/3, runs 1 of 0..3.
  const Result r =
      wirepack(dir, "sweep s.json --out o",
               "SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "o/manifest.shard-1-of-3.json\n");
  const json m = json::parse(read_text(dir / "o/manifest.shard-1-of-3.json"));
  ASSERT_EQ(m["runs"].size(), 1u);
  EXPECT_EQ(m["runs"][0]["file"], parsed(text).runs[1].file);
  EXPECT_TRUE(fs::exists(dir / "o/joblog.shard-1-of-3.csv"));
  EXPECT_FALSE(fs::exists(dir / "o/manifest.json"));
}

// Three shard processes at once into one directory (a SLURM job array on one file system):
// each writes only its own files, together they are the sweep, and the unsharded command then
// finds everything done.
TEST(CliSweep, ConcurrentShardsShareOneDirectory) {
  TempDir dir;
  const std::string text = tiny_sweep(R"({"mu_s": [0, 0.5], "rho": [8, 10, 12]})", 3, 3);
  dir.write("s.json", text);
  const sweep::Sweep sw = parsed(text);
  const std::string w = "'" WIREPACK_BINARY "' sweep s.json --out o --threads 1 --shard ";
  const Result r =
      wirepack(dir, "--version >/dev/null && (" + w + "0/3 & p0=$!; " + w + "1/3 & p1=$!; " + w +
                        "2/3 & p2=$!; wait $p0 && wait $p1 && wait $p2)");
  ASSERT_EQ(r.code, 0) << r.err;
  std::multiset<std::string> files;
  for (int k = 0; k < 3; ++k) {
    const std::string tag = ".shard-" + std::to_string(k) + "-of-3";
    const json m = json::parse(read_text(dir / ("o/manifest" + tag + ".json")));
    EXPECT_EQ(m["counts"]["complete"], 6) << tag;
    for (const auto& run : m["runs"]) files.insert(run["file"].get<std::string>());
  }
  std::multiset<std::string> expected;
  for (const auto& run : sw.runs) expected.insert(run.file);
  EXPECT_EQ(files, expected);
  const Result all = wirepack(dir, "sweep s.json --out o");
  ASSERT_EQ(all.code, 0) << all.err;
  EXPECT_NE(all.err.find("(0 run now"), std::string::npos) << all.err;
  EXPECT_EQ(json::parse(read_text(dir / "o/manifest.json"))["counts"]["complete"], 18);
}

// Crash safety (issue 5): a sweep killed with SIGKILL mid-way and run again ends with every run
// complete, no duplicates, and the runs finished before the kill untouched.
TEST(CliSweep, KilledSweepResumes) {
  TempDir dir;
  // Eight runs of ~0.2 s on one thread.
  const std::string text = tiny_sweep(R"({"mu_s": [0]})", 8, 10, 0.5e-3);
  dir.write("s.json", text);
  const sweep::Sweep sw = parsed(text);
  const fs::path runs = dir.path() / "out/runs";

  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::chdir(dir.path().c_str()) != 0) ::_exit(127);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execl(WIREPACK_BINARY, WIREPACK_BINARY, "sweep", "s.json", "--out", "out", "--threads", "1",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Kill it as soon as the first run file is there.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  bool seen = false;
  while (!seen && std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(runs, ec))
      seen = seen || e.path().extension() == ".h5";
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(seen) << "no run file within 30 s";
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it was killed";

  std::map<std::string, std::pair<std::string, fs::file_time_type>> finished;
  for (const auto& r : sw.runs) {
    const std::string p = (dir.path() / "out" / r.file).string();
    if (fs::exists(p)) finished[r.file] = {read_text(p), fs::last_write_time(p)};
  }
  ASSERT_GE(finished.size(), 1u);
  ASSERT_LT(finished.size(), sw.runs.size()) << "every run finished before the kill";
  // A run that was being written when the node died leaves a partial file.
  for (const auto& r : sw.runs)
    if (!finished.contains(r.file)) {
      std::ofstream(dir / ("out/" + r.file + ".part")) << "partial";
      break;
    }

  const Result again = wirepack(dir, "sweep s.json --out out --threads 2");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("1 leftover .part file(s) removed"), std::string::npos) << again.err;

  std::set<std::string> on_disk;
  for (const auto& e : fs::directory_iterator(runs))
    on_disk.insert("runs/" + e.path().filename().string());
  std::set<std::string> expected;
  for (const auto& r : sw.runs) expected.insert(r.file);
  EXPECT_EQ(on_disk, expected);  // no .part, no duplicates, nothing missing
  for (const auto& r : sw.runs)
    EXPECT_EQ(sweep::read_run_file(dir / ("out/" + r.file)).status, sweep::RunStatus::Complete);
  for (const auto& [file, before] : finished) {
    const std::string p = dir / ("out/" + file);
    EXPECT_EQ(read_text(p), before.first) << file;
    EXPECT_EQ(fs::last_write_time(p), before.second) << file;
  }
  // The joblog has no run twice, and a line for every run of the second invocation (the killed
  // attempt never finished, so it has none; a run killed between its rename and its joblog line
  // has none either).
  const json m = json::parse(read_text(dir / "out/manifest.json"));
  EXPECT_EQ(m["counts"]["complete"], 8);
  std::istringstream log(read_text(dir / "out/joblog.csv"));
  std::multiset<std::string> ids;
  std::string line;
  std::getline(log, line);
  while (std::getline(log, line)) ids.insert(line.substr(0, line.find(',')));
  for (const auto& r : sw.runs)
    EXPECT_EQ(ids.count(r.id), finished.contains(r.file) ? ids.count(r.id) : 1u) << r.file;
  for (const auto& id : ids) EXPECT_EQ(ids.count(id), 1u) << id;
}

}  // namespace
}  // namespace wirepack
