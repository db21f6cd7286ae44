// CSV and XDMF export of a run file (docs/design.md §4.7).
#include "sweep/runfile/export.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <hdf5.h>

#include "sweep/config/sweep_config.hpp"
#include "sweep/run_file_fixture.hpp"
#include "sweep/runfile/run_checkpoint.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::kLayout1Fixture;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

RunRecord record(bool shell) {
  RunRecord r;
  r.config = {{"rho", 20.0}};
  r.status = RunStatus::Complete;
  r.series = {{"l", {0.0, 0.1, 0.2}}, {"K", {0.0, 1.5, std::nan("")}}, {"N", {0, 1, 2}}};
  for (int k = 0; k < 3; ++k) {
    Snapshot s;
    s.l = 2.5 * k;
    for (int i = 0; i < 3 + k; ++i) s.wire.push_back({1e-3 * i, 0, 0});
    s.curvature.assign(s.wire.size(), 1.0);
    if (shell) {
      s.shell_vertices = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
      s.shell_triangles = {{0, 1, 2}};
    }
    r.snapshots.push_back(s);
  }
  return r;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(Export, CsvHeaderAndValues) {
  TempDir dir;
  write_run_file(record(false), dir / "run.h5");
  export_csv(dir / "run.h5", dir / "run.csv");
  EXPECT_EQ(read_text(dir / "run.csv"), "l,K,N\n0,0,0\n0.1,1.5,1\n0.2,nan,2\n");
  EXPECT_FALSE(fs::exists(dir / "run.csv.tmp"));
}

TEST(Export, XdmfWireOnly) {
  TempDir dir;
  write_run_file(record(false), dir / "run.h5");
  fs::create_directory(dir.path() / "view");
  export_xdmf(dir / "run.h5", dir / "view/run.xmf");
  const std::string x = read_text(dir / "view/run.xmf");
  EXPECT_EQ(x.rfind("<?xml", 0), 0u);
  EXPECT_NE(x.find("<Xdmf Version=\"3.0\""), std::string::npos);
  EXPECT_NE(x.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_EQ(count(x, "<Time "), 3u);  // one time step per snapshot
  EXPECT_EQ(count(x, "<Grid Name=\"snapshot_"), 3u);
  EXPECT_EQ(count(x, "TopologyType=\"Polyline\""), 3u);
  EXPECT_EQ(count(x, "TopologyType=\"Triangle\""), 0u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NE(x.find("../run.h5:/snapshots/" + std::to_string(k) + "/wire<"), std::string::npos);
    EXPECT_NE(x.find("../run.h5:/snapshots/" + std::to_string(k) + "/curvature<"),
              std::string::npos);
  }
  EXPECT_NE(x.find("<Time Value=\"5\" />"), std::string::npos);
  // Snapshot 2 has 5 nodes: 4 segments with inline connectivity.
  EXPECT_NE(x.find("NumberOfElements=\"4\" NodesPerElement=\"2\""), std::string::npos);
  EXPECT_NE(x.find(">0 1 1 2 2 3 3 4</DataItem>"), std::string::npos);
  // Balanced elements.
  EXPECT_EQ(count(x, "<Grid "), count(x, "</Grid>"));
  EXPECT_EQ(count(x, "<DataItem "), count(x, "</DataItem>"));
  EXPECT_NE(x.find("</Xdmf>"), std::string::npos);
}

TEST(Export, XdmfWithShell) {
  TempDir dir;
  write_run_file(record(true), dir / "run.h5");
  export_xdmf(dir / "run.h5", dir / "run.xmf");
  const std::string x = read_text(dir / "run.xmf");
  EXPECT_EQ(count(x, "<Time "), 3u);
  EXPECT_EQ(count(x, "TopologyType=\"Triangle\""), 3u);
  EXPECT_EQ(count(x, ">run.h5:/shell_triangles<"), 3u);  // the mesh, stored once
  EXPECT_NE(x.find(">run.h5:/snapshots/1/shell_vertices<"), std::string::npos);
  EXPECT_EQ(count(x, "<Grid "), count(x, "</Grid>"));
}

// Checks that every Format="HDF" DataItem of the .xmf file names a dataset of its run file
// with the dimensions it states; returns how many there are.
std::size_t check_hdf_items(const std::string& xmf) {
  static const std::regex item(
      R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*Format="HDF">([^<:]+):([^<]+)</DataItem>)re");
  const std::string x = read_text(xmf);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::size_t n = 0;
  for (std::sregex_iterator it(x.begin(), x.end(), item), end; it != end; ++it, ++n) {
    const std::string dims = (*it)[1], h5 = (*it)[2], path = (*it)[3];
    const std::string file_path = (fs::path(xmf).parent_path() / h5).string();
    const hid_t file = H5Fopen(file_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_GE(file, 0) << file_path;
    if (file < 0) continue;
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    EXPECT_GE(set, 0) << h5 << ':' << path << " is not a dataset";
    if (set >= 0) {
      const hid_t space = H5Dget_space(set);
      hsize_t d[2] = {0, 0};
      const int rank = H5Sget_simple_extent_dims(space, d, nullptr);
      EXPECT_EQ(
          rank == 2 ? std::to_string(d[0]) + " " + std::to_string(d[1]) : std::to_string(d[0]),
          dims)
          << path;
      H5Sclose(space);
      H5Dclose(set);
    }
    H5Fclose(file);
  }
  return n;
}

TEST(Export, XdmfPathsExistInFile) {
  TempDir dir;
  RunRecord r = record(true);
  r.snapshots[2].shell_triangles = {{0, 2, 1}};  // a mesh of its own
  write_run_file(r, dir / "run.h5");
  fs::create_directory(dir.path() / "view");
  export_xdmf(dir / "run.h5", dir / "view/run.xmf");
  const std::string x = read_text(dir / "view/run.xmf");
  EXPECT_EQ(count(x, ">../run.h5:/shell_triangles<"), 2u);
  EXPECT_EQ(count(x, ">../run.h5:/snapshots/2/shell_triangles<"), 1u);
  // Per snapshot: wire, curvature, shell triangles and vertices.
  EXPECT_EQ(check_hdf_items(dir / "view/run.xmf"), 12u);

  // A layout 1 file: every snapshot's triangles in the snapshot.
  fs::copy_file(std::string(WIREPACK_SOURCE_DIR) + "/" + kLayout1Fixture, dir / "old.h5");
  export_xdmf(dir / "old.h5", dir / "old.xmf");
  const std::string old = read_text(dir / "old.xmf");
  EXPECT_EQ(count(old, ":/shell_triangles<"), 0u);
  EXPECT_EQ(count(old, ">old.h5:/snapshots/1/shell_triangles<"), 1u);
  EXPECT_EQ(check_hdf_items(dir / "old.xmf"), 12u);
}

// The fields (issue 18): node attributes of the wire and the shell, a cell attribute of the
// shell, each referencing a dataset of the right shape and number type.
TEST(Export, XdmfFieldAttributes) {
  TempDir dir;
  RunRecord r = record(true);
  for (std::size_t k = 1; k < r.snapshots.size(); ++k) {  // none in snapshot 0 (an old file)
    Snapshot& s = r.snapshots[k];
    s.wire_contacts.assign(s.wire.size(), 1);
    s.shell_area_stretch = {1.5};
    s.shell_contact_force = {{0, 0, 1e-3}, {0, 0, 0}, {0, 0, 0}};
    s.shell_clamped = {0, 1, 1};
  }
  write_run_file(r, dir / "run.h5");
  export_xdmf(dir / "run.h5", dir / "run.xmf");
  const std::string x = read_text(dir / "run.xmf");
  EXPECT_EQ(count(x,
                  "<Attribute Name=\"wire_contacts\" AttributeType=\"Scalar\" "
                  "Center=\"Node\">"),
            2u);
  EXPECT_EQ(count(x,
                  "<Attribute Name=\"shell_area_stretch\" AttributeType=\"Scalar\" "
                  "Center=\"Cell\">"),
            2u);
  EXPECT_EQ(count(x,
                  "<Attribute Name=\"shell_contact_force\" AttributeType=\"Vector\" "
                  "Center=\"Node\">"),
            2u);
  EXPECT_EQ(count(x,
                  "<Attribute Name=\"shell_clamped\" AttributeType=\"Scalar\" "
                  "Center=\"Node\">"),
            2u);
  EXPECT_NE(x.find("<DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"4\" "
                   "Format=\"HDF\">run.h5:/snapshots/2/shell_area_stretch<"),
            std::string::npos);
  EXPECT_NE(x.find("<DataItem Dimensions=\"3\" NumberType=\"UChar\" Precision=\"1\" "
                   "Format=\"HDF\">run.h5:/snapshots/1/shell_clamped<"),
            std::string::npos);
  EXPECT_NE(x.find("<DataItem Dimensions=\"3 3\" NumberType=\"Float\" Precision=\"8\" "
                   "Format=\"HDF\">run.h5:/snapshots/1/shell_contact_force<"),
            std::string::npos);
  EXPECT_EQ(x.find("/snapshots/0/shell_clamped"), std::string::npos);
  // Per snapshot: wire, curvature, shell triangles and vertices; 4 fields in snapshots 1, 2.
  EXPECT_EQ(check_hdf_items(dir / "run.xmf"), 12u + 8u);
  EXPECT_EQ(count(x, "<Attribute "), count(x, "</Attribute>"));
}

// A run part-way: its checkpoint exports the series recorded so far, with the run file's
// columns; its config parses with integer keys intact; XDMF (which references the run file's
// datasets) and a damaged checkpoint are refused with the file and the reason, writing nothing.
TEST(Export, CheckpointOfARunPartWay) {
  TempDir dir;
  RunCheckpoint c;
  c.config = canonical_json(nlohmann::json{{"rho", 20}, {"seed", 3}, {"mu_s", 0.5}});
  c.record = record(false);
  c.engine = "state";
  write_checkpoint(c, dir / "run.h5.ckpt");
  export_csv(dir / "run.h5.ckpt", dir / "run.csv");
  EXPECT_EQ(read_text(dir / "run.csv"), "l,K,N\n0,0,0\n0.1,1.5,1\n0.2,nan,2\n");
  const RunRecord r = read_run_for_export(dir / "run.h5.ckpt");
  EXPECT_EQ(r.status, RunStatus::Running);
  EXPECT_TRUE(r.config.at("seed").is_number_integer());
  EXPECT_EQ(r.config.at("seed"), 3);
  EXPECT_EQ(r.config.at("mu_s"), 0.5);
  EXPECT_EQ(r.snapshots.size(), 3u);

  const auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const RunFileError& e) {
      return e.what();
    }
    return "";
  };
  const std::string xdmf = message([&] { export_xdmf(dir / "run.h5.ckpt", dir / "run.xmf"); });
  EXPECT_NE(xdmf.find("run.h5.ckpt: a checkpoint has no HDF5 datasets"), std::string::npos) << xdmf;
  EXPECT_FALSE(fs::exists(dir / "run.xmf"));
  std::string bytes = read_text(dir / "run.h5.ckpt");
  bytes[bytes.size() / 2] ^= 0x20;
  std::ofstream(dir / "bad.h5.ckpt", std::ios::binary) << bytes;
  const std::string bad = message([&] { export_csv(dir / "bad.h5.ckpt", dir / "bad.csv"); });
  EXPECT_NE(bad.find("bad.h5.ckpt: damaged"), std::string::npos) << bad;
  EXPECT_FALSE(fs::exists(dir / "bad.csv"));
  const std::string part = message([&] { export_csv(dir / "run.h5.part", dir / "p.csv"); });
  EXPECT_NE(part.find("a partial run file"), std::string::npos) << part;
}

TEST(Export, MissingRunFileThrows) {
  TempDir dir;
  EXPECT_THROW(export_csv(dir / "none.h5", dir / "x.csv"), RunFileError);
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
}

}  // namespace
}  // namespace wirepack::sweep
