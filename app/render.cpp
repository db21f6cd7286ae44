#include "app/render.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "sweep/errors.hpp"
#include "sweep/runfile/run_file.hpp"

extern char** environ;

namespace wirepack::app {

namespace {

namespace fs = std::filesystem;
using sweep::InputError;

#ifndef WIREPACK_SOURCE_DIR
#define WIREPACK_SOURCE_DIR "."
#endif
#ifndef WIREPACK_XOPEN_RETRY
#define WIREPACK_XOPEN_RETRY ""
#endif

bool ends_with(std::string s, const std::string& suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool executable(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

bool is_file(const std::string& path) {
  std::error_code ec;
  return !path.empty() && fs::is_regular_file(path, ec);
}

// `name` on PATH, or "".
std::string find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = dirs.substr(start, end - start);
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (executable(candidate)) return candidate;
    start = end + 1;
  }
  return "";
}

std::string pvbatch_program() {
  const char* env = std::getenv("WIREPACK_PVBATCH");
  if (env && *env) return executable(env) ? env : "";
  return find_program("pvbatch");
}

std::string source_dir() {
  const char* env = std::getenv("WIREPACK_SOURCE_DIR");
  return env && *env ? env : WIREPACK_SOURCE_DIR;
}

// Runs argv[0] (searched on PATH) with the child's stdout sent to stderr (a renderer's chatter
// never mixes with the paths this command prints); returns its exit status (-1: not run or
// killed).
int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void remove_quietly(const std::string& path) {
  std::error_code ec;
  fs::remove(path, ec);
}

// Renames `tmp` to `path`; false (and `tmp` removed) when it does not exist or cannot be renamed.
bool publish(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(tmp, ec) || fs::file_size(tmp, ec) == 0) {
    remove_quietly(tmp);
    return false;
  }
  fs::rename(tmp, path, ec);
  if (ec) remove_quietly(tmp);
  return !ec;
}

// ParaView: scripts/render_paraview.py writes and renames the outputs itself.
int render_paraview(const RenderOptions& o, const std::string& pvbatch, int snapshot,
                    std::ostream& log) {
  std::vector<std::string> cmd;
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) {
    if (find_program("xvfb-run").empty()) {
      log << "wirepack render: no display and no xvfb-run (scripts/install_paraview.sh installs "
             "it); trying pvbatch off-screen\n";
    } else {
      cmd = {"xvfb-run", "-a", "-s", "-screen 0 1920x1440x24"};
      // Xvfb here drops some new connections; pvbatch gets an XOpenDisplay that retries.
      if (is_file(WIREPACK_XOPEN_RETRY))
        cmd.insert(cmd.end(), {"env", std::string("LD_PRELOAD=") + WIREPACK_XOPEN_RETRY});
    }
  }
  cmd.insert(cmd.end(), {pvbatch, source_dir() + "/scripts/render_paraview.py", o.run_file,
                         "--snapshot", std::to_string(snapshot), "--shell-field", o.shell_field,
                         "--size", o.size, "--kappa-range", o.kappa_range});
  if (!o.out.empty()) cmd.insert(cmd.end(), {"--out", o.out});
  if (!o.movie.empty()) cmd.insert(cmd.end(), {"--movie", o.movie});
  if (o.half_radius) cmd.push_back("--half-radius");
  if (!o.title.empty()) cmd.insert(cmd.end(), {"--title", o.title});
  const int rc = run_program(cmd);
  if (rc != 0) {
    // The script leaves nothing behind but its temporary names, should it have been killed.
    if (!o.out.empty()) remove_quietly(o.out + ".tmp.png");
    if (!o.movie.empty()) remove_quietly(o.movie + ".tmp.mp4");
    log << "wirepack render: the ParaView renderer failed (exit " << rc << ")\n";
    return 1;
  }
  return 0;
}

