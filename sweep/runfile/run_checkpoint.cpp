#include "sweep/runfile/run_checkpoint.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "engine/state_archive.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/sweep_config.hpp"

namespace wirepack::sweep {

namespace {

constexpr char kMagic[] = "wirepack checkpoint\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;

// The body of a checkpoint, written or read (engine/state_archive.hpp); C: RunCheckpoint or
// const RunCheckpoint.
template <class C, class Archive>
void serialize(C& c, Archive& ar) {
  ar(c.config, c.record.version, c.record.git, c.record.started, c.wall_s);
  ar(c.next_row, c.next_snapshot, c.last_row_l, c.last_snapshot_l);
  ar.tag("SERI");
  ar.count(c.record.series, 10000);
  for (auto& s : c.record.series) {
    ar(s.name, s.values);
  }
  ar.count(c.record.snapshots, 1000000);
  for (auto& s : c.record.snapshots) {
    ar.tag("SNAP");
    ar(s.l, s.wire, s.curvature, s.shell_vertices, s.shell_triangles, s.wire_contacts);
    ar(s.shell_area_stretch, s.shell_contact_force, s.shell_clamped);
  }
  ar.tag("ENGN");
  ar(c.engine);
}

}  // namespace

void write_checkpoint(const RunCheckpoint& c, const std::string& path) {
  StateWriter out;
  serialize(c, out);
  std::string file(kMagic, kMagicSize);
  const std::int32_t format = kCheckpointFormat;
  file.append(reinterpret_cast<const char*>(&format), sizeof format);
  file += out.bytes();
  const std::uint64_t sum = fnv1a64(file);
  file.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  write_file_atomic(path, file);
}

RunCheckpoint read_checkpoint(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw CheckpointError(path + ": cannot be opened");
  std::ostringstream buf;
  buf << f.rdbuf();
  const std::string file = buf.str();
  const auto fail = [&](const std::string& why) -> CheckpointError {
    return CheckpointError(path + ": " + why);
  };
  if (file.size() < kMagicSize + sizeof(std::int32_t) + sizeof(std::uint64_t) ||
      file.compare(0, kMagicSize, kMagic) != 0)
    throw fail("not a wirepack checkpoint");
  std::int32_t format = 0;
  std::memcpy(&format, file.data() + kMagicSize, sizeof format);
  if (format != kCheckpointFormat)
    throw fail("checkpoint format " + std::to_string(format) + ", this build reads " +
               std::to_string(kCheckpointFormat));
  const std::size_t body_end = file.size() - sizeof(std::uint64_t);
  std::uint64_t sum = 0;
  std::memcpy(&sum, file.data() + body_end, sizeof sum);
  if (sum != fnv1a64(std::string_view(file).substr(0, body_end)))
    throw fail("damaged (checksum mismatch)");
  const std::size_t body_start = kMagicSize + sizeof(std::int32_t);
  StateReader in(std::string_view(file).substr(body_start, body_end - body_start));
  RunCheckpoint c;
  try {
    serialize(c, in);
    in.expect_end();
  } catch (const CheckpointError& e) {
    throw fail(e.what());
  }
  return c;
}

namespace {

// The checkpoint keeps the config in canonical form (sweep_config.hpp: every number a double);
// integral values are made integers again so that the scene parses as the run file's config
// (whose integer keys, e.g. /seed, refuse a double).
nlohmann::json integers_restored(const nlohmann::json& v) {
  if (v.is_number_float()) {
    const double x = v.get<double>();
    if (std::isfinite(x) && x == std::trunc(x) && std::fabs(x) < 9007199254740992.0)
      return static_cast<std::int64_t>(x);
    return v;
  }
  nlohmann::json out = v;
  if (v.is_object() || v.is_array()) {
    for (auto it = out.begin(); it != out.end(); ++it) *it = integers_restored(*it);
  }
  return out;
}

}  // namespace

RunRecord read_checkpoint_record(const std::string& path) {
  RunCheckpoint c = read_checkpoint(path);
  RunRecord r = std::move(c.record);
  r.status = RunStatus::Running;
  try {
    r.config = integers_restored(nlohmann::json::parse(c.config));
  } catch (const nlohmann::json::exception& e) {
    throw CheckpointError(path + ": its configuration is not JSON (" + e.what() + ")");
  }
  return r;
}

}  // namespace wirepack::sweep
