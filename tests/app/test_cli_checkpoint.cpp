// Checkpoints end to end (docs/design.md §4.8): `wirepack run --checkpoint-every 0.05` is killed
// with SIGKILL as soon as a checkpoint exists, then again at a later checkpoint of the resumed
// run; the third invocation resumes, finishes, removes the checkpoint, and its run file is
// bitwise the file of a run never interrupted (every series but the wall time, every snapshot's
// wire and shell), on an elastic shell with friction (contact lists, friction springs, twist).
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "sanitizers.hpp"
#include "sweep/runfile/run_file.hpp"

namespace wirepack {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_wirepack;
using testing::TempDir;
using clock_type = std::chrono::steady_clock;

const char* kScene = R"({"rho": 10, "shell": "elastic", "xi": 10, "eps": 1000, "mu_s": 0.5,
    "l_max": 7, "numerics": "fast", "output": {"every_l": 0.1, "snapshots_every_l": 1}})";

// Starts `wirepack run s.json --out run.h5 --checkpoint-every 0.05` in `dir` (stderr to `log`)
// and kills it with SIGKILL once run.h5.ckpt exists with a modification time after `after`;
// returns that modification time, or -1 when the run ended first.
double run_until_checkpoint(const TempDir& dir, const std::string& log, double after) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.path().c_str()) != 0) ::_exit(127);
    if (!std::freopen(log.c_str(), "w", stderr) || !std::freopen("/dev/null", "w", stdout))
      ::_exit(127);
    ::execl(WIREPACK_BINARY, WIREPACK_BINARY, "run", "s.json", "--out", "run.h5",
            "--checkpoint-every", "0.05", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const std::string ckpt = dir / "run.h5.ckpt";
  const auto t0 = clock_type::now();
  for (;;) {
    struct stat st {};
    if (::stat(ckpt.c_str(), &st) == 0) {
      const double mtime = st.st_mtim.tv_sec + 1e-9 * st.st_mtim.tv_nsec;
      if (mtime > after) {
        ::kill(pid, SIGKILL);
        int status = 0;
        ::waitpid(pid, &status, 0);
        return WIFSIGNALED(status) ? mtime : -1;
      }
    }
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return -1;
    if (clock_type::now() - t0 > std::chrono::seconds(120)) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Every series but the wall time and every snapshot's wire, curvature and shell, bitwise.
void expect_same_run(const std::string& reference, const std::string& run) {
  SCOPED_TRACE(run);
  const sweep::RunRecord a = sweep::read_run_file(reference);
  const sweep::RunRecord b = sweep::read_run_file(run);
  EXPECT_EQ(b.status, sweep::RunStatus::Complete);
  ASSERT_EQ(a.series.size(), b.series.size());
  for (std::size_t c = 0; c < a.series.size(); ++c) {
    ASSERT_EQ(a.series[c].name, b.series[c].name);
    if (a.series[c].name == "wall_s") continue;
    ASSERT_EQ(a.series[c].values.size(), b.series[c].values.size()) << a.series[c].name;
    EXPECT_EQ(std::memcmp(a.series[c].values.data(), b.series[c].values.data(),
                          a.series[c].values.size() * sizeof(double)),
              0)
        << a.series[c].name;
  }
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    EXPECT_EQ(a.snapshots[k].wire, b.snapshots[k].wire) << k;
    EXPECT_EQ(a.snapshots[k].shell_vertices, b.snapshots[k].shell_vertices) << k;
    EXPECT_EQ(a.snapshots[k].curvature, b.snapshots[k].curvature) << k;
  }
}

// Starts `wirepack ARGS...` in `dir`, stderr into `log`, stdout to /dev/null.
pid_t start(const TempDir& dir, const std::string& log, std::vector<std::string> args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.path().c_str()) != 0) ::_exit(127);
    if (!std::freopen(log.c_str(), "w", stderr) || !std::freopen("/dev/null", "w", stdout))
      ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(WIREPACK_BINARY)};
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(WIREPACK_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

// Waits until `log` contains `text` (true) or the process exits or 60 s pass (false).
bool wait_for_text(pid_t pid, const std::string& log, const std::string& text) {
  const auto t0 = clock_type::now();
  while (clock_type::now() - t0 < std::chrono::seconds(60)) {
    if (read_text(log).find(text) != std::string::npos) return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

int exit_code(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CliCheckpoint, KilledRunResumesBitwise) {
  TempDir dir;
  dir.write("s.json", kScene);
  const auto ref = run_wirepack(dir, "run s.json --out ref.h5 --checkpoint-every 0");
  ASSERT_EQ(ref.code, 0) << ref.err;

  const double first = run_until_checkpoint(dir, dir / "log1", 0.0);
  ASSERT_GT(first, 0) << "the run ended before its first checkpoint: " << read_text(dir / "log1");
  ASSERT_FALSE(fs::exists(dir / "run.h5"));
  const double second = run_until_checkpoint(dir, dir / "log2", first);
  ASSERT_GT(second, 0) << read_text(dir / "log2");
  EXPECT_NE(read_text(dir / "log2").find("resumed from the checkpoint at l = "), std::string::npos)
      << read_text(dir / "log2");

  const auto last = run_wirepack(dir, "run s.json --out run.h5 --checkpoint-every 0.05");
  ASSERT_EQ(last.code, 0) << last.err;
  EXPECT_NE(last.err.find("resumed from the checkpoint at l = "), std::string::npos) << last.err;
  EXPECT_FALSE(fs::exists(dir / "run.h5.ckpt"));

  expect_same_run(dir / "ref.h5", dir / "run.h5");
  // The wall time goes on from the checkpoint: the resumed file's last wall time covers the
  // killed invocations' work up to their last checkpoints as well.
  EXPECT_GT(sweep::read_run_file(dir / "run.h5").find_series("wall_s")->values.back(), 0.0);
}

}  // namespace
}  // namespace wirepack

namespace wirepack {
namespace {

// SIGTERM (a batch system's time limit) stops a run at once with its checkpoint, whatever the
// checkpoint interval: exit 128 + 15, no run file; the same command resumes it bitwise.
TEST(CliCheckpoint, SigtermStopsARunWithItsCheckpoint) {
  TempDir dir;
  // kScene to l = 22: 5.4 s on one idle core (2026-12-04; l = 14 took 1.8 s there and ended
  // before its first progress line, every 2 s); under the sanitizers kScene's own l = 7 takes
  // ~100 s, long enough.
  std::string scene = kScene;
  if (!testing::kUnderSanitizers) scene.replace(scene.find("\"l_max\": 7"), 10, "\"l_max\": 22");
  dir.write("s.json", scene);
  const auto ref = run_wirepack(dir, "run s.json --out ref.h5 --checkpoint-every 0");
  ASSERT_EQ(ref.code, 0) << ref.err;

  const std::string log = dir / "log";
  const pid_t pid = start(dir, log, {"run", "s.json", "--out", "run.h5"});  // default interval
  ASSERT_TRUE(wait_for_text(pid, log, "ETA")) << read_text(log);  // a progress line, not the last
  ::kill(pid, SIGTERM);
  EXPECT_EQ(exit_code(pid), 128 + SIGTERM) << read_text(log);
  EXPECT_NE(read_text(log).find("checkpoint run.h5.ckpt written"), std::string::npos)
      << read_text(log);
  EXPECT_TRUE(fs::exists(dir / "run.h5.ckpt"));
  EXPECT_FALSE(fs::exists(dir / "run.h5"));
  EXPECT_FALSE(fs::exists(dir / "run.h5.part"));

  // The run part-way, from its checkpoint: the series so far are the first rows of the
  // finished run's (every column but the wall time), and its last snapshot has a profile.
  const auto part =
      run_wirepack(dir, "export run.h5.ckpt --csv part.csv --profile part_profile.csv");
  ASSERT_EQ(part.code, 0) << part.err;
  ASSERT_EQ(run_wirepack(dir, "export ref.h5 --csv ref.csv").code, 0);
  const auto rows = [](const std::string& text) {
    std::vector<std::vector<std::string>> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      out.emplace_back();
      std::istringstream cs(line);
      for (std::string cell; std::getline(cs, cell, ',');) out.back().push_back(cell);
    }
    return out;
  };
  const auto so_far = rows(read_text(dir / "part.csv"));
  const auto whole = rows(read_text(dir / "ref.csv"));
  ASSERT_GT(so_far.size(), 2u);  // the header and more than the row at l = 0
  ASSERT_LT(so_far.size(), whole.size());
  const auto wall = std::find(whole[0].begin(), whole[0].end(), "wall_s") - whole[0].begin();
  for (std::size_t i = 0; i < so_far.size(); ++i) {
    ASSERT_EQ(so_far[i].size(), whole[i].size()) << "row " << i;
    for (std::size_t c = 0; c < whole[i].size(); ++c) {
      if (i > 0 && static_cast<long>(c) == wall) continue;
      EXPECT_EQ(so_far[i][c], whole[i][c]) << "row " << i << ", column " << whole[0][c];
    }
  }
  EXPECT_NE(read_text(dir / "part_profile.csv").find("from_hole,s_R,kappa_R"), std::string::npos);
  // XDMF needs the run file's datasets: refused, exit 2, and the CSV asked beside it not written.
  const auto xdmf = run_wirepack(dir, "export run.h5.ckpt --csv x.csv --xdmf x.xmf");
  EXPECT_EQ(xdmf.code, 2);
  EXPECT_NE(xdmf.err.find("a checkpoint has no HDF5 datasets"), std::string::npos) << xdmf.err;
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
  EXPECT_FALSE(fs::exists(dir / "x.xmf"));

  const auto last = run_wirepack(dir, "run s.json --out run.h5");
  ASSERT_EQ(last.code, 0) << last.err;
  EXPECT_NE(last.err.find("resumed from the checkpoint at l = "), std::string::npos) << last.err;
  EXPECT_FALSE(fs::exists(dir / "run.h5.ckpt"));
  expect_same_run(dir / "ref.h5", dir / "run.h5");
}

// SIGINT (Ctrl-C) stops a sweep: no new run starts, the runs going keep their checkpoints and
// stay pending in the manifest, exit 128 + 2; rerunning finishes every run bitwise as a sweep
// never interrupted.
TEST(CliCheckpoint, SigintStopsASweep) {
  TempDir dir;
  dir.write("w.json", R"({"name": "w", "base": {"rho": 10, "shell": "rigid", "l_max": 10,
      "numerics": "fast"}, "grid": {"mu_s": [0, 0.5]}, "seeds": 2})");
  const auto ref = run_wirepack(dir, "sweep w.json --out ref --threads 2 --checkpoint-every 0");
  ASSERT_EQ(ref.code, 0) << ref.err;

  const std::string log = dir / "log";
  const pid_t pid = start(dir, log, {"sweep", "w.json", "--out", "out", "--threads", "2"});
  ASSERT_TRUE(wait_for_text(pid, log, "running 4 on 2 threads")) << read_text(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_code(pid), 128 + SIGINT) << read_text(log);
  EXPECT_NE(read_text(log).find("stopped by signal 2"), std::string::npos) << read_text(log);
  int checkpoints = 0, finished = 0;
  for (const auto& e : fs::directory_iterator(dir / "out/runs")) {
    checkpoints += e.path().extension() == ".ckpt";
    finished += e.path().extension() == ".h5";
  }
  EXPECT_GE(checkpoints, 1) << read_text(log);
  EXPECT_LT(finished, 4);
  const std::string manifest = read_text(dir / "out/manifest.json");
  EXPECT_NE(manifest.find("\"pending\": " + std::to_string(4 - finished)), std::string::npos)
      << manifest;

  // Start times have a resolution of 1 s: resume in a later second than the first start.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  const auto again = run_wirepack(dir, "sweep w.json --out out --threads 2");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("resumed from its checkpoint"), std::string::npos) << again.err;
  for (const auto& e : fs::directory_iterator(dir / "ref/runs"))
    expect_same_run(e.path(), dir / "out/runs" / e.path().filename());
  for (const auto& e : fs::directory_iterator(dir / "out/runs"))
    EXPECT_EQ(e.path().extension(), ".h5") << e.path();
  // The manifest says when each run started as its file does: a resumed run's first start, not
  // the resumption (rereading the files on a later resume must change nothing).
  const auto m = nlohmann::json::parse(read_text(dir / "out/manifest.json"));
  ASSERT_EQ(m.at("runs").size(), 4u);
  for (const auto& entry : m.at("runs")) {
    const std::string file = entry.at("file");
    EXPECT_EQ(entry.at("started").get<std::string>(),
              sweep::read_run_file(dir / ("out/" + file)).started)
        << file;
  }
}

}  // namespace
}  // namespace wirepack