// gnuplot: results/render.sh draws one snapshot; ffmpeg makes a movie of all of them.
int render_gnuplot(const RenderOptions& o, int snapshot, std::size_t snapshots, std::ostream& log) {
  const std::string script = source_dir() + "/results/render.sh";
  const std::string title = o.title.empty() ? fs::path(o.run_file).filename().string() : o.title;
  const auto draw = [&](int k, const std::string& png) {
    return run_program({"bash", script, o.run_file, png, std::to_string(k), title}) == 0;
  };
  if (!o.out.empty()) {
    const std::string tmp = o.out + ".tmp.png";
    if (!draw(snapshot, tmp) || !publish(tmp, o.out)) {
      remove_quietly(tmp);
      log << "wirepack render: the gnuplot renderer failed (results/render.sh needs gnuplot and "
             "h5dump: scripts/setup.sh installs them)\n";
      return 1;
    }
  }
  if (!o.movie.empty()) {
    if (find_program("ffmpeg").empty()) {
      log << "wirepack render: no movie: ffmpeg is not installed (scripts/install_paraview.sh "
             "installs it)\n";
      return 1;
    }
    char dir_template[] = "/tmp/wirepack-frames-XXXXXX";
    const char* dir = ::mkdtemp(dir_template);
    if (!dir) {
      log << "wirepack render: cannot create a directory for the frames\n";
      return 1;
    }
    bool ok = true;
    for (std::size_t k = 0; k < snapshots && ok; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05zu.png", k);
      ok = draw(static_cast<int>(k), dir + std::string(name));
    }
    const std::string tmp = o.movie + ".tmp.mp4";
    ok = ok && run_program({"ffmpeg", "-y", "-loglevel", "error", "-framerate", "4", "-i",
                            std::string(dir) + "/frame_%05d.png", "-vf",
                            "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                            "yuv420p", tmp}) == 0;
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (!ok || !publish(tmp, o.movie)) {
      remove_quietly(tmp);
      log << "wirepack render: the movie could not be made (gnuplot frames, ffmpeg)\n";
      return 1;
    }
  }
  return 0;
}

}  // namespace

RenderPlan check_render(const RenderOptions& o) {
  if (o.out.empty() && o.movie.empty())
    throw InputError("render: nothing to write: give --out PICTURE.png and/or --movie MOVIE.mp4");
  if (!o.out.empty() && !ends_with(o.out, ".png"))
    throw InputError(o.out + ": --out must name a PNG file (PICTURE.png)");
  if (!o.movie.empty() && !ends_with(o.movie, ".mp4"))
    throw InputError(o.movie + ": --movie must name an MP4 file (MOVIE.mp4)");
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(o.size.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X') ||
      w < 16 || h < 16 || w > 8192 || h > 8192)
    throw InputError("--size: must be WxH with 16 <= W, H <= 8192 (got \"" + o.size + "\")");
  double k0 = 0, k1 = 0;
  if (std::sscanf(o.kappa_range.c_str(), "%lf,%lf%c", &k0, &k1, &rest) != 2 || !(k0 < k1))
    throw InputError("--kappa-range: must be A,B with A < B (got \"" + o.kappa_range + "\")");
  std::error_code ec;
  if (!fs::is_regular_file(o.run_file, ec)) throw InputError(o.run_file + ": no such run file");
  sweep::RunRecord r;
  try {
    r = sweep::read_run_file(o.run_file);
  } catch (const sweep::RunFileError& e) {
    throw InputError(e.what());
  }
  const std::size_t n = r.snapshots.size();
  if (n == 0) throw InputError(o.run_file + ": the run file has no snapshots, nothing to draw");
  if (o.snapshot < -1 || o.snapshot >= static_cast<long>(n))
    throw InputError("--snapshot " + std::to_string(o.snapshot) + ": " + o.run_file + " has " +
                     std::to_string(n) + " snapshots (0 to " + std::to_string(n - 1) + ")");
  return {o.snapshot < 0 ? static_cast<int>(n) - 1 : o.snapshot, n};
}

int render_run(const RenderOptions& o, const RenderPlan& plan, std::ostream& out,
               std::ostream& log) {
  const std::string pvbatch = pvbatch_program();
  int rc = 0;
  if (!pvbatch.empty()) {
    rc = render_paraview(o, pvbatch, plan.snapshot, log);
  } else {
    log << "wirepack render: ParaView (pvbatch) is not installed (scripts/install_paraview.sh "
           "installs it); falling back to the gnuplot renderer results/render.sh (the wire as a "
           "line, the shell as a wireframe, no colour fields)\n";
    rc = render_gnuplot(o, plan.snapshot, plan.snapshots, log);
  }
  if (rc != 0) return rc;
  if (!o.out.empty()) out << o.out << '\n';
  if (!o.movie.empty()) out << o.movie << '\n';
  return 0;
}

}  // namespace wirepack::app
