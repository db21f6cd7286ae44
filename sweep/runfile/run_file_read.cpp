// Reading run files (sweep/runfile/run_file.hpp); writing them is in run_file.cpp.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>

#include "sweep/runfile/hdf5_handle.hpp"
#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep {

namespace {

// The HDF5 wrapper (hdf5_handle.hpp): check, fail, Handle, Hdf5Lock, utf8_string_type.
using namespace h5;

bool has_attr(hid_t loc, const std::string& name) {
  const htri_t e = H5Aexists(loc, name.c_str());
  if (e < 0) fail("look up attribute " + name);
  return e > 0;
}

std::string read_string_attr(hid_t loc, const std::string& name) {
  Handle attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  Handle ftype(H5Aget_type(attr.get()), H5Tclose, "type of attribute " + name);
  if (H5Tget_class(ftype.get()) != H5T_STRING)
    throw RunFileError("attribute " + name + " is not a string");
  const htri_t vlen = H5Tis_variable_str(ftype.get());
  if (vlen < 0) fail("type of attribute " + name);
  if (vlen > 0) {
    Handle mtype = utf8_string_type();
    char* ptr = nullptr;
    check(H5Aread(attr.get(), mtype.get(), &ptr), "read attribute " + name);
    std::string out = ptr ? ptr : "";
    H5free_memory(ptr);
    return out;
  }
  const std::size_t size = H5Tget_size(ftype.get());
  Handle mtype(H5Tcopy(H5T_C_S1), H5Tclose, "copy string type");
  check(H5Tset_size(mtype.get(), size), "set string size");
  std::string out(size, '\0');
  check(H5Aread(attr.get(), mtype.get(), out.data()), "read attribute " + name);
  out.resize(std::min(out.find('\0'), out.size()));
  return out;
}

double read_double_attr(hid_t loc, const std::string& name) {
  Handle attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  double v = 0;
  check(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}

int read_int_attr(hid_t loc, const std::string& name) {
  Handle attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  Handle ftype(H5Aget_type(attr.get()), H5Tclose, "type of attribute " + name);
  if (H5Tget_class(ftype.get()) != H5T_INTEGER)
    throw RunFileError("attribute " + name + " is not an integer");
  int v = 0;
  check(H5Aread(attr.get(), H5T_NATIVE_INT, &v), "read attribute " + name);
  return v;
}

// Reads a dataset of `cols` columns (cols = 0: 1-D) as `mem_type`; returns the row count.
template <class T>
std::vector<T> read_dataset(hid_t loc, const std::string& name, hid_t mem_type, std::size_t cols) {
  Handle set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose, "dataspace of " + name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != (cols == 0 ? 1 : 2))
    throw RunFileError("dataset " + name + " has rank " + std::to_string(rank));
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (cols != 0 && dims[1] != cols)
    throw RunFileError("dataset " + name + " has " + std::to_string(dims[1]) +
                       " columns, expected " + std::to_string(cols));
  std::vector<T> out(dims[0]);
  if (!out.empty())
    check(H5Dread(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()),
          "read dataset " + name);
  return out;
}

bool has_link(hid_t loc, const std::string& name) {
  const htri_t e = H5Lexists(loc, name.c_str(), H5P_DEFAULT);
  if (e < 0) fail("look up " + name);
  return e > 0;
}

// Names of a group's members in creation order (name order if the group does not track it).
std::vector<std::string> member_names(hid_t group) {
  H5G_info_t info;
  check(H5Gget_info(group, &info), "group info");
  std::vector<std::string> names;
  for (H5_index_t index : {H5_INDEX_CRT_ORDER, H5_INDEX_NAME}) {
    names.clear();
    bool ok = true;
    for (hsize_t i = 0; i < info.nlinks && ok; ++i) {
      const ssize_t len =
          H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
      if (len < 0) {
        ok = false;
        break;
      }
      std::string name(static_cast<std::size_t>(len) + 1, '\0');
      H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
      name.resize(static_cast<std::size_t>(len));
      names.push_back(name);
    }
    if (ok) break;
    H5Eclear2(H5E_DEFAULT);
  }
  if (names.size() != info.nlinks) fail("list group members");
  return names;
}

// "MAJOR.MINOR.PATCH" (a suffix after the patch number is ignored), or nullopt.
std::optional<std::array<unsigned long, 3>> parse_version(const std::string& v) {
  std::array<unsigned long, 3> out{};
  const char* p = v.c_str();
  for (int i = 0; i < 3; ++i) {
    if (i > 0) {
      if (*p != '.') return std::nullopt;
      ++p;
    }
    if (*p < '0' || *p > '9') return std::nullopt;
    char* end = nullptr;
    out[static_cast<std::size_t>(i)] = std::strtoul(p, &end, 10);
    p = end;
  }
  return out;
}

// A file written by a newer wirepack may have another layout: refused with the versions named.
// An empty version (hand-made files) is taken as this one's.
void check_version(const std::string& version) {
  if (version.empty()) return;
  const auto file = parse_version(version);
  if (!file) throw RunFileError("version attribute \"" + version + "\" is not a wirepack version");
  const auto ours = parse_version(build_version());
  if (ours && *file > *ours)
    throw RunFileError("written by wirepack " + version + ", newer than this wirepack " +
                       build_version() + " (its layout may differ; read it with wirepack " +
                       version + " or later)");
}

RunRecord read_record(const std::string& path) {
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path);
  Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose, "open /");
  RunRecord r;
  if (!has_attr(root.get(), "status") || !has_attr(root.get(), "config"))
    throw RunFileError(path + ": not a wirepack run file (no status or config attribute)");
  r.status = run_status_from_string(read_string_attr(root.get(), "status"));
  const std::string config = read_string_attr(root.get(), "config");
  try {
    r.config = nlohmann::json::parse(config);
  } catch (const nlohmann::json::exception& e) {
    throw RunFileError(path + ": config attribute is not JSON: " + e.what());
  }
  const auto opt = [&](const char* name) {
    return has_attr(root.get(), name) ? read_string_attr(root.get(), name) : std::string();
  };
  r.failure = opt("failure");
  r.version = opt("version");
  r.git = opt("git");
  r.started = opt("started");
  r.finished = opt("finished");
  check_version(r.version);
  // Layout 1 (files from before the attribute) keeps the triangles in every snapshot.
  r.layout = has_attr(root.get(), "layout") ? read_int_attr(root.get(), "layout") : 1;
  if (r.layout < 1 || r.layout > kRunFileLayout)
    throw RunFileError("run file layout " + std::to_string(r.layout) +
                       " is unknown to this wirepack " + build_version() + " (it reads 1 to " +
                       std::to_string(kRunFileLayout) + ")");

  // Every run file has /series (with at least l, all of one length) and /snapshots, even a
  // run that failed at its first step; a file without them is not one wirepack wrote whole.
  for (const char* group : {"series", "snapshots"})
    if (!has_link(file.get(), group))
      throw RunFileError(std::string("required group /") + group + " is missing");
  {
    Handle g(H5Gopen2(file.get(), "series", H5P_DEFAULT), H5Gclose, "open /series");
    for (const auto& name : member_names(g.get()))
      r.series.push_back({name, read_dataset<double>(g.get(), name, H5T_NATIVE_DOUBLE, 0)});
    if (!r.find_series("l")) throw RunFileError("required dataset /series/l is missing");
    for (const auto& s : r.series)
      if (s.values.size() != r.series.front().values.size())
        throw RunFileError("dataset /series/" + s.name + " has " + std::to_string(s.values.size()) +
                           " values, /series/" + r.series.front().name + " has " +
                           std::to_string(r.series.front().values.size()));
  }
  // Layout 2: the mesh, for snapshots that have vertices but no triangles of their own (each
  // normally has a hard link to it, read like a dataset of its own).
  std::vector<std::array<int, 3>> shared;
  const bool has_shared = has_link(file.get(), "shell_triangles");
  if (has_shared)
    shared = read_dataset<std::array<int, 3>>(file.get(), "shell_triangles", H5T_NATIVE_INT, 3);
  {
    Handle g(H5Gopen2(file.get(), "snapshots", H5P_DEFAULT), H5Gclose, "open /snapshots");
    auto names = member_names(g.get());
    // Snapshot k is group "k": order numerically whatever the index order was.
    std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
      return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
    for (const auto& name : names) {
      Handle sg(H5Gopen2(g.get(), name.c_str(), H5P_DEFAULT), H5Gclose, "open snapshot " + name);
      Snapshot s;
      s.l = read_double_attr(sg.get(), "l");
      s.wire = read_dataset<std::array<double, 3>>(sg.get(), "wire", H5T_NATIVE_DOUBLE, 3);
      if (has_link(sg.get(), "curvature"))
        s.curvature = read_dataset<double>(sg.get(), "curvature", H5T_NATIVE_DOUBLE, 0);
      if (has_link(sg.get(), "shell_vertices"))
        s.shell_vertices =
            read_dataset<std::array<double, 3>>(sg.get(), "shell_vertices", H5T_NATIVE_DOUBLE, 3);
      if (has_link(sg.get(), "shell_triangles"))
        s.shell_triangles =
            read_dataset<std::array<int, 3>>(sg.get(), "shell_triangles", H5T_NATIVE_INT, 3);
      else if (has_shared && has_link(sg.get(), "shell_vertices"))
        s.shell_triangles = shared;
      // Fields: optional.
      if (has_link(sg.get(), "wire_contacts"))
        s.wire_contacts = read_dataset<int>(sg.get(), "wire_contacts", H5T_NATIVE_INT, 0);
      if (has_link(sg.get(), "shell_area_stretch"))
        s.shell_area_stretch =
            read_dataset<double>(sg.get(), "shell_area_stretch", H5T_NATIVE_DOUBLE, 0);
      if (has_link(sg.get(), "shell_contact_force"))
        s.shell_contact_force = read_dataset<std::array<double, 3>>(sg.get(), "shell_contact_force",
                                                                    H5T_NATIVE_DOUBLE, 3);
      // The rim: where the snapshot links it (every snapshot written with one does).
      if (has_link(sg.get(), "shell_clamped"))
        s.shell_clamped =
            read_dataset<std::uint8_t>(sg.get(), "shell_clamped", H5T_NATIVE_UINT8, 0);
      r.snapshots.push_back(std::move(s));
    }
  }
  return r;
}

}  // namespace

RunRecord read_run_file(const std::string& path) {
  Hdf5Lock lock;
  try {
    return read_record(path);
  } catch (const RunFileError& e) {
    const std::string what = e.what();
    if (what.rfind(path, 0) == 0) throw;
    throw RunFileError(path + ": " + what);
  }
}

}  // namespace wirepack::sweep
