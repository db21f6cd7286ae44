// `wirepack refine` end to end on a real tiny sweep (rigid sphere, fast preset, l_max = 4, runs
// of a few hundredths of a second): it adds points, records them in DIR/refine.json, runs them
// with the sweep's seeds, resumes after SIGKILL, and bad input exits 2 with nothing written.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <thread>

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
Result wirepack(const TempDir& dir, const std::string& args) {
  return wirepack::testing::run_wirepack(dir, args);
}

// mu_s = 0, 0.5, 1 x 2 seeds on the rigid sphere, D over l in [1, 4].
constexpr const char* kSweep = R"({"name": "tiny",
  "base": {"rho": 20, "shell": "rigid", "l_max": 4, "numerics": "fast"},
  "grid": {"mu_s": [0, 0.5, 1.0]}, "seeds": 2, "analysis": {"D_window": [1, 4]}})";

// A finished tiny sweep in DIR/out.
void make_sweep(const TempDir& dir) {
  dir.write("s.json", kSweep);
  const Result r = wirepack(dir, "sweep s.json --out out --threads 1");
  ASSERT_EQ(r.code, 0) << r.err;
}

sweep::Sweep refined_sweep(const TempDir& dir) {
  return sweep::load_sweep(dir / "out/refine.json");
}

TEST(CliRefine, OneRoundAddsPointsWithTheSameSeeds) {
  TempDir dir;
  make_sweep(dir);
  const Result r = wirepack(dir, "refine out --runs 4 --threads 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("refine.json"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("one round done"), std::string::npos) << r.err;
  const sweep::Sweep sw = refined_sweep(dir);
  ASSERT_EQ(sw.listed_points.size(), 2u);  // 4 runs = 2 points x 2 seeds
  EXPECT_EQ(sw.seeds, (std::vector<std::uint64_t>{1, 2}));
  // Before a fit (3 values): inside the range, between the grid's values.
  for (const auto& p : sw.listed_points) {
    const double mu = p[0].get<double>();
    EXPECT_GT(mu, 0);
    EXPECT_LT(mu, 1);
    EXPECT_NE(mu, 0.5);
  }
  for (const auto& run : sw.runs)
    EXPECT_EQ(sweep::read_run_file(dir / ("out/" + run.file)).status, sweep::RunStatus::Complete)
        << run.file;
  const json m = json::parse(read_text(dir / "out/manifest.json"));
  EXPECT_EQ(m["counts"]["complete"], 10);
  EXPECT_EQ(m["sweep"]["points"].size(), 2u);
  // The log has a line for the round that added them and the one that stopped.
  const std::string log = read_text(dir / "out/refine_log.csv");
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 3);

  // analyze reads the listed points like grid points.
  const Result a = wirepack(dir, "analyze out --no-plots");
  ASSERT_EQ(a.code, 0) << a.err;
  const std::string crit = read_text(dir / "out/analysis/critical.csv");
  EXPECT_NE(crit.find("\nmu_s,,linear,5,10,0,0,0,1,"), std::string::npos) << crit;
}

