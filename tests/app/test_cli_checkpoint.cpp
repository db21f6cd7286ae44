// Checkpoints end to end (docs/design.md §4.8): `wirepack run --checkpoint-every 0.05` is killed
// with SIGKILL as soon as a checkpoint exists, then again at a later checkpoint of the resumed
// run; the third invocation resumes, finishes, removes the checkpoint, and its run file is
// bitwise the file of a run never interrupted (every series but the wall time, every snapshot's
// wire and shell), on an elastic shell with friction (contact lists, friction springs, twist).
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "sweep/run_file.hpp"

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

  const sweep::RunRecord a = sweep::read_run_file(dir / "ref.h5");
  const sweep::RunRecord b = sweep::read_run_file(dir / "run.h5");
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
  // The wall time goes on from the checkpoint: the resumed file's last wall time covers the
  // killed invocations' work up to their last checkpoints as well.
  EXPECT_GT(b.find_series("wall_s")->values.back(), 0.0);
}

}  // namespace
}  // namespace wirepack
