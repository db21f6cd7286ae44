// Run file (docs/design.md §4.3): write/read round trip, write-then-rename, failures leave
// nothing; layout 2 (compressed datasets, one shared triangle dataset) and reading layout 1 files.
#include "sweep/runfile/run_file.hpp"

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <thread>

#include <gtest/gtest.h>
#include <hdf5.h>

#include "sweep/run_file_fixture.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::kLayout1Fixture;
using wirepack::testing::layout1_record;
using wirepack::testing::TempDir;

RunRecord sample_record() {
  RunRecord r;
  r.config = {{"rho", 20.0}, {"shell", "elastic"}, {"wire", {{"radius", 5e-4}}}};
  r.status = RunStatus::Failed;
  r.failure = "step collapse at t = 1e-3 s";
  r.version = "0.1.0";
  r.git = "abc123";
  r.started = "2024-05-01T12:00:00Z";
  r.finished = "2024-05-01T12:01:00Z";
  // Deliberately not in alphabetical order: the file keeps recording order.
  r.series = {
      {"l", {0.0, 0.1, 0.2}}, {"U_b_hat", {1.0, std::nan(""), 3.0}}, {"D", {0.5, 0.25, 0.125}}};
  Snapshot s0;
  s0.l = 0;
  Snapshot s1;
  s1.l = 0.2;
  s1.wire = {{0, 0, -1e-2}, {0, 1e-3, -9e-3}, {1e-3, 2e-3, -8e-3}};
  s1.curvature = {0, 12.5, 0};
  s1.shell_vertices = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  s1.shell_triangles = {{0, 1, 2}, {0, 2, 3}};
  r.snapshots = {s0, s1};
  // Snapshot indices above 9 must still come back in numeric order.
  for (int k = 2; k < 12; ++k) {
    Snapshot s;
    s.l = 0.1 * k;
    s.wire = {{0, 0, 0}, {0, 0, 1e-3 * k}};
    s.curvature = {0, 0};
    r.snapshots.push_back(s);
  }
  return r;
}

TEST(RunFile, RoundTrip) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  const RunRecord r = sample_record();
  write_run_file(r, path);
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));

  const RunRecord b = read_run_file(path);
  EXPECT_EQ(b.config, r.config);
  EXPECT_EQ(b.status, RunStatus::Failed);
  EXPECT_EQ(b.failure, r.failure);
  EXPECT_EQ(b.version, r.version);
  EXPECT_EQ(b.git, r.git);
  EXPECT_EQ(b.started, r.started);
  EXPECT_EQ(b.finished, r.finished);
  ASSERT_EQ(b.series.size(), 3u);
  EXPECT_EQ(b.series[0].name, "l");
  EXPECT_EQ(b.series[1].name, "U_b_hat");
  EXPECT_EQ(b.series[2].name, "D");
  EXPECT_EQ(b.series[0].values, r.series[0].values);
  EXPECT_TRUE(std::isnan(b.series[1].values[1]));
  EXPECT_EQ(b.series[1].values[2], 3.0);
  ASSERT_NE(b.find_series("D"), nullptr);
  EXPECT_EQ(b.find_series("D")->values, r.series[2].values);
  EXPECT_EQ(b.find_series("nope"), nullptr);

  ASSERT_EQ(b.snapshots.size(), r.snapshots.size());
  for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
    EXPECT_EQ(b.snapshots[k].l, r.snapshots[k].l) << k;
    EXPECT_EQ(b.snapshots[k].wire, r.snapshots[k].wire) << k;
    EXPECT_EQ(b.snapshots[k].curvature, r.snapshots[k].curvature) << k;
    EXPECT_EQ(b.snapshots[k].shell_vertices, r.snapshots[k].shell_vertices) << k;
    EXPECT_EQ(b.snapshots[k].shell_triangles, r.snapshots[k].shell_triangles) << k;
  }
  EXPECT_TRUE(b.snapshots[0].wire.empty());
}

