// Full disk (issue 19, part 5), end to end: a sweep and a single run write into a file system
// that fills up. The runs that cannot be written fail with the reason ("No space left on
// device" / "File too large"), no final-named file is partial, the runs finished before are
// untouched, the sweep lists the failures and exits 1; once space is freed, the same command
// completes the sweep.
//
// Two ways to fill a disk: a 1 MiB tmpfs mounted in a private mount namespace (`unshare -m`,
// needs root or CAP_SYS_ADMIN: CI runs as root), and RLIMIT_FSIZE (`ulimit -f` with SIGXFSZ
// ignored, so a write past the limit fails with EFBIG), which works for any user. Where the
// mount is refused, the tmpfs test says so and checks the RLIMIT_FSIZE variant instead.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

// Six short rigid runs whose files grow with l_max (more rows, more and longer snapshots).
const char* kSweep = R"({"name": "full", "base": {"rho": 10, "mu_s": 0, "shell": "rigid",
    "numerics": "fast", "output": {"snapshots_every_l": 0.5}}, "grid": {"l_max": [1, 6]},
    "seeds": 3})";
const char* kScene = R"({"rho": 10, "mu_s": 0, "shell": "rigid", "l_max": 6,
    "numerics": "fast", "output": {"snapshots_every_l": 0.5}})";

enum class Limit { Tmpfs, FileSize };

int code_of(const TempDir& dir, const std::string& name) {
  return std::stoi(read_text(dir / name));
}

