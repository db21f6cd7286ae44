// Kill campaign (issue 19, part 4): a small sweep is killed with SIGKILL at pseudo-random
// moments (fixed seed) and resumed each time, until at least kKills kills. Four kinds of
// moment, in turn: after a random delay in the range of the sweep's duration; when the n-th run
// file is created as NAME.h5.part (inside run-file writes); when the n-th manifest temporary
// is created (inside manifest rewrites); when the n-th run checkpoint temporary is created
// (inside checkpoint writes: the sweep checkpoints its runs every 20 ms, so most kills also
// leave checkpoints that the next invocation resumes from); the last three are seen through
// inotify, no environment variable or hook in wirepack. After every kill each final-named run
// file must be whole and each checkpoint readable; at the end of every round every run is
// complete with series and snapshots bitwise equal to an uninterrupted sweep without
// checkpoints, no .part, checkpoint or temporary is left, and the manifest and joblog agree
// with the files (one joblog line per run).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/run_checkpoint.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using clock_type = std::chrono::steady_clock;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

constexpr int kKills = 24;   // at least this many SIGKILLs in all
constexpr int kRounds = 40;  // at most this many rounds (fresh directories; ~3 kills each)

// Eight runs of a few tenths of a second: rigid, fast numerics, with and without friction.
const char* kSweep = R"({"name": "kill", "base": {"rho": 10, "shell": "rigid", "l_max": 8,
    "numerics": "fast"}, "grid": {"mu_s": [0, 0.5]}, "seeds": 4})";

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Starts `wirepack sweep s.json --out OUT --threads 2 --checkpoint-every EVERY` in `cwd`,
// output into `log`.
pid_t start_sweep(const fs::path& cwd, const std::string& out, const std::string& log,
                  const char* checkpoint_every) {
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  if (::chdir(cwd.c_str()) != 0) ::_exit(127);
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(fd, STDOUT_FILENO);
  ::dup2(fd, STDERR_FILENO);
  // A lower priority than the test, so the test's kill lands while the sweep is still inside
  // the write it was notified of.
  if (::nice(5) == -1) {
  }
  ::execl(WIREPACK_BINARY, WIREPACK_BINARY, "sweep", "s.json", "--out", out.c_str(), "--threads",
          "2", "--checkpoint-every", checkpoint_every, static_cast<char*>(nullptr));
  ::_exit(127);
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) out.push_back(e.path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

// Series except wall_s, and snapshots, compared bitwise.
void expect_bitwise_equal(const sweep::RunRecord& a, const sweep::RunRecord& b,
                          const std::string& what) {
  ASSERT_EQ(a.series.size(), b.series.size()) << what;
  for (std::size_t c = 0; c < a.series.size(); ++c) {
    const auto& x = a.series[c];
    const auto& y = b.series[c];
    ASSERT_EQ(x.name, y.name) << what;
    if (x.name == "wall_s") continue;
    ASSERT_EQ(x.values.size(), y.values.size()) << what << " " << x.name;
    EXPECT_EQ(std::memcmp(x.values.data(), y.values.data(), x.values.size() * sizeof(double)), 0)
        << what << " " << x.name;
  }
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size()) << what;
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    const auto& x = a.snapshots[k].wire;
    const auto& y = b.snapshots[k].wire;
    ASSERT_EQ(x.size(), y.size()) << what << " snapshot " << k;
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])), 0)
        << what << " snapshot " << k;
  }
}

