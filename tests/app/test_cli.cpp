// The wirepack executable end to end (docs/design.md §6.2): exit codes, messages, nothing written
// on bad input, a short real run and its export.
#include <sys/wait.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli_runner.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

using Result = wirepack::testing::CliResult;

// Runs `wirepack ARGS` in `dir` (cli_runner.hpp).
Result wirepack(const TempDir& dir, const std::string& args) {
  return wirepack::testing::run_wirepack(dir, args);
}

struct BadScene {
  const char* name;
  const char* text;
  const char* key;  // what stderr must name
};

const std::vector<BadScene>& bad_scenes() {
  static const std::vector<BadScene> cases = {
      {"unknown_top", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "bogus": 1})", "/bogus"},
      {"unknown_nested", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "wire": {"diam": 1}})",
       "/wire/diam"},
      {"wrong_type", R"({"rho": "20", "mu_s": 0, "shell": "rigid"})", "/rho"},
      {"overflow", R"({"rho": 20, "xi": 10, "eps": 1e999, "mu_s": 0})", "/eps"},
      {"negative_length",
       R"({"rho": 20, "mu_s": 0, "shell": "rigid", "numerics": {"element_length": -1e-3}})",
       "/numerics/element_length"},
      {"poisson", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "wire": {"poisson_ratio": 0.7}})",
       "/wire/poisson_ratio"},
      {"mu_d_above_mu_s", R"({"rho": 20, "mu_s": 0.3, "mu_d": 0.4, "shell": "rigid"})", "/mu_d"},
      {"missing_rho", R"({"mu_s": 0, "shell": "rigid"})", "/rho"},
      {"missing_xi", R"({"rho": 20, "eps": 1000, "mu_s": 0})", "/xi"},
      {"seed_float", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "seed": 1.5})", "/seed"},
      {"twist_choice",
       R"({"rho": 20, "mu_s": 0, "shell": "rigid", "numerics": {"twist": "sometimes"}})",
       "/numerics/twist"},
      {"not_object", R"([{"rho": 20}])", "must be a JSON object"},
      {"parse_error", "{\"rho\": 20,\n \"mu_s\": }", "line 2, column"},
  };
  return cases;
}

