#include "sweep/runfile/run_file.hpp"
// Writing run files, and what reading shares with it; reading is in run_file_read.cpp.

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "sweep/runfile/hdf5_handle.hpp"
#include "wirepack_git.hpp"  // WIREPACK_GIT, written at build time (cmake/git_hash.cmake)

namespace wirepack::sweep {

#ifndef WIREPACK_VERSION
#define WIREPACK_VERSION "unknown"
#endif

std::string build_version() {
  return WIREPACK_VERSION;
}
std::string build_git() {
  return WIREPACK_GIT;
}

std::string to_string(RunStatus s) {
  switch (s) {
    case RunStatus::Running:
      return "running";
    case RunStatus::Complete:
      return "complete";
    case RunStatus::Failed:
      return "failed";
  }
  return "?";
}

RunStatus run_status_from_string(const std::string& s) {
  if (s == "running") return RunStatus::Running;
  if (s == "complete") return RunStatus::Complete;
  if (s == "failed") return RunStatus::Failed;
  throw RunFileError("unknown run status \"" + s + "\"");
}

const Series* RunRecord::find_series(const std::string& name) const {
  for (const auto& s : series)
    if (s.name == name) return &s;
  return nullptr;
}

Series* RunRecord::find_series(const std::string& name) {
  for (auto& s : series)
    if (s.name == name) return &s;
  return nullptr;
}

namespace {

// The run's mesh, stored once as /shell_triangles: the first snapshot's non-empty triangles.
const std::vector<std::array<int, 3>>* shared_triangles(const RunRecord& r) {
  for (const auto& s : r.snapshots)
    if (!s.shell_triangles.empty()) return &s.shell_triangles;
  return nullptr;
}

// Whether snapshot `s` is stored with the shared mesh (a hard link to /shell_triangles).
bool uses_shared_triangles(const RunRecord& r, const Snapshot& s) {
  const auto* shared = shared_triangles(r);
  return shared && s.shell_triangles == *shared;
}

// The clamped rim, stored once as /shell_clamped: the first snapshot's non-empty flags.
const std::vector<std::uint8_t>* shared_clamped(const RunRecord& r) {
  for (const auto& s : r.snapshots)
    if (!s.shell_clamped.empty()) return &s.shell_clamped;
  return nullptr;
}

}  // namespace

std::string shell_triangles_path(const RunRecord& r, std::size_t k) {
  if (r.layout >= 2 && k < r.snapshots.size() && uses_shared_triangles(r, r.snapshots[k]))
    return "/shell_triangles";
  return "/snapshots/" + std::to_string(k) + "/shell_triangles";
}

std::mutex& hdf5_mutex() {
  static std::mutex m;
  return m;
}

namespace {

// The HDF5 wrapper (hdf5_handle.hpp): check, fail, Handle, Hdf5Lock, utf8_string_type.
using namespace h5;

Handle ordered_group_plist() {
  Handle p(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "create group property list");
  check(H5Pset_link_creation_order(p.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "track link creation order");
  return p;
}

Handle create_group(hid_t parent, const std::string& name) {
  Handle plist = ordered_group_plist();
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, plist.get(), H5P_DEFAULT), H5Gclose,
                "create group " + name);
}

void write_string_attr(hid_t loc, const std::string& name, const std::string& value) {
  Handle type = utf8_string_type();
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create scalar dataspace");
  Handle attr(H5Acreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose, "create attribute " + name);
  const char* ptr = value.c_str();
  check(H5Awrite(attr.get(), type.get(), &ptr), "write attribute " + name);
}

void write_double_attr(hid_t loc, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create scalar dataspace");
  Handle attr(H5Acreate2(loc, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose, "create attribute " + name);
  check(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

void write_int_attr(hid_t loc, const std::string& name, int value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create scalar dataspace");
  Handle attr(H5Acreate2(loc, name.c_str(), H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose, "create attribute " + name);
  check(H5Awrite(attr.get(), H5T_NATIVE_INT, &value), "write attribute " + name);
}

// ---- storage: chunked and compressed where it pays ----

// Below 32 KiB a chunk index costs more than deflate saves on float64 coordinates (measured).
constexpr hsize_t kCompressMinBytes = 1 << 15;  // smaller datasets stay contiguous [bytes]
constexpr hsize_t kChunkBytes = 1 << 18;        // largest chunk [bytes]
constexpr unsigned kDeflateLevel = 4;           // zlib level, 1 (fastest) to 9 (smallest)

// Whether this HDF5 library can write deflate-compressed datasets (zlib is optional in an HDF5
// build; shuffle is always built in).
bool deflate_encoder_available() {
  unsigned config = 0;
  const bool ok = H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0 &&
                  H5Zget_filter_info(H5Z_FILTER_DEFLATE, &config) >= 0 &&
                  (config & H5Z_FILTER_CONFIG_ENCODE_ENABLED) != 0;
  H5Eclear2(H5E_DEFAULT);
  return ok;
}

// Creation properties of a dataset of shape `dims` and `elem` bytes per value: chunked (at most
// kChunkBytes a chunk) with shuffle + deflate if `compress` and it holds kCompressMinBytes or
// more; contiguous otherwise (small or empty: HDF5 cannot chunk an empty fixed-size dataset).
Handle dataset_plist(const std::vector<hsize_t>& dims, hsize_t elem, bool compress) {
  Handle p(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create dataset property list");
  hsize_t row = elem;  // bytes per row
  for (std::size_t d = 1; d < dims.size(); ++d) row *= dims[d];
  if (!compress || dims[0] * row < kCompressMinBytes) return p;
  std::vector<hsize_t> chunk = dims;
  chunk[0] = std::clamp<hsize_t>(kChunkBytes / row, 1, dims[0]);
  check(H5Pset_chunk(p.get(), static_cast<int>(chunk.size()), chunk.data()), "set chunk shape");
  check(H5Pset_shuffle(p.get()), "add the shuffle filter");
  check(H5Pset_deflate(p.get(), kDeflateLevel), "add the deflate filter");
  return p;
}

// Creates a dataset of shape `dims` (rank 1 or 2), compressed if `compress` (dataset_plist),
// and writes `data` (row-major).
Handle write_dataset(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type,
                     std::vector<hsize_t> dims, const void* data, bool compress) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose,
               "create dataspace for " + name);
  Handle dcpl = dataset_plist(dims, H5Tget_size(file_type), compress);
  Handle set(
      H5Dcreate2(loc, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
      H5Dclose, "create dataset " + name);
  if (dims[0] > 0)
    check(H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "write dataset " + name);
  return set;
}

// Builds the run file in memory (HDF5's core driver, no backing store) and returns its bytes.
// HDF5 never touches the disk, so a full disk or a file-size limit cannot leave it with a
// half-closed file (which made the library crash at exit) and every I/O error is ours to report.
std::vector<char> build_image(const RunRecord& r, const std::string& file_name) {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create file access property list");
  check(H5Pset_fapl_core(fapl.get(), 1 << 20, 0), "select HDF5's in-memory driver");
  Handle file(H5Fcreate(file_name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
              "create " + file_name);
  const bool compress = deflate_encoder_available();
  {
    Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose, "open /");
    write_string_attr(root.get(), "status", to_string(r.status));
    write_string_attr(root.get(), "failure", r.failure);
    write_string_attr(root.get(), "config", r.config.dump());
    write_string_attr(root.get(), "version", r.version);
    write_string_attr(root.get(), "git", r.git);
    write_string_attr(root.get(), "started", r.started);
    write_string_attr(root.get(), "finished", r.finished);
    write_int_attr(root.get(), "layout", kRunFileLayout);

    Handle series = create_group(file.get(), "series");
    for (const auto& s : r.series) {
      if (s.values.size() != r.series.front().values.size())
        throw RunFileError("series " + s.name + " has " + std::to_string(s.values.size()) +
                           " values, series " + r.series.front().name + " has " +
                           std::to_string(r.series.front().values.size()));
      write_dataset(series.get(), s.name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {s.values.size()},
                    s.values.data(), compress);
    }

    // The mesh does not change during a run: stored once, hard-linked into the snapshots.
    const auto* shared = shared_triangles(r);
    if (shared)
      write_dataset(root.get(), "shell_triangles", H5T_STD_I32LE, H5T_NATIVE_INT,
                    {shared->size(), 3}, shared->data(), compress);

    // So is the clamped rim (1 byte per vertex).
    const auto* clamped = shared_clamped(r);
    if (clamped)
      write_dataset(root.get(), "shell_clamped", H5T_STD_U8LE, H5T_NATIVE_UINT8, {clamped->size()},
                    clamped->data(), compress);

    Handle snaps = create_group(file.get(), "snapshots");
    for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
      const Snapshot& s = r.snapshots[k];
      if (s.curvature.size() != s.wire.size())
        throw RunFileError("snapshot " + std::to_string(k) + ": curvature has " +
                           std::to_string(s.curvature.size()) + " values for " +
                           std::to_string(s.wire.size()) + " nodes");
      Handle g = create_group(snaps.get(), std::to_string(k));
      write_double_attr(g.get(), "l", s.l);
      Handle wire = write_dataset(g.get(), "wire", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                  {s.wire.size(), 3}, s.wire.data(), compress);
      write_double_attr(wire.get(), "l", s.l);
      write_dataset(g.get(), "curvature", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {s.curvature.size()},
                    s.curvature.data(), compress);
      const auto check_size = [&](const char* name, std::size_t got, std::size_t want,
                                  const char* of) {
        if (got != want)
          throw RunFileError("snapshot " + std::to_string(k) + ": " + name + " has " +
                             std::to_string(got) + " values for " + std::to_string(want) + " " +
                             of);
      };
      if (!s.wire_contacts.empty()) {
        check_size("wire_contacts", s.wire_contacts.size(), s.wire.size(), "nodes");
        write_dataset(g.get(), "wire_contacts", H5T_STD_I32LE, H5T_NATIVE_INT,
                      {s.wire_contacts.size()}, s.wire_contacts.data(), compress);
      }
      if (!s.shell_vertices.empty() || !s.shell_triangles.empty()) {
        write_dataset(g.get(), "shell_vertices", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                      {s.shell_vertices.size(), 3}, s.shell_vertices.data(), compress);
        // A hard link keeps /snapshots/<k>/shell_triangles valid for every reader.
        if (uses_shared_triangles(r, s))
          check(H5Lcreate_hard(root.get(), "shell_triangles", g.get(), "shell_triangles",
                               H5P_DEFAULT, H5P_DEFAULT),
                "link shell_triangles into snapshot " + std::to_string(k));
        else
          write_dataset(g.get(), "shell_triangles", H5T_STD_I32LE, H5T_NATIVE_INT,
                        {s.shell_triangles.size(), 3}, s.shell_triangles.data(), compress);
        // Fields: the stretch in single precision (a picture's colour, not a state).
        if (!s.shell_area_stretch.empty()) {
          check_size("shell_area_stretch", s.shell_area_stretch.size(), s.shell_triangles.size(),
                     "triangles");
          write_dataset(g.get(), "shell_area_stretch", H5T_IEEE_F32LE, H5T_NATIVE_DOUBLE,
                        {s.shell_area_stretch.size()}, s.shell_area_stretch.data(), compress);
        }
        if (!s.shell_contact_force.empty()) {
          check_size("shell_contact_force", s.shell_contact_force.size(), s.shell_vertices.size(),
                     "vertices");
          write_dataset(g.get(), "shell_contact_force", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                        {s.shell_contact_force.size(), 3}, s.shell_contact_force.data(), compress);
        }
        if (!s.shell_clamped.empty()) {
          check_size("shell_clamped", s.shell_clamped.size(), s.shell_vertices.size(), "vertices");
          if (s.shell_clamped == *clamped)
            check(H5Lcreate_hard(root.get(), "shell_clamped", g.get(), "shell_clamped", H5P_DEFAULT,
                                 H5P_DEFAULT),
                  "link shell_clamped into snapshot " + std::to_string(k));
          else
            write_dataset(g.get(), "shell_clamped", H5T_STD_U8LE, H5T_NATIVE_UINT8,
                          {s.shell_clamped.size()}, s.shell_clamped.data(), compress);
        }
      }
    }
  }
  check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "flush " + file_name);
  const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
  if (size < 0) fail("size the image of " + file_name);
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file.get(), image.data(), image.size()) != size)
    fail("copy the image of " + file_name);
  file.close("close " + file_name);
  return image;
}

// Writes `bytes` to `path` (created or truncated) and fsyncs it; on any error the file is
// removed and RunFileError names the path and the system's reason ("No space left on device").
void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw RunFileError("cannot create " + path + ": " + std::strerror(errno));
  std::size_t done = 0;
  int err = 0;
  while (done < bytes.size() && err == 0) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno != EINTR) err = errno;
    if (n > 0) done += static_cast<std::size_t>(n);
  }
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) {
    ::unlink(path.c_str());
    throw RunFileError("cannot write " + path + ": " + std::strerror(err));
  }
}

}  // namespace

void write_run_file(const RunRecord& record, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string part = path + ".part";
  std::vector<char> image;
  {
    Hdf5Lock lock;
    image = build_image(record, part);
  }
  write_bytes(part, image);  // removes the .part itself on failure
  std::error_code ec;
  fs::rename(part, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(part, ignored);
    throw RunFileError("rename " + part + " to " + path + ": " + ec.message());
  }
}

}  // namespace wirepack::sweep