TEST(KillCampaign, SweepSurvivesSigkillAtRandomMoments) {
  TempDir dir;
  dir.write("s.json", kSweep);
  const sweep::Sweep sw = sweep::parse_sweep(json::parse(kSweep), "s.json");
  ASSERT_EQ(sw.runs.size(), 8u);

  // The uninterrupted reference, and its duration (the range of the random delays).
  const auto t_ref0 = clock_type::now();
  const pid_t ref = start_sweep(dir.path(), "ref", dir / "ref.log", "0");
  int status = 0;
  ASSERT_EQ(::waitpid(ref, &status, 0), ref);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "ref.log");
  const double t_ref = std::chrono::duration<double>(clock_type::now() - t_ref0).count();
  std::map<std::string, sweep::RunRecord> reference;
  for (const auto& r : sw.runs) reference[r.file] = sweep::read_run_file(dir / ("ref/" + r.file));

  std::mt19937_64 rng(19);
  int kills = 0, during_part = 0, during_manifest = 0, during_checkpoint = 0, invocations = 0,
      rounds = 0, resumed = 0;
  int by_kind[4] = {0, 0, 0, 0};
  while (kills < kKills && rounds < kRounds) {
    const std::string out = "k" + std::to_string(rounds++);
    const fs::path root = dir.path() / out;
    fs::create_directories(root / "runs");
    for (int attempt = 0;; ++attempt) {
      ASSERT_LT(attempt, 60) << out << ": no progress after 60 invocations";
      // 0: delay, 1: n-th .part, 2: n-th manifest temporary, 3: n-th checkpoint temporary
      const int kind = kills % 4;
      const int nth = std::uniform_int_distribution<int>(1, 3)(rng);
      const double delay = std::uniform_real_distribution<double>(0, t_ref)(rng);

      const int ifd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
      ASSERT_GE(ifd, 0);
      ASSERT_GE(::inotify_add_watch(ifd, root.c_str(), IN_CREATE), 0);
      ASSERT_GE(::inotify_add_watch(ifd, (root / "runs").c_str(), IN_CREATE), 0);
      const auto t0 = clock_type::now();
      const pid_t pid = start_sweep(dir.path(), out, dir / "sweep.log", "0.02");
      ASSERT_GT(pid, 0);
      ++invocations;
      int seen = 0;
      bool killed = false, exited = false;
      while (!killed && !exited) {
        pollfd p{ifd, POLLIN, 0};
        ::poll(&p, 1, 1);
        alignas(inotify_event) char buf[4096];
        for (ssize_t n; (n = ::read(ifd, buf, sizeof(buf))) > 0;)
          for (char* q = buf; q < buf + n;) {
            const auto* ev = reinterpret_cast<const inotify_event*>(q);
            const std::string name = ev->len ? ev->name : "";
            if ((kind == 1 && ends_with(name, ".h5.part")) ||
                (kind == 2 && name.rfind("manifest.json.tmp.", 0) == 0) ||
                (kind == 3 && name.find(".h5.ckpt.tmp.") != std::string::npos))
              ++seen;
            q += sizeof(inotify_event) + ev->len;
          }
        const double t = std::chrono::duration<double>(clock_type::now() - t0).count();
        if ((kind == 0 && t >= delay) || (kind != 0 && seen >= nth)) {
          killed = ::kill(pid, SIGKILL) == 0;
        } else if (t > 120) {
          ::kill(pid, SIGKILL);
          FAIL() << out << ": a sweep of 8 short runs still running after 120 s";
        }
        exited = ::waitpid(pid, &status, killed ? 0 : WNOHANG) == pid;
      }
      ::close(ifd);
      // Runs this invocation resumed from their checkpoints.
      const std::string log_text = read_text(dir / "sweep.log");
      for (std::size_t at = 0;
           (at = log_text.find("resumed from its checkpoint", at)) != std::string::npos; ++at)
        ++resumed;
      EXPECT_EQ(log_text.find("checkpoint not"), std::string::npos) << log_text;
      if (exited && !WIFSIGNALED(status)) {
        // Finished before the kill: the round is over.
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "sweep.log");
        break;
      }
      ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
      ++kills;
      ++by_kind[kind];
      // What the kill interrupted, and the invariants: a final-named file is always whole, a
      // checkpoint always readable.
      bool part = false, tmp = false, ckpt_tmp = false;
      for (const auto& n : names_in(root / "runs")) {
        if (ends_with(n, ".part")) {
          part = true;
          continue;
        }
        if (n.find(".h5.ckpt.tmp.") != std::string::npos) {
          ckpt_tmp = true;
          continue;
        }
        if (ends_with(n, ".h5.ckpt")) {
          EXPECT_NO_THROW(sweep::read_checkpoint((root / "runs" / n).string())) << n;
          continue;
        }
        const std::string file = (root / "runs" / n).string();
        EXPECT_NO_THROW({
          const auto rec = sweep::read_run_file(file);
          EXPECT_EQ(rec.status, sweep::RunStatus::Complete) << file;
        }) << file;
      }
      for (const auto& n : names_in(root)) tmp = tmp || n.rfind("manifest.json.tmp.", 0) == 0;
      during_part += part;
      during_manifest += tmp;
      during_checkpoint += ckpt_tmp;
    }

    // The round's end state.
    SCOPED_TRACE(out);
    std::set<std::string> expected_runs;
    for (const auto& r : sw.runs) {
      expected_runs.insert(fs::path(r.file).filename());
      expect_bitwise_equal(sweep::read_run_file(root / r.file), reference[r.file], r.file);
    }
    const auto runs_on_disk = names_in(root / "runs");
    EXPECT_EQ(std::set<std::string>(runs_on_disk.begin(), runs_on_disk.end()), expected_runs);
    EXPECT_EQ(names_in(root),
              (std::vector<std::string>{".lock", "joblog.csv", "manifest.json", "runs"}));
    const json m = json::parse(read_text((root / "manifest.json").string()));
    EXPECT_EQ(m["counts"],
              (json{{"runs", 8}, {"pending", 0}, {"running", 0}, {"complete", 8}, {"failed", 0}}));
    for (const auto& r : m["runs"]) {
      EXPECT_EQ(r["status"], "complete") << r["file"];
      EXPECT_TRUE(fs::exists(root / r["file"].get<std::string>())) << r["file"];
    }
    // One joblog line per run, complete, with 8 fields; nothing else.
    std::istringstream log(read_text((root / "joblog.csv").string()));
    std::string line;
    std::getline(log, line);
    EXPECT_EQ(line, "id,file,start,end,wall_s,status,reason,shard");
    std::multiset<std::string> ids;
    while (std::getline(log, line)) {
      EXPECT_EQ(std::count(line.begin(), line.end(), ','), 7) << line;
      EXPECT_NE(line.find(",complete,"), std::string::npos) << line;
      ids.insert(line.substr(0, line.find(',')));
    }
    std::multiset<std::string> expected_ids;
    for (const auto& r : sw.runs) expected_ids.insert(r.id);
    EXPECT_EQ(ids, expected_ids);
    if (::testing::Test::HasFailure()) break;
  }
  std::cout << "kill campaign: " << kills << " SIGKILLs survived in " << rounds << " rounds, "
            << invocations << " invocations (" << by_kind[0] << " after a random delay, "
            << by_kind[1] << " at a run-file creation, " << by_kind[2] << " at a manifest rewrite, "
            << by_kind[3] << " at a checkpoint write); " << during_part
            << " left a .part on disk (inside a run-file write), " << during_manifest
            << " a manifest temporary (inside a manifest rewrite), " << during_checkpoint
            << " a checkpoint temporary; " << resumed
            << " runs resumed from checkpoints; reference sweep " << t_ref << " s" << std::endl;
  EXPECT_GE(kills, kKills);
  EXPECT_GE(during_part, 1);
  EXPECT_GE(during_manifest, 1);
  EXPECT_GE(during_checkpoint, 1);
  EXPECT_GE(resumed, 1);
}

}  // namespace
}  // namespace wirepack