TEST(Cli, BadScenesExit2AndWriteNothing) {
  for (const auto& c : bad_scenes()) {
    SCOPED_TRACE(c.name);
    TempDir dir;
    const std::string file = std::string(c.name) + ".json";
    dir.write(file, c.text);
    for (const std::string& cmd : {"validate " + file, "run " + file + " --out x.h5"}) {
      SCOPED_TRACE(cmd);
      const Result r = wirepack(dir, cmd);
      EXPECT_EQ(r.code, 2) << r.err;
      EXPECT_NE(r.err.find(file + ": "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(c.key), std::string::npos) << r.err;
      EXPECT_EQ(r.out, "");
      EXPECT_FALSE(fs::exists(dir / "x.h5"));
      EXPECT_FALSE(fs::exists(dir / "x.h5.part"));
    }
  }
}

TEST(Cli, ValidatePrintsResolvedScene) {
  TempDir dir;
  dir.write("s.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid"})");
  const Result r = wirepack(dir, "validate s.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["shell"], "rigid");
  EXPECT_EQ(j["l_max"], 50.0);
  EXPECT_EQ(j["/numerics/element_length"_json_pointer], 0.5e-3);
  EXPECT_FALSE(j.contains("xi"));
  EXPECT_NE(r.err.find("numerics preset \"default\": element_length 1 r"), std::string::npos)
      << r.err;
  dir.write("f.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "numerics": "fast"})");
  const Result f = wirepack(dir, "validate f.json");
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_EQ(nlohmann::json::parse(f.out)["/numerics/tolerance"_json_pointer], 1e-3);
  EXPECT_NE(f.err.find("numerics preset \"fast\": element_length 2 r, shell_mesh_size 4 r, "
                       "quasistatic_ratio 0.02, tolerance 0.001"),
            std::string::npos)
      << f.err;

  for (const char* scene : {"rigid_default.json", "elastic_example.json"}) {
    const Result s =
        wirepack(dir, std::string("validate '") + WIREPACK_SOURCE_DIR "/scenes/" + scene + "'");
    EXPECT_EQ(s.code, 0) << scene << ": " << s.err;
  }
}

TEST(Cli, UsageErrors) {
  TempDir dir;
  dir.write("s.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid"})");
  EXPECT_EQ(wirepack(dir, "").code, 2);
  EXPECT_EQ(wirepack(dir, "frobnicate").code, 2);
  EXPECT_EQ(wirepack(dir, "run s.json").code, 2);  // --out is required
  EXPECT_EQ(wirepack(dir, "validate").code, 2);
  EXPECT_EQ(wirepack(dir, "validate missing.json").code, 2);
  EXPECT_EQ(wirepack(dir, "export missing.h5 --csv x.csv").code, 2);
  EXPECT_EQ(wirepack(dir, "export missing.h5").code, 2);  // neither --csv nor --xdmf
  EXPECT_EQ(wirepack(dir, "--help").code, 0);
  // An output directory that cannot be created (its parent is a file) is refused before any
  // work.
  const Result r = wirepack(dir, "run s.json --out s.json/x.h5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("s.json/x.h5"), std::string::npos) << r.err;
  // A bad scene with a missing output directory creates nothing.
  dir.write("bad.json", R"({"rho": -1, "mu_s": 0, "shell": "rigid"})");
  EXPECT_EQ(wirepack(dir, "run bad.json --out nowhere/x.h5").code, 2);
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
}

TEST(Cli, EmbeddedDefaultSceneValidatesAndCreatesTheOutputDirectory) {
  TempDir dir;
  // The embedded default is the scene of scenes/rigid_default.json.
  dir.write("l1.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "l_max": 0.5})");
  const Result r = wirepack(dir, "run l1.json --out runs/sub/x.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "runs/sub/x.h5"));
}

TEST(Cli, Schema) {
  TempDir dir;
  const Result r = wirepack(dir, "schema");
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("| `/rho` | number | required | > 2 |"), std::string::npos) << r.out;
}

// Run files and manifests are stamped with build_git(), the commit the binary was built from
// (with "-dirty" when its sources differ from it): read at build time, so a build after new
// commits names the new HEAD and not the commit of the last cmake configure.
TEST(Cli, VersionNamesTheCommitItWasBuiltFrom) {
  TempDir dir;
  const int git = std::system(("git -C '" WIREPACK_SOURCE_DIR "' rev-parse --short=12 HEAD >'" +
                               (dir / "head") + "' 2>/dev/null")
                                  .c_str());
  if (!WIFEXITED(git) || WEXITSTATUS(git) != 0) GTEST_SKIP() << "the sources are no git checkout";
  std::string head = read_text(dir / "head");
  while (!head.empty() && std::isspace(static_cast<unsigned char>(head.back()))) head.pop_back();
  ASSERT_EQ(head.size(), 12u) << head;
  const Result r = wirepack(dir, "--version");
  ASSERT_EQ(r.code, 0) << r.err;
  const bool clean = r.out.find("(" + head + ")") != std::string::npos;
  const bool dirty = r.out.find("(" + head + "-dirty)") != std::string::npos;
  EXPECT_TRUE(clean || dirty) << "wirepack --version: " << r.out << "HEAD: " << head;
  EXPECT_EQ(sweep::build_git(), head + (dirty ? "-dirty" : ""));
}

TEST(Cli, ShortRunAndExport) {
  TempDir dir;
  dir.write("s.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "l_max": 1,
                          "numerics": {"element_length": 1e-3}})");
  const Result r = wirepack(dir, "run s.json --out run.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "run.h5\n");
  EXPECT_FALSE(fs::exists(dir / "run.h5.part"));
  const auto rec = sweep::read_run_file(dir / "run.h5");
  EXPECT_EQ(rec.status, sweep::RunStatus::Complete);
  EXPECT_GE(rec.find_series("l")->values.back(), 1.0);

  const Result e = wirepack(dir, "export run.h5 --csv run.csv --xdmf run.xmf");
  ASSERT_EQ(e.code, 0) << e.err;
  const std::string csv = read_text(dir / "run.csv");
  EXPECT_EQ(
      csv.rfind("l,U_b_hat,U_b,U_t,U_s,U_m,U_sb,E_kin,K,N,S,D,R_t,R_x,R_y,dt,wall_s,steps,S_kappa,"
                "D_chord,chord\n",
                0),
      0u);
  EXPECT_NE(read_text(dir / "run.xmf").find("run.h5:/snapshots/"), std::string::npos);

  // --profile: the last snapshot by default; a snapshot that does not exist is bad input.
  const Result p = wirepack(dir, "export run.h5 --profile profile.csv");
  ASSERT_EQ(p.code, 0) << p.err;
  const std::string profile = read_text(dir / "profile.csv");
  EXPECT_NE(
      profile.find("\nfrom_hole,s_R,kappa_R,kappa_n_R,shell_gap_r,self_contacts,in_chord\n0,0,"),
      std::string::npos)
      << profile;
  const Result bad = wirepack(dir, "export run.h5 --profile p2.csv --snapshot 999");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("no snapshot 999"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "p2.csv"));
}

// Twin runs end to end: the same seed twice gives one trajectory (never parts, separation 0);
// a run and its twin with perturbation/offset 1e-6 compare snapshot by snapshot; a file that is
// no run file is bad input and writes nothing.
// Several sweep directories: their critical points in one four-dimensional table (issue 51),
// here the committed golden sweep (rho = 10, rigid: xi and eps blank) read twice; without
// --out it is bad input and nothing is written.
TEST(Cli, AnalyzeSeveralDirectoriesWritesTheFourDimensionalTable) {
  TempDir dir;
  const std::string golden = WIREPACK_SOURCE_DIR "/tests/golden/sweep";
  const Result r = wirepack(dir, "analyze " + golden + " " + golden + " --out p4d --no-plots");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = read_text(dir / "p4d/phase_diagram_4d.csv");
  EXPECT_EQ(csv.rfind("source,order_parameter,axis,rho,xi,eps,mu_s,other,status,", 0), 0u) << csv;
  std::size_t rows = 0, at = 0;
  while ((at = csv.find(golden + ",D,mu_s,10,,,,numerics.tolerance=", at)) != std::string::npos) {
    ++rows;
    ++at;
  }
  EXPECT_EQ(rows, 4u) << csv;  // two tolerance slices of mu_s, twice
  const Result no_out = wirepack(dir, "analyze " + golden + " " + golden);
  EXPECT_EQ(no_out.code, 2);
  EXPECT_NE(no_out.err.find("--out"), std::string::npos) << no_out.err;
}

