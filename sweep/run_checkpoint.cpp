#include "sweep/run_checkpoint.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "engine/state_archive.hpp"
#include "sweep/atomic_file.hpp"

namespace wirepack::sweep {

namespace {

constexpr char kMagic[] = "wirepack checkpoint\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64 offset basis
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;  // FNV prime
  }
  return h;
}

void put_snapshot(StateWriter& out, const Snapshot& s) {
  out.tag("SNAP");
  out.put(s.l);
  out.put(s.wire);
  out.put(s.curvature);
  out.put(s.shell_vertices);
  out.put(s.shell_triangles);
  out.put(s.wire_contacts);
  out.put(s.shell_area_stretch);
  out.put(s.shell_contact_force);
  out.put(s.shell_clamped);
}

void get_snapshot(StateReader& in, Snapshot& s) {
  in.tag("SNAP");
  in.get(s.l);
  in.get(s.wire);
  in.get(s.curvature);
  in.get(s.shell_vertices);
  in.get(s.shell_triangles);
  in.get(s.wire_contacts);
  in.get(s.shell_area_stretch);
  in.get(s.shell_contact_force);
  in.get(s.shell_clamped);
}

}  // namespace

void write_checkpoint(const RunCheckpoint& c, const std::string& path) {
  StateWriter out;
  out.put(c.config);
  out.put(c.record.version);
  out.put(c.record.git);
  out.put(c.record.started);
  out.put(c.wall_s);
  out.put(c.next_row);
  out.put(c.next_snapshot);
  out.put(c.last_row_l);
  out.put(c.last_snapshot_l);
  out.tag("SERI");
  out.put(static_cast<std::uint64_t>(c.record.series.size()));
  for (const Series& s : c.record.series) {
    out.put(s.name);
    out.put(s.values);
  }
  out.put(static_cast<std::uint64_t>(c.record.snapshots.size()));
  for (const Snapshot& s : c.record.snapshots) put_snapshot(out, s);
  out.tag("ENGN");
  out.put(c.engine);
  std::string file(kMagic, kMagicSize);
  const std::int32_t format = kCheckpointFormat;
  file.append(reinterpret_cast<const char*>(&format), sizeof format);
  file += out.bytes();
  const std::uint64_t sum = fnv1a(file);
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
  if (sum != fnv1a(std::string_view(file).substr(0, body_end)))
    throw fail("damaged (checksum mismatch)");
  const std::size_t body_start = kMagicSize + sizeof(std::int32_t);
  StateReader in(std::string_view(file).substr(body_start, body_end - body_start));
  RunCheckpoint c;
  try {
    in.get(c.config);
    in.get(c.record.version);
    in.get(c.record.git);
    in.get(c.record.started);
    in.get(c.wall_s);
    in.get(c.next_row);
    in.get(c.next_snapshot);
    in.get(c.last_row_l);
    in.get(c.last_snapshot_l);
    in.tag("SERI");
    const auto n_series = in.get<std::uint64_t>();
    if (n_series > 10000) in.fail(std::to_string(n_series) + " series");
    c.record.series.resize(n_series);
    for (Series& s : c.record.series) {
      in.get(s.name);
      in.get(s.values);
    }
    const auto n_snapshots = in.get<std::uint64_t>();
    if (n_snapshots > 1000000) in.fail(std::to_string(n_snapshots) + " snapshots");
    c.record.snapshots.resize(n_snapshots);
    for (Snapshot& s : c.record.snapshots) get_snapshot(in, s);
    in.tag("ENGN");
    in.get(c.engine);
    in.expect_end();
  } catch (const CheckpointError& e) {
    throw fail(e.what());
  }
  return c;
}

}  // namespace wirepack::sweep
