// Corrupt inputs to `wirepack analyze` and `wirepack export` (issue 19, part 6), end to end: a
// truncated run file, a `.part` leftover, a run file of a newer wirepack, one without a required
// dataset, one that is not HDF5, and directories with no runs. Each bad file gets its own
// message, the rest is analysed (exit 0); export refuses a bad file with exit 2 and writes
// nothing; a directory with no runs is bad input (exit 2, nothing written).
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
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
Result wirepack(const TempDir& dir, const std::string& args) {
  return wirepack::testing::run_wirepack(dir, args);
}

// Six short rigid runs (l = 1, fast numerics): one seed per kind of damage below.
const char* kSweep = R"({"name": "c", "base": {"rho": 10, "mu_s": 0, "shell": "rigid",
    "l_max": 1, "numerics": "fast"}, "grid": {}, "seeds": 6})";

// Every file name in `dir` (recursively), relative to it.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    out.push_back(fs::relative(e.path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

// The lines of `text` that contain `what`.
std::size_t lines_with(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.find(what) != std::string::npos;
  return n;
}

class CorruptInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("s.json", kSweep);
    const Result r = wirepack(dir, "sweep s.json --out d --threads 2");
    ASSERT_EQ(r.code, 0) << r.err;
    const sweep::Sweep sw = sweep::parse_sweep(json::parse(kSweep), "s.json");
    ASSERT_EQ(sw.runs.size(), 6u);
    for (const auto& run : sw.runs) files.push_back(dir / ("d/" + run.file));

    // 0: truncated to half its size (a copy cut short, a disk that lost its tail).
    fs::resize_file(files[0], fs::file_size(files[0]) / 2);
    // 1: only a .part left (killed while it was written).
    fs::rename(files[1], files[1] + ".part");
    // 2: written by a wirepack from the future.
    sweep::RunRecord rec = sweep::read_run_file(files[2]);
    rec.version = "99.0.0";
    sweep::write_run_file(rec, files[2]);
    // 3: a required dataset missing (/series/l).
    rec = sweep::read_run_file(files[3]);
    rec.series.erase(rec.series.begin());
    ASSERT_EQ(rec.series.front().name, "U_b_hat");
    sweep::write_run_file(rec, files[3]);
    // 4: not HDF5 at all.
    std::ofstream(files[4], std::ios::trunc) << "not a run file\n";
    // 5: intact.
  }

  TempDir dir;
  std::vector<std::string> files;  // absolute paths, in run order
};

TEST_F(CorruptInputs, AnalyzeNamesEachBadFileAndAnalysesTheRest) {
  const Result r = wirepack(dir, "analyze d --no-plots --resamples 0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("6 runs, 1 complete, 5 skipped"), std::string::npos) << r.err;
  // One line per bad file, naming it and saying what is wrong.
  const std::vector<std::pair<std::size_t, std::string>> why = {{0, "truncated file"},
                                                                {1, "only a .part file"},
                                                                {2, "newer than this wirepack"},
                                                                {3, "/series/l is missing"},
                                                                {4, "file signature not found"}};
  for (const auto& [i, reason] : why) {
    const std::string name = fs::path(files[i]).filename().string();
    EXPECT_EQ(lines_with(r.err, name), 1u) << name << "\n" << r.err;
    EXPECT_EQ(lines_with(r.err, reason), 1u) << reason << "\n" << r.err;
    std::istringstream in(r.err);
    for (std::string line; std::getline(in, line);)
      if (line.find(name) != std::string::npos) {
        EXPECT_NE(line.find(reason), std::string::npos) << line;
      }
  }
  // The intact run is analysed: one complete run at the one grid point.
  const std::string runs = read_text(dir / "d/analysis/runs.csv");
  EXPECT_EQ(lines_with(runs, ",complete,"), 1u) << runs;
  EXPECT_EQ(lines_with(runs, ",unreadable,"), 4u) << runs;
  EXPECT_EQ(lines_with(runs, ",missing,"), 1u) << runs;
  EXPECT_TRUE(fs::exists(dir / "d/analysis/curves.csv"));

  // The sweep itself runs the damaged ones again (each with a warning) and keeps the intact one.
  const Result s = wirepack(dir, "sweep s.json --out d --threads 2");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(lines_with(s.err, "unreadable ("), 4u) << s.err;
  EXPECT_NE(s.err.find("1 leftover .part file(s) removed"), std::string::npos) << s.err;
  EXPECT_NE(s.err.find("(5 run now"), std::string::npos) << s.err;
  const Result again = wirepack(dir, "analyze d --no-plots --resamples 0");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("6 runs, 6 complete, 0 skipped"), std::string::npos) << again.err;
}

TEST_F(CorruptInputs, ExportRefusesEachBadFileAndWritesNothing) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {files[0], "truncated file"},
      {files[1] + ".part", "a partial run file"},
      {files[1], "unable to open file"},
      {files[2], "written by wirepack 99.0.0, newer than this wirepack"},
      {files[3], "required dataset /series/l is missing"},
      {files[4], "file signature not found"}};
  const auto before = listing(dir.path());
  for (const auto& [file, reason] : bad) {
    SCOPED_TRACE(file);
    const Result r = wirepack(dir, "export '" + file + "' --csv x.csv --xdmf x.xmf");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_EQ(listing(dir.path()), before);  // no x.csv, no x.csv.tmp, no x.xmf
  }
  const Result ok = wirepack(dir, "export '" + files[5] + "' --csv x.csv");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(read_text(dir / "x.csv").rfind("l,U_b_hat,", 0), 0u);
}

TEST(CorruptInputsDirs, DirectoryWithNoRunsExit2AndWritesNothing) {
  TempDir dir;
  fs::create_directories(dir.path() / "empty");
  fs::create_directories(dir.path() / "sweepish/runs");
  dir.write("sweepish/runs/notes.txt", "no run files here\n");
  dir.write("sweepish/runs/x.h5.tmp", "");
  for (const std::string d : {"empty", "sweepish", "nowhere"}) {
    SCOPED_TRACE(d);
    const auto before = listing(dir.path());
    const Result r = wirepack(dir, "analyze " + d + " --no-plots");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind(d + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(d == "nowhere" ? "no such directory" : "no run files"), std::string::npos)
        << r.err;
    EXPECT_EQ(listing(dir.path()), before);
  }
}

}  // namespace
}  // namespace wirepack