// Killed with SIGKILL in the middle of its runs, refine run again completes the budget: every
// listed point's runs complete, none twice, the runs finished before the kill untouched.
TEST(CliRefine, KilledRefineResumes) {
  TempDir dir;
  make_sweep(dir);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::chdir(dir.path().c_str()) != 0) ::_exit(127);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execl(WIREPACK_BINARY, WIREPACK_BINARY, "refine", "out", "--runs", "4", "--budget", "16",
            "--threads", "1", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Kill it as soon as the first run of a listed point is finished.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool seen = false;
  while (!seen && std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    if (fs::exists(dir / "out/refine.json", ec)) {
      try {
        for (const auto& run : refined_sweep(dir).runs)
          if (run.point >= 3 && fs::exists(dir / ("out/" + run.file), ec)) seen = true;
      } catch (const std::exception&) {
      }
    }
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(seen) << "no refined run within 60 s";
  ASSERT_TRUE(WIFSIGNALED(status)) << "refine ended before it was killed";

  std::map<std::string, fs::file_time_type> finished;
  std::size_t listed_before = 0;
  {
    const sweep::Sweep sw = refined_sweep(dir);
    listed_before = sw.listed_points.size();
    for (const auto& run : sw.runs)
      if (fs::exists(dir / ("out/" + run.file)))
        finished[run.file] = fs::last_write_time(dir / ("out/" + run.file));
    ASSERT_LT(finished.size(), sw.runs.size()) << "every run finished before the kill";
  }

  const Result again = wirepack(dir, "refine out --runs 4 --budget 16 --threads 1");
  ASSERT_EQ(again.code, 0) << again.err;
  const sweep::Sweep sw = refined_sweep(dir);
  EXPECT_GE(sw.listed_points.size(), listed_before);
  EXPECT_LE(sw.listed_points.size() * 2, 16u);
  EXPECT_TRUE(again.err.find("run budget reached") != std::string::npos ||
              again.err.find("no new value") != std::string::npos)
      << again.err;
  std::set<std::string> expected, on_disk;
  for (const auto& run : sw.runs) expected.insert(run.file);
  for (const auto& e : fs::directory_iterator(dir / "out/runs"))
    on_disk.insert("runs/" + e.path().filename().string());
  EXPECT_EQ(on_disk, expected);  // no .part, nothing missing, nothing twice
  for (const auto& run : sw.runs)
    EXPECT_EQ(sweep::read_run_file(dir / ("out/" + run.file)).status, sweep::RunStatus::Complete)
        << run.file;
  for (const auto& [file, time] : finished)
    EXPECT_EQ(fs::last_write_time(dir / ("out/" + file)), time) << file;

  // Once the budget is spent, a rerun adds nothing.
  const Result third = wirepack(dir, "refine out --runs 4 --budget 16 --threads 1");
  ASSERT_EQ(third.code, 0) << third.err;
  EXPECT_EQ(refined_sweep(dir).listed_points.size(), sw.listed_points.size());
  EXPECT_NE(third.err.find("0 rounds added 0 runs"), std::string::npos) << third.err;
}

// --add seeds: new seeds (numbered after the sweep's) at grid values near the transition, run and
// recorded in refine.json's extra_seeds; analyze counts them with their points.
TEST(CliRefine, AddSeedsRunsNewSeedsAtExistingPoints) {
  TempDir dir;
  make_sweep(dir);
  const Result r = wirepack(dir, "refine out --add seeds --runs 4 --threads 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("adding seeds 3"), std::string::npos) << r.err;
  const sweep::Sweep sw = refined_sweep(dir);
  EXPECT_TRUE(sw.listed_points.empty());
  ASSERT_FALSE(sw.extra_seeds.empty());
  std::size_t extra = 0;
  for (const auto& e : sw.extra_seeds) {
    EXPECT_LT(e.point, 3u);  // grid points
    ASSERT_FALSE(e.seeds.empty());
    EXPECT_EQ(e.seeds.front(), 3u);
    extra += e.seeds.size();
  }
  EXPECT_LE(extra, 4u);
  ASSERT_EQ(sw.runs.size(), 6u + extra);
  for (const auto& run : sw.runs)
    EXPECT_EQ(sweep::read_run_file(dir / ("out/" + run.file)).status, sweep::RunStatus::Complete)
        << run.file;
  const json m = json::parse(read_text(dir / "out/manifest.json"));
  EXPECT_EQ(m["counts"]["complete"], 6 + static_cast<int>(extra));
  EXPECT_EQ(m["sweep"]["extra_seeds"].size(), sw.extra_seeds.size());
  EXPECT_NE(read_text(dir / "out/refine_log.csv").find(",seeds 3"), std::string::npos);
  // The points with an extra seed have 3 seeds in the analysis.
  const Result a = wirepack(dir, "analyze out --no-plots");
  ASSERT_EQ(a.code, 0) << a.err;
  const std::string curve = read_text(dir / "out/analysis/D_vs_mu_s.csv");
  EXPECT_NE(curve.find(",3,"), std::string::npos) << curve;
}

TEST(CliRefine, BadInputExits2AndWritesNothing) {
  TempDir dir;
  make_sweep(dir);
  const auto listing = [&] {
    std::set<std::string> s;
    for (const auto& e : fs::recursive_directory_iterator(dir.path())) s.insert(e.path().string());
    return s;
  };
  const auto before = listing();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"refine nowhere", "nowhere: no such directory"},
      {"refine .", ".: no manifest.json and no refine.json: not a sweep directory"},
      {"refine out --axis rho",
       "--axis: rho is not a swept transition parameter of out (swept: "
       "mu_s)"},
      {"refine out --until-ci 0", "--until-ci: must be a width > 0"},
      {"refine out --budget -4", "--budget: must be >= 0 runs"},
      {"refine out --runs 0", "--runs"},
      {"refine out --add more", "--add"},
  };
  for (const auto& [args, message] : cases) {
    SCOPED_TRACE(args);
    const Result r = wirepack(dir, args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(listing(), before);
  }
}

}  // namespace
}  // namespace wirepack
