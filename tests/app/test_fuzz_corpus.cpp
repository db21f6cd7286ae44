// The fuzz corpus (tests/fuzz/corpus, issue 19 part 3) through the CLI: every valid_*.json
// validates (exit 0); every bad_*.json gives exit 2 from `validate`, `run` and `sweep`, a first
// message that names the file and the JSON pointer of the key (a line and column for the
// bad_syntax_* files, which do not parse), nothing on stdout, and no file written.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli_runner.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

using Result = wirepack::testing::CliResult;

// Runs `wirepack ARGS` in `dir` (cli_runner.hpp).
Result wirepack(const TempDir& dir, const std::string& args) {
  return wirepack::testing::run_wirepack(dir, args);
}

std::vector<fs::path> corpus(const std::string& prefix) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(WIREPACK_SOURCE_DIR "/tests/fuzz/corpus"))
    if (e.path().filename().string().rfind(prefix, 0) == 0) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(FuzzCorpus, HasAtLeast40Files) {
  EXPECT_GE(corpus("valid_").size() + corpus("bad_").size(), 40u);
  EXPECT_GE(corpus("valid_").size(), 10u);
  EXPECT_GE(corpus("bad_").size(), 30u);
}

TEST(FuzzCorpus, ValidFilesValidate) {
  for (const auto& f : corpus("valid_")) {
    TempDir dir;
    const std::string name = f.filename().string();
    fs::copy_file(f, dir.path() / name);
    const Result r = wirepack(dir, "validate " + name);
    EXPECT_EQ(r.code, 0) << name << ": " << r.err;
  }
}

TEST(FuzzCorpus, MalformedFilesExit2NameFileAndPointerWriteNothing) {
  for (const auto& f : corpus("bad_")) {
    const std::string name = f.filename().string();
    const bool syntax = name.rfind("bad_syntax_", 0) == 0;
    for (const std::string& cmd :
         {"validate " + name, "run " + name + " --out x.h5", "sweep " + name + " --out o"}) {
      SCOPED_TRACE(cmd);
      TempDir dir;
      fs::copy_file(f, dir.path() / name);
      const Result r = wirepack(dir, cmd);
      EXPECT_EQ(r.code, 2) << r.err;
      EXPECT_EQ(r.out, "");
      // The first message: `FILE: /pointer: rule` (or `FILE: line L, column C: ...`).
      EXPECT_EQ(r.err.rfind(name + (syntax ? ": line " : ": /"), 0), 0u) << r.err;
      std::vector<std::string> left;
      for (const auto& e : fs::directory_iterator(dir.path()))
        left.push_back(e.path().filename().string());
      EXPECT_EQ(left, std::vector<std::string>{name});
    }
  }
}

}  // namespace
}  // namespace wirepack