TEST(Cli, TwinComparesTwoRunsModuloTheFeedAxisRotation) {
  TempDir dir;
  const std::string scene = R"({"rho": 10, "mu_s": 0.5, "shell": "rigid", "l_max": 1.5,
                                "numerics": {"element_length": 1e-3},
                                "output": {"snapshots_every_l": 0.5}})";
  dir.write("a.json", scene);
  std::string twin = scene;
  twin.replace(twin.rfind('}'), 1, R"(, "perturbation": {"offset": 1e-6}})");
  dir.write("b.json", twin);
  ASSERT_EQ(wirepack(dir, "run a.json --out a.h5").code, 0);
  ASSERT_EQ(wirepack(dir, "run a.json --out a2.h5").code, 0);
  ASSERT_EQ(wirepack(dir, "run b.json --out b.h5").code, 0);
  const Result same = wirepack(dir, "twin a.h5 a2.h5 --csv same.csv");
  ASSERT_EQ(same.code, 0) << same.err;
  EXPECT_NE(same.out.find("snapshots compared: 3 (l <= 1.5"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("never parted by more than 1 r (largest 0 r); rms never above 1 r "
                          "(largest 0 r)"),
            std::string::npos)
      << same.out;
  const std::string rows = read_text(dir / "same.csv");
  EXPECT_EQ(rows.rfind("l,separation_r,rms_r\n0.5", 0), 0u) << rows;
  EXPECT_NE(rows.find(",0,0\n"), std::string::npos) << rows;
  const Result ab = wirepack(dir, "twin a.h5 b.h5");
  ASSERT_EQ(ab.code, 0) << ab.err;
  // The 1e-6 r offset is still of its own size at l = 1.5 (a rigid scene that has barely
  // begun to buckle): never parted, the largest separation a few 1e-6 r.
  EXPECT_NE(ab.out.find("snapshots compared: 3"), std::string::npos) << ab.out;
  const auto at = ab.out.find("(largest ");
  ASSERT_NE(at, std::string::npos) << ab.out;
  const double largest = std::stod(ab.out.substr(at + 9));
  EXPECT_GT(largest, 1e-7);
  EXPECT_LT(largest, 1e-4);
  dir.write("not_a_run.h5", "text");
  const Result bad = wirepack(dir, "twin a.h5 not_a_run.h5 --csv bad.csv");
  EXPECT_EQ(bad.code, 2);
  EXPECT_FALSE(fs::exists(dir / "bad.csv"));
}

TEST(Cli, FailedRunExit1) {
  TempDir dir;
  // Forces overflow a double, so the engine stops with a non-finite state.
  dir.write("s.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "l_max": 1,
                          "wire": {"youngs_modulus": 1e300}})");
  const Result r = wirepack(dir, "run s.json --out run.h5");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("run failed"), std::string::npos) << r.err;
  const auto rec = sweep::read_run_file(dir / "run.h5");
  EXPECT_EQ(rec.status, sweep::RunStatus::Failed);
  EXPECT_FALSE(rec.failure.empty());
}

// run --threads 2 without a wait policy or spin count in the environment starts itself once more
// with GOMP_SPINCOUNT set (app/main.cpp): the same arguments reach the run, and its file is the
// one a single thread writes (series equal, all but the wall clock).
TEST(Cli, ThreadedRunRestartsWithASpinCountAndWritesTheSameRun) {
  TempDir dir;
  dir.write("s.json", R"({"rho": 20, "xi": 10, "eps": 1000, "mu_s": 0.3, "l_max": 1.5,
                          "numerics": "fast"})");
  const Result one = wirepack(dir, "run s.json --out one.h5 --threads 1");
  ASSERT_EQ(one.code, 0) << one.err;
  const Result two = wirepack::testing::run_wirepack(dir, "run s.json --out two.h5 --threads 2",
                                                     "env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT");
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(two.out, "two.h5\n");
  const auto a = sweep::read_run_file(dir / "one.h5");
  const auto b = sweep::read_run_file(dir / "two.h5");
  ASSERT_EQ(b.status, sweep::RunStatus::Complete);
  ASSERT_EQ(a.series.size(), b.series.size());
  for (size_t k = 0; k < a.series.size(); ++k) {
    if (a.series[k].name == "wall_s") continue;
    const auto &x = a.series[k].values, &y = b.series[k].values;  // bitwise (NaN where undefined)
    ASSERT_EQ(x.size(), y.size()) << a.series[k].name;
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << a.series[k].name;
  }
}

}  // namespace
}  // namespace wirepack
