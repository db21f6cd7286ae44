#include "sweep/running/sweep_manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "sweep/atomic_file.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep {

using json = nlohmann::json;

std::string Shard::text() const {
  return std::to_string(index) + "/" + std::to_string(count);
}

std::string Shard::suffix() const {
  if (count == 1) return "";
  return ".shard-" + std::to_string(index) + "-of-" + std::to_string(count);
}

namespace {

// Parses a whole string as a non-negative integer.
std::optional<std::size_t> to_size(const std::string& s) {
  std::size_t v = 0;
  const char* end = s.data() + s.size();
  const auto res = std::from_chars(s.data(), end, v);
  if (s.empty() || res.ec != std::errc() || res.ptr != end) return std::nullopt;
  return v;
}

}  // namespace

Shard parse_shard(const std::string& text, const std::string& what) {
  const auto slash = text.find('/');
  if (slash != std::string::npos) {
    const auto k = to_size(text.substr(0, slash));
    const auto n = to_size(text.substr(slash + 1));
    if (k && n && *n >= 1 && *k < *n) return Shard{*k, *n};
  }
  throw InputError(what + ": must be K/N with 0 <= K < N, e.g. 0/4 (got \"" + text + "\")");
}

std::optional<Shard> shard_from_env(const std::function<const char*(const char*)>& getenv) {
  const auto get = [&](const char* name) -> const char* {
    return getenv ? getenv(name) : std::getenv(name);
  };
  const char* id = get("SLURM_ARRAY_TASK_ID");
  const char* count = get("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count) return std::nullopt;
  const char* min = get("SLURM_ARRAY_TASK_MIN");
  const char* step = get("SLURM_ARRAY_TASK_STEP");
  const auto i = to_size(id);
  const auto n = to_size(count);
  const auto m = min ? to_size(min) : std::optional<std::size_t>(0);
  const auto s = step ? to_size(step) : std::optional<std::size_t>(1);
  const std::string env = std::string("SLURM_ARRAY_TASK_ID=") + id + ", _COUNT=" + count +
                          ", _MIN=" + (min ? min : "(unset)") +
                          ", _STEP=" + (step ? step : "(unset)");
  if (!i || !n || !m || !s || *n < 1 || *s < 1 || *i < *m || (*i - *m) % *s != 0 ||
      (*i - *m) / *s >= *n)
    throw InputError(env + ": not a consistent job-array task; pass --shard K/N");
  return Shard{(*i - *m) / *s, *n};
}

std::string manifest_path(const std::string& dir, const Shard& shard) {
  return (std::filesystem::path(dir) / ("manifest" + shard.suffix() + ".json")).string();
}
std::string joblog_path(const std::string& dir, const Shard& shard) {
  return (std::filesystem::path(dir) / ("joblog" + shard.suffix() + ".csv")).string();
}
std::string lock_path(const std::string& dir, const Shard& shard) {
  return (std::filesystem::path(dir) / (".lock" + shard.suffix())).string();
}

std::string to_string(EntryStatus s) {
  switch (s) {
    case EntryStatus::Pending:
      return "pending";
    case EntryStatus::Running:
      return "running";
    case EntryStatus::Complete:
      return "complete";
    case EntryStatus::Failed:
      return "failed";
  }
  return "?";
}

json manifest_json(const Sweep& sweep, const Shard& shard,
                   const std::vector<ManifestEntry>& entries) {
  std::size_t n[4] = {0, 0, 0, 0};  // per EntryStatus
  json runs = json::array();
  for (const auto& e : entries) {
    ++n[static_cast<int>(e.status)];
    const SweepRun& r = *e.run;
    runs.push_back({{"index", r.index},
                    {"id", r.id},
                    {"file", r.file},
                    {"point", r.point_values},
                    {"seed", r.seed},
                    {"status", to_string(e.status)},
                    {"wall_s", e.wall_s >= 0 ? json(e.wall_s) : json(nullptr)},
                    {"reason", e.reason},
                    {"started", e.started},
                    {"finished", e.finished}});
  }
  return {{"sweep", sweep.resolved},
          {"shard", shard.text()},
          {"version", build_version()},
          {"git", build_git()},
          {"updated", utc_now_iso8601()},
          {"counts",
           {{"runs", entries.size()},
            {"pending", n[0]},
            {"running", n[1]},
            {"complete", n[2]},
            {"failed", n[3]}}},
          {"runs", std::move(runs)}};
}

std::string find_manifest(const std::string& dir_text) {
  namespace fs = std::filesystem;
  const fs::path dir(dir_text);
  std::error_code ec;
  if (fs::is_regular_file(dir / "manifest.json", ec)) return (dir / "manifest.json").string();
  std::vector<std::string> shards;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("manifest.shard-", 0) == 0 && name.ends_with(".json"))
      shards.push_back(e.path().string());
  }
  std::sort(shards.begin(), shards.end());
  return shards.empty() ? "" : shards.front();
}

JobLog::JobLog(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0) return;
  // An empty file gets the header; one whose last line was cut short (a write that failed
  // half-way, a full disk) gets its newline, so the next line starts a line of its own.
  char last = '\n';
  if (st.st_size > 0 && ::pread(fd_, &last, 1, st.st_size - 1) != 1) last = '\n';
  const char* start = st.st_size == 0 ? "id,file,start,end,wall_s,status,reason,shard\n"
                      : last != '\n'  ? "\n"
                                      : "";
  if (!write_all(fd_, start)) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(err));
  }
}

JobLog::~JobLog() {
  if (fd_ >= 0) ::close(fd_);
}

void JobLog::append(const JobLogLine& l) {
  char wall[32];
  std::snprintf(wall, sizeof(wall), "%.3f", l.wall_s);
  const std::string line = csv_field(l.id) + "," + csv_field(l.file) + "," + l.start + "," + l.end +
                           "," + wall + "," + l.status + "," + csv_field(l.reason) + "," + l.shard +
                           "\n";
  if (!write_all(fd_, line))
    throw std::runtime_error("cannot append to " + path_ + ": " + std::strerror(errno));
}

DirLock::DirLock(const std::string& path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path + ": cannot create lock file (" + std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {
    held_ = true;
    return;
  }
  if (errno == EWOULDBLOCK) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(path +
                     ": another `wirepack sweep` is working on this shard of this directory");
  }
  // ENOLCK, EINVAL, ...: the file system has no flock; go on without it.
}

DirLock::~DirLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

}  // namespace wirepack::sweep