// Runs the scenario as one bash script (under `unshare -m` for a tmpfs); every step's exit
// code, stderr and a copy of the sweep directory land in `dir`. Returns the script's own exit
// code (77: the tmpfs could not be mounted).
int run_scenario(const TempDir& dir, Limit limit, std::size_t small_kb, std::size_t large_kb) {
  const std::string bin = "'" WIREPACK_BINARY "'";
  const std::string t = "'" + dir.path().string() + "'";
  std::ostringstream s;
  s << "set -u\ntrap '' XFSZ\ncd " << t << "\n";
  if (limit == Limit::Tmpfs) {
    // Room for every run file and the records, a filler leaving space for about one and a half
    // large run files in step 1, and no space at all in step 3.
    const std::size_t total_kb = 3 * (small_kb + large_kb) + 512;
    s << "mkdir -p mnt && mount -t tmpfs -o size=" << total_kb << "k tmpfs mnt || exit 77\n"
      << "W=mnt\nlimited() { \"$@\"; }\n"
      << "dd if=/dev/zero of=mnt/filler bs=1k count=" << total_kb - (large_kb * 3 / 2 + 64)
      << " 2>/dev/null\n"
      << "fill() { dd if=/dev/zero of=mnt/filler bs=1k count=" << total_kb
      << " 2>/dev/null; true; }\n";
  } else {
    // Every file may hold a small run, none a large one.
    s << "mkdir -p w\nW=w\nlimited() { ( ulimit -f " << (small_kb + large_kb) / 2
      << "; exec \"$@\" ); }\nfill() { true; }\n";
  }
  s << "limited " << bin << " sweep s.json --out $W/d --threads 2 >1.out 2>1.err; echo $? >1.code\n"
    << "cp -a $W/d after1\n"
    << "rm -f $W/filler\n"
    << bin << " sweep s.json --out $W/d --threads 2 >2.out 2>2.err; echo $? >2.code\n"
    << "cp -a $W/d after2\n"
    // A single run into a disk with no room for it.
    << "mkdir -p $W/r\nfill\n"
    << "limited " << bin << " run r.json --out $W/r/run.h5 >3.out 2>3.err; echo $? >3.code\n"
    << "ls -a $W/r >3.ls\n";
  dir.write("script.sh", s.str());
  dir.write("s.json", kSweep);
  dir.write("r.json", kScene);
  const std::string cmd = (limit == Limit::Tmpfs ? "unshare -m bash " : "bash ") + t +
                          "/script.sh >" + t + "/script.log 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Sizes of a small (l_max = 1) and a large (l_max = 6) run file [KiB, rounded up].
std::pair<std::size_t, std::size_t> run_file_sizes() {
  static std::pair<std::size_t, std::size_t> sizes = [] {
    TempDir dir;
    dir.write("s.json", kSweep);
    const std::string cmd = "cd '" + dir.path().string() +
                            "' && '" WIREPACK_BINARY
                            "' sweep s.json --out d --threads 2 >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    const auto sw = sweep::parse_sweep(json::parse(kSweep), "s.json");
    std::size_t small = 0, large = 0;
    for (const auto& r : sw.runs) {
      const std::size_t kb = (fs::file_size(dir / ("d/" + r.file)) + 1023) / 1024;
      auto& v = r.point_values.at("l_max") == 1 ? small : large;
      v = std::max(v, kb);
    }
    return std::pair{small, large};
  }();
  return sizes;
}

void check_scenario(const TempDir& dir, Limit limit) {
  const auto [small_kb, large_kb] = run_file_sizes();
  ASSERT_GT(large_kb, small_kb * 3 / 2) << small_kb << " KiB, " << large_kb << " KiB";
  const std::string reason = limit == Limit::Tmpfs ? "No space left on device" : "File too large";
  const auto sw = sweep::parse_sweep(json::parse(kSweep), "s.json");

  // 1. The disk fills: failures listed with the reason, exit 1, every final file whole.
  EXPECT_EQ(code_of(dir, "1.code"), 1) << read_text(dir / "1.err");
  const std::string err1 = read_text(dir / "1.err");
  EXPECT_NE(err1.find("  failed: "), std::string::npos) << err1;
  EXPECT_NE(err1.find(reason), std::string::npos) << err1;
  std::map<std::string, std::string> finished;  // file -> bytes, complete after step 1
  std::size_t failed = 0;
  for (const auto& r : sw.runs) {
    const std::string p = dir / ("after1/" + r.file);
    EXPECT_FALSE(fs::exists(p + ".part")) << p;
    if (!fs::exists(p)) {
      ++failed;
      // Listed on stderr.
      EXPECT_NE(err1.find("/d/" + r.file + ": "), std::string::npos) << err1;
      continue;
    }
    sweep::RunRecord rec;
    ASSERT_NO_THROW(rec = sweep::read_run_file(p)) << p;
    EXPECT_EQ(rec.status, sweep::RunStatus::Complete) << p;
    finished[r.file] = read_text(p);
  }
  EXPECT_GE(failed, 1u);
  std::cout << (limit == Limit::Tmpfs ? "tmpfs" : "RLIMIT_FSIZE") << ": " << finished.size()
            << " runs complete, " << failed << " failed with \"" << reason << "\" (small run file "
            << small_kb << " KiB, large " << large_kb << " KiB)" << std::endl;
  if (limit == Limit::FileSize) {
    // Deterministic: the small runs fit, the large ones do not.
    EXPECT_EQ(finished.size(), 3u);
    for (const auto& r : sw.runs)
      EXPECT_EQ(finished.contains(r.file), r.point_values.at("l_max") == 1) << r.file;
  } else {
    EXPECT_GE(finished.size(), 1u) << "nothing fitted: the tmpfs is too small";
  }

  // 2. Space freed: the same command completes the sweep; the finished runs are untouched.
  EXPECT_EQ(code_of(dir, "2.code"), 0) << read_text(dir / "2.err");
  for (const auto& r : sw.runs) {
    const std::string p = dir / ("after2/" + r.file);
    sweep::RunRecord rec;
    ASSERT_NO_THROW(rec = sweep::read_run_file(p)) << p;
    EXPECT_EQ(rec.status, sweep::RunStatus::Complete) << p;
    if (finished.contains(r.file)) {
      EXPECT_EQ(read_text(p), finished[r.file]) << p;
      EXPECT_EQ(fs::last_write_time(p), fs::last_write_time(dir / ("after1/" + r.file))) << p;
    }
    EXPECT_FALSE(fs::exists(p + ".part")) << p;
  }
  const json m = json::parse(read_text(dir / "after2/manifest.json"));
  EXPECT_EQ(m["counts"]["complete"], 6);
  for (const auto& e : fs::directory_iterator(dir.path() / "after2"))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();

  // 3. A single run that cannot be written: exit 1 with the reason, no file at all.
  EXPECT_EQ(code_of(dir, "3.code"), 1) << read_text(dir / "3.err");
  const std::string err3 = read_text(dir / "3.err");
  EXPECT_NE(err3.find(reason), std::string::npos) << err3;
  EXPECT_NE(err3.find("run.h5"), std::string::npos) << err3;
  EXPECT_EQ(read_text(dir / "3.ls"), ".\n..\n");
}

TEST(FullDisk, FileSizeLimit) {
  const auto [small_kb, large_kb] = run_file_sizes();
  TempDir dir;
  ASSERT_EQ(run_scenario(dir, Limit::FileSize, small_kb, large_kb), 0)
      << read_text(dir / "script.log");
  check_scenario(dir, Limit::FileSize);
}

TEST(FullDisk, TmpfsFillsUp) {
  const auto [small_kb, large_kb] = run_file_sizes();
  TempDir dir;
  const int rc = run_scenario(dir, Limit::Tmpfs, small_kb, large_kb);
  if (rc == 77) {
    std::cout << "tmpfs: mount refused here (" << read_text(dir / "script.log")
              << "); checked with RLIMIT_FSIZE instead" << std::endl;
    TempDir fallback;
    ASSERT_EQ(run_scenario(fallback, Limit::FileSize, small_kb, large_kb), 0)
        << read_text(fallback / "script.log");
    check_scenario(fallback, Limit::FileSize);
    return;
  }
  ASSERT_EQ(rc, 0) << read_text(dir / "script.log");
  check_scenario(dir, Limit::Tmpfs);
}

}  // namespace
}  // namespace wirepack
