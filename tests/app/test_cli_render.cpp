// `wirepack render` (issue 18) in the fast suite, whether or not ParaView is installed: bad
// input exits 2 and writes nothing; without ParaView (WIREPACK_PVBATCH naming no program) it
// says so and draws the picture with the gnuplot renderer. The ParaView path itself is tested
// by tests/paraview/test_render.sh (ctest -L paraview).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/cli_runner.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::run_wirepack;
using wirepack::testing::TempDir;

// A run of 3 snapshots: a wire of 4 nodes inside a 4-vertex shell.
void write_small_run(const std::string& path) {
  RunRecord r;
  r.config = {{"rho", 20.0}, {"shell", "elastic"}, {"wire", {{"radius", 5e-4}}}};
  r.status = RunStatus::Complete;
  r.series = {{"l", {0.0, 0.5, 1.0}}};
  for (int k = 0; k < 3; ++k) {
    Snapshot s;
    s.l = 0.5 * k;
    for (int i = 0; i < 4; ++i) s.wire.push_back({1e-3 * i, 1e-3 * k * i * i, -8e-3 + 2e-3 * i});
    s.curvature = {0, 10.0 * k, 20.0 * k, 0};
    s.shell_vertices = {{0, 0, 1e-2}, {1e-2, 0, 0}, {0, 1e-2, 0}, {-1e-2, 0, -1e-2}};
    s.shell_triangles = {{0, 1, 2}, {0, 2, 3}};
    r.snapshots.push_back(s);
  }
  write_run_file(r, path);
}

bool has(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

TEST(CliRender, BadInputExits2AndWritesNothing) {
  TempDir dir;
  write_small_run(dir / "run.h5");
  const std::string no_pv = "WIREPACK_PVBATCH=/nonexistent/pvbatch";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"render none.h5 --out pics/a.png", "none.h5: no such run file"},
      {"render run.h5 --out pics/a.png --snapshot 3",
       "--snapshot 3: run.h5 has 3 snapshots (0 to 2)"},
      {"render run.h5 --out pics/a.png --snapshot -2", "--snapshot -2"},
      {"render run.h5 --out pics/a.jpg", "must name a PNG file"},
      {"render run.h5 --movie pics/a.avi", "must name an MP4 file"},
      {"render run.h5 --out pics/a.png --size 10x10", "--size"},
      {"render run.h5 --out pics/a.png --kappa-range 3,1", "--kappa-range"},
      {"render run.h5 --out pics/a.png --shell-field colour", "--shell-field"},
      {"render run.h5", "--movie"},  // neither --out nor --movie
  };
  for (const auto& c : cases) {
    const auto r = run_wirepack(dir, c.args, no_pv);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_TRUE(has(r.err, c.message)) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "pics")) << c.args;  // not even the directory
  }
  // A file that is not a run file.
  { std::ofstream(dir / "junk.h5") << "not HDF5"; }
  const auto r = run_wirepack(dir, "render junk.h5 --out pics/a.png", no_pv);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir / "pics"));
}

TEST(CliRender, WithoutParaViewFallsBackToGnuplot) {
  TempDir dir;
  write_small_run(dir / "run.h5");
  const auto r = run_wirepack(dir, "render run.h5 --out pics/run.png --snapshot 1",
                              "WIREPACK_PVBATCH=/nonexistent/pvbatch");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "ParaView (pvbatch) is not installed")) << r.err;
  EXPECT_TRUE(has(r.err, "scripts/install_paraview.sh")) << r.err;
  EXPECT_TRUE(has(r.err, "gnuplot")) << r.err;
  EXPECT_EQ(r.out, "pics/run.png\n");
  ASSERT_TRUE(fs::exists(dir / "pics/run.png"));
  EXPECT_GT(fs::file_size(dir / "pics/run.png"), 1000u);
  // A PNG of the gnuplot renderer's size, 1200 x 600 (IHDR: width and height, big-endian).
  const std::string png = wirepack::testing::read_text(dir / "pics/run.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  EXPECT_EQ(be32(16), 1200u);
  EXPECT_EQ(be32(20), 600u);
  EXPECT_FALSE(fs::exists(dir / "pics/run.png.tmp.png"));
}

}  // namespace
}  // namespace wirepack::sweep