TEST(RunFile, StatusStrings) {
  for (RunStatus s : {RunStatus::Running, RunStatus::Complete, RunStatus::Failed})
    EXPECT_EQ(run_status_from_string(to_string(s)), s);
  EXPECT_EQ(to_string(RunStatus::Complete), "complete");
  EXPECT_THROW(run_status_from_string("done"), RunFileError);
}

TEST(RunFile, OverwriteReplaces) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  RunRecord r = sample_record();
  write_run_file(r, path);
  r.status = RunStatus::Complete;
  r.failure = "";
  r.snapshots.clear();
  write_run_file(r, path);
  const RunRecord b = read_run_file(path);
  EXPECT_EQ(b.status, RunStatus::Complete);
  EXPECT_TRUE(b.snapshots.empty());
}

TEST(RunFile, UnwritablePathLeavesNothing) {
  TempDir dir;
  // A path below a regular file fails even for root.
  const std::string file = dir.write("plain", "x");
  EXPECT_THROW(write_run_file(sample_record(), file + "/run.h5"), RunFileError);
  EXPECT_THROW(write_run_file(sample_record(), dir / "missing/run.h5"), RunFileError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(RunFile, ReadOnlyDirectoryLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "permission bits do not stop root";
  TempDir dir;
  const fs::path ro = dir.path() / "ro";
  fs::create_directory(ro);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  try {
    write_run_file(sample_record(), (ro / "run.h5").string());
    ADD_FAILURE() << "no exception";
  } catch (const RunFileError& e) {
    EXPECT_NE(std::string(e.what()).find("run.h5.part"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(ro));
}

TEST(RunFile, FailedWriteKeepsPreviousFile) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  write_run_file(sample_record(), path);
  RunRecord bad = sample_record();
  bad.status = RunStatus::Complete;
  bad.series[1].values.pop_back();  // ragged series: refused mid-write
  EXPECT_THROW(write_run_file(bad, path), RunFileError);
  EXPECT_FALSE(fs::exists(path + ".part"));
  EXPECT_EQ(read_run_file(path).status, RunStatus::Failed);
}

TEST(RunFile, ReadErrors) {
  TempDir dir;
  EXPECT_THROW(read_run_file(dir / "none.h5"), RunFileError);
  const std::string junk = dir.write("junk.h5", "not hdf5");
  try {
    read_run_file(junk);
    ADD_FAILURE() << "no exception";
  } catch (const RunFileError& e) {
    EXPECT_NE(std::string(e.what()).find(junk), std::string::npos) << e.what();
  }
}

// A record with datasets above and below the compression threshold (32 KiB), with values a
// lossy path would change: NaN, infinities, -0, subnormals, full random mantissas.
RunRecord large_record() {
  RunRecord r = sample_record();
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-1e-2, 1e-2);
  const double special[] = {std::nan(""),
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            -0.0,
                            std::numeric_limits<double>::denorm_min(),
                            1e300};
  r.series.clear();
  for (const char* name : {"l", "U_b_hat", "N", "D"}) {
    Series s{name, {}};
    for (int i = 0; i < 5000; ++i) s.values.push_back(u(rng));
    r.series.push_back(s);
  }
  for (std::size_t i = 0; i < std::size(special); ++i) r.series[1].values[10 * i] = special[i];
  std::vector<std::array<int, 3>> mesh(3000);
  for (auto& t : mesh)
    for (int& v : t) v = static_cast<int>(rng() % 1500);
  r.snapshots.clear();
  for (int k = 0; k < 6; ++k) {
    Snapshot s;
    s.l = 0.5 * k;
    for (int i = 0; i < 1500 * k; ++i) {
      s.wire.push_back({u(rng), u(rng), u(rng)});
      s.curvature.push_back(i == 3 ? special[0] : 1e3 * u(rng));
    }
    if (k < 5) {  // snapshot 5 has no shell, snapshot 3 a mesh of its own
      for (int i = 0; i < 1500; ++i) s.shell_vertices.push_back({u(rng), u(rng), u(rng)});
      s.shell_triangles = mesh;
      if (k == 3) s.shell_triangles[7][1] = 1499 - s.shell_triangles[7][1];
    }
    r.snapshots.push_back(s);
  }
  return r;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every series and snapshot array of `b` bitwise equal to `a`'s.
void expect_same_data(const RunRecord& a, const RunRecord& b) {
  ASSERT_EQ(b.series.size(), a.series.size());
  for (std::size_t c = 0; c < a.series.size(); ++c) {
    EXPECT_EQ(b.series[c].name, a.series[c].name);
    EXPECT_TRUE(same_bytes(b.series[c].values, a.series[c].values)) << a.series[c].name;
  }
  ASSERT_EQ(b.snapshots.size(), a.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    const Snapshot& x = a.snapshots[k];
    const Snapshot& y = b.snapshots[k];
    EXPECT_EQ(std::memcmp(&y.l, &x.l, sizeof x.l), 0) << k;
    EXPECT_TRUE(same_bytes(y.wire, x.wire)) << k;
    EXPECT_TRUE(same_bytes(y.curvature, x.curvature)) << k;
    EXPECT_TRUE(same_bytes(y.shell_vertices, x.shell_vertices)) << k;
    EXPECT_EQ(y.shell_triangles, x.shell_triangles) << k;
    EXPECT_EQ(y.wire_contacts, x.wire_contacts) << k;
    EXPECT_TRUE(same_bytes(y.shell_contact_force, x.shell_contact_force)) << k;
    EXPECT_EQ(y.shell_clamped, x.shell_clamped) << k;
    // The stretch is stored in single precision.
    ASSERT_EQ(y.shell_area_stretch.size(), x.shell_area_stretch.size()) << k;
    for (std::size_t i = 0; i < x.shell_area_stretch.size(); ++i)
      EXPECT_EQ(y.shell_area_stretch[i], double(float(x.shell_area_stretch[i]))) << k;
  }
}

// An HDF5 identifier closed at scope exit.
struct H5Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5Id() {
    if (id >= 0) close(id);
  }
};

// Layout and filters of the dataset at `path`: "contiguous" or "chunked shuffle deflate".
std::string storage(hid_t file, const std::string& path) {
  H5Id set{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
  if (set.id < 0) return "missing";
  H5Id dcpl{H5Dget_create_plist(set.id), H5Pclose};
  std::string out = H5Pget_layout(dcpl.id) == H5D_CHUNKED ? "chunked" : "contiguous";
  for (int i = 0; i < H5Pget_nfilters(dcpl.id); ++i) {
    unsigned flags = 0, config = 0;
    std::size_t n = 0;
    const H5Z_filter_t f =
        H5Pget_filter2(dcpl.id, static_cast<unsigned>(i), &flags, &n, nullptr, 0, nullptr, &config);
    out += f == H5Z_FILTER_SHUFFLE   ? " shuffle"
           : f == H5Z_FILTER_DEFLATE ? " deflate"
                                     : " filter" + std::to_string(f);
  }
  return out;
}

// Number of hard links to the object at `path`.
unsigned link_count(hid_t file, const std::string& path) {
#if H5_VERSION_GE(1, 12, 0)
  H5O_info2_t info;
  if (H5Oget_info_by_name3(file, path.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) return 0;
#else
  H5O_info_t info;
  if (H5Oget_info_by_name2(file, path.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) return 0;
#endif
  return info.rc;
}

TEST(RunFile, CompressedRoundTripIsBitwise) {
  TempDir dir;
  const RunRecord r = large_record();
  write_run_file(r, dir / "run.h5");
  const RunRecord b = read_run_file(dir / "run.h5");
  EXPECT_EQ(b.layout, kRunFileLayout);
  EXPECT_EQ(b.config, r.config);
  EXPECT_EQ(b.version, r.version);
  expect_same_data(r, b);
}

TEST(RunFile, LargeDatasetsAreChunkedAndCompressed) {
  if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0) GTEST_SKIP() << "HDF5 built without deflate";
  TempDir dir;
  write_run_file(large_record(), dir / "run.h5");
  H5Id file{H5Fopen((dir / "run.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  ASSERT_GE(file.id, 0);
  for (const char* path :
       {"/series/l", "/series/U_b_hat", "/snapshots/2/wire", "/snapshots/5/curvature",
        "/snapshots/2/shell_vertices", "/shell_triangles", "/snapshots/3/shell_triangles"})
    EXPECT_EQ(storage(file.id, path), "chunked shuffle deflate") << path;
  // Below 32 KiB: contiguous (no wire nodes in snapshot 0; 3000 curvatures; 3-row series).
  EXPECT_EQ(storage(file.id, "/snapshots/0/wire"), "contiguous");
  EXPECT_EQ(storage(file.id, "/snapshots/2/curvature"), "contiguous");
  EXPECT_EQ(storage(file.id, "/snapshots/0/curvature"), "contiguous");
  write_run_file(sample_record(), dir / "small.h5");
  H5Id small{H5Fopen((dir / "small.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  EXPECT_EQ(storage(small.id, "/series/l"), "contiguous");
  EXPECT_EQ(storage(small.id, "/snapshots/1/wire"), "contiguous");
}

TEST(RunFile, TrianglesStoredOnce) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  const RunRecord r = large_record();
  write_run_file(r, path);
  {
    H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    ASSERT_GE(file.id, 0);
    // One dataset, linked from the root and from snapshots 0, 1, 2, 4 (3 has its own mesh).
    EXPECT_EQ(link_count(file.id, "/shell_triangles"), 5u);
    EXPECT_EQ(link_count(file.id, "/snapshots/3/shell_triangles"), 1u);
    EXPECT_EQ(H5Lexists(file.id, "/snapshots/5/shell_triangles", H5P_DEFAULT), 0);
  }
  for (std::size_t k = 0; k < r.snapshots.size(); ++k)
    EXPECT_EQ(shell_triangles_path(r, k),
              k == 3 || k == 5 ? "/snapshots/" + std::to_string(k) + "/shell_triangles"
                               : "/shell_triangles")
        << k;
  expect_same_data(r, read_run_file(path));

  // A snapshot with vertices but no triangle link (a file edited by hand) gets the shared mesh.
  {
    H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose};
    ASSERT_GE(H5Ldelete(file.id, "/snapshots/1/shell_triangles", H5P_DEFAULT), 0);
  }
  EXPECT_EQ(read_run_file(path).snapshots[1].shell_triangles, r.snapshots[1].shell_triangles);
}

TEST(RunFile, ReadsLayout1Files) {
  // Written by wirepack 0.1.0 (commit 4820c39): triangles in every snapshot, uncompressed.
  const std::string path = std::string(WIREPACK_SOURCE_DIR) + "/" + kLayout1Fixture;
  const RunRecord b = read_run_file(path);
  const RunRecord r = layout1_record();
  EXPECT_EQ(b.layout, 1);
  EXPECT_EQ(b.config, r.config);
  EXPECT_EQ(b.status, r.status);
  EXPECT_EQ(b.git, r.git);
  expect_same_data(r, b);  // incl. the fields (issue 18): optional, empty here
  for (const Snapshot& s : b.snapshots) {
    EXPECT_TRUE(s.wire_contacts.empty());
    EXPECT_TRUE(s.shell_area_stretch.empty());
    EXPECT_TRUE(s.shell_contact_force.empty());
    EXPECT_TRUE(s.shell_clamped.empty());
  }
  for (std::size_t k = 0; k < b.snapshots.size(); ++k)
    EXPECT_EQ(shell_triangles_path(b, k), "/snapshots/" + std::to_string(k) + "/shell_triangles");
  // Rewritten, it comes out in layout 2 with the same data.
  TempDir dir;
  write_run_file(b, dir / "run.h5");
  const RunRecord c = read_run_file(dir / "run.h5");
  EXPECT_EQ(c.layout, 2);
  expect_same_data(r, c);
}

// A record with the shell fields (issue 18) in snapshots 1 and 2, none in snapshot 0.
RunRecord fields_record() {
  RunRecord r = layout1_record();
  for (std::size_t k = 1; k < r.snapshots.size(); ++k) {
    Snapshot& s = r.snapshots[k];
    s.wire_contacts = {0, 2, int(k)};
    s.shell_area_stretch = {1.0 + 0.1 * double(k), 1.0 / 3.0};
    s.shell_contact_force = {{0, 0, 0}, {1e-3, -2e-3, 0.5 * double(k)}, {0, 0, 0}, {0, 0, 1e-9}};
    s.shell_clamped = {0, 0, 1, 1};
  }
  return r;
}

TEST(RunFile, FieldsRoundTripAndRimStoredOnce) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  const RunRecord r = fields_record();
  write_run_file(r, path);
  const RunRecord b = read_run_file(path);
  expect_same_data(r, b);
  EXPECT_TRUE(b.snapshots[0].wire_contacts.empty());
  EXPECT_TRUE(b.snapshots[0].shell_area_stretch.empty());
  EXPECT_TRUE(b.snapshots[0].shell_contact_force.empty());
  EXPECT_NEAR(b.snapshots[1].shell_area_stretch[1], 1.0 / 3.0, 1e-7);
  {
    H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    ASSERT_GE(file.id, 0);
    // One rim dataset, linked from the root and from snapshots 1 and 2 (0 has no rim).
    EXPECT_EQ(link_count(file.id, "/shell_clamped"), 3u);
    EXPECT_EQ(H5Lexists(file.id, "/snapshots/0/shell_clamped", H5P_DEFAULT), 0);
    EXPECT_EQ(H5Lexists(file.id, "/snapshots/0/wire_contacts", H5P_DEFAULT), 0);
  }
  // Rewritten from what was read: the same file contents.
  write_run_file(b, dir / "again.h5");
  expect_same_data(b, read_run_file(dir / "again.h5"));
}

TEST(RunFile, FieldOfTheWrongSizeIsRefused) {
  TempDir dir;
  for (int which = 0; which < 4; ++which) {
    RunRecord r = fields_record();
    Snapshot& s = r.snapshots[2];
    if (which == 0) s.wire_contacts.push_back(1);
    if (which == 1) s.shell_area_stretch.pop_back();
    if (which == 2) s.shell_contact_force.pop_back();
    if (which == 3) s.shell_clamped.push_back(0);
    EXPECT_THROW(write_run_file(r, dir / "bad.h5"), RunFileError) << which;
    EXPECT_FALSE(fs::exists(dir / "bad.h5")) << which;
    EXPECT_FALSE(fs::exists(dir / "bad.h5.part")) << which;
  }
}

TEST(RunFile, RejectsUnknownLayout) {
  TempDir dir;
  const std::string path = dir / "run.h5";
  write_run_file(sample_record(), path);
  {
    H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose};
    H5Id attr{H5Aopen_by_name(file.id, "/", "layout", H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    const int three = 3;
    ASSERT_GE(H5Awrite(attr.id, H5T_NATIVE_INT, &three), 0);
  }
  try {
    read_run_file(path);
    ADD_FAILURE() << "no exception";
  } catch (const RunFileError& e) {
    EXPECT_NE(std::string(e.what()).find("layout 3 is unknown"), std::string::npos) << e.what();
  }
}

TEST(RunFile, ConcurrentWritersAndReaders) {
  TempDir dir;
  const RunRecord r = sample_record();
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      const std::string path = dir / ("run" + std::to_string(t) + ".h5");
      for (int i = 0; i < 5; ++i) {
        write_run_file(r, path);
        EXPECT_EQ(read_run_file(path).snapshots.size(), r.snapshots.size());
      }
    });
  for (auto& th : threads) th.join();
}

}  // namespace
}  // namespace wirepack::sweep
