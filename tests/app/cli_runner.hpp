#pragma once
// Runs the wirepack executable (WIREPACK_BINARY, set by CMake for the test targets) as a user
// would, with a working directory, and captures its exit code and output. Shared by the CLI tests.
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "sweep/temp_dir.hpp"

namespace wirepack::testing {

struct CliResult {
  int code = -1;         // exit status, -1 if killed by a signal
  std::string out, err;  // stdout, stderr
};

// Runs `ENV wirepack ARGS` with `dir` as working directory (ENV: "NAME=value ..." or empty).
inline CliResult run_wirepack(const TempDir& dir, const std::string& args,
                              const std::string& env = "") {
  TempDir logs;
  const std::string cmd = "cd '" + dir.path().string() + "' && " + env + " '" WIREPACK_BINARY "' " +
                          args + " >'" + (logs / "out") + "' 2>'" + (logs / "err") + "'";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(logs / "out");
  r.err = read_text(logs / "err");
  return r;
}

}  // namespace wirepack::testing
