// Sweep files (docs/design.md §4.4): grid expansion (counts, order, ids, file names), strict
// validation with the sweep file's own pointers, the embedded default sweep, the cost model.
#include "sweep/config/sweep_config.hpp"

#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sweep/config/json_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

using json = nlohmann::json;

Sweep parse_text(const std::string& text) {
  return parse_sweep(parse_json_text(text, "sweep.json"), "sweep.json");
}

// Every message of the InputError thrown by parsing `text` (fails the test if none).
std::vector<std::string> errors_of(const std::string& text) {
  try {
    parse_text(text);
  } catch (const InputError& e) {
    return e.messages();
  }
  ADD_FAILURE() << "no InputError for " << text;
  return {};
}

bool has_message(const std::vector<std::string>& messages, const std::string& part) {
  for (const auto& m : messages)
    if (m.find(part) != std::string::npos) return true;
  return false;
}

std::string joined(const std::vector<std::string>& messages) {
  std::string out;
  for (const auto& m : messages) out += m + "\n";
  return out;
}

constexpr const char* kSweep = R"({
  "name": "t",
  "base": {"shell": "rigid", "l_max": 1, "numerics": {"element_length": 1e-3}},
  "grid": {"rho": [8, 10], "mu_s": [0, 0.5, 1]},
  "seeds": 2,
  "analysis": {"window": [0.5, 1]}
})";

TEST(SweepConfig, ExpandsGridTimesSeedsInRunOrder) {
  const Sweep sw = parse_text(kSweep);
  EXPECT_EQ(sw.name, "t");
  ASSERT_EQ(sw.axes.size(), 2u);
  // Axes sorted by pointer (/mu_s < /rho): mu_s varies slowest, then rho, then the seed.
  EXPECT_EQ(sw.axes[0].pointer, "/mu_s");
  EXPECT_EQ(sw.axes[1].pointer, "/rho");
  ASSERT_EQ(sw.runs.size(), 3u * 2u * 2u);
  EXPECT_EQ(sw.points(), 6u);
  EXPECT_EQ(sw.seeds, (std::vector<std::uint64_t>{1, 2}));
  std::set<std::string> ids, files;
  for (std::size_t i = 0; i < sw.runs.size(); ++i) {
    const SweepRun& r = sw.runs[i];
    EXPECT_EQ(r.index, i);
    EXPECT_EQ(r.point, i / 2);
    EXPECT_EQ(r.seed, 1 + i % 2);
    const double mu_s = std::vector<double>{0, 0.5, 1}[i / 4];
    const double rho = std::vector<double>{8, 10}[(i / 2) % 2];
    EXPECT_EQ(r.point_values, (json{{"mu_s", mu_s}, {"rho", rho}}));
    EXPECT_EQ(r.scene.engine.mu_s, mu_s);
    EXPECT_EQ(r.scene.engine.rho, rho);
    EXPECT_EQ(r.scene.engine.seed, r.seed);
    EXPECT_EQ(r.scene.resolved["seed"], r.seed);
    EXPECT_EQ(r.id, run_id(r.scene.resolved));
    EXPECT_EQ(r.id.size(), 16u);
    EXPECT_GT(r.cost, 0);
    ids.insert(r.id);
    files.insert(r.file);
  }
  EXPECT_EQ(ids.size(), sw.runs.size());
  EXPECT_EQ(files.size(), sw.runs.size());
  EXPECT_EQ(sw.runs[5].file, "runs/mu_s-0.5_rho-8_s2_" + sw.runs[5].id.substr(0, 12) + ".h5");
  EXPECT_EQ(sw.resolved["seeds"], json::array({1, 2}));
  EXPECT_EQ(sw.resolved["analysis"], (json{{"window", {0.5, 1}}}));
  EXPECT_EQ(sw.analysis, sw.resolved["analysis"]);
}

TEST(SweepConfig, IdsIndependentOfKeyOrderAndNumberSpelling) {
  const Sweep a = parse_text(kSweep);
  // Same sweep: keys in another order, 8 written 8.0, the pointer form of a top-level key.
  const Sweep b = parse_text(R"({
    "seeds": [1, 2], "analysis": {"window": [0.5, 1]},
    "grid": {"mu_s": [0.0, 0.5, 1.0], "/rho": [8.0, 10]},
    "base": {"numerics": {"element_length": 0.001}, "l_max": 1.0, "shell": "rigid"},
    "name": "t"})");
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    EXPECT_EQ(a.runs[i].id, b.runs[i].id) << i;
    EXPECT_EQ(a.runs[i].file, b.runs[i].file) << i;
  }
}

TEST(SweepConfig, RunIdIsFnv1aOfCanonicalJson) {
  // Stable across builds: FNV-1a 64 of the canonical text.
  EXPECT_EQ(canonical_json(json::parse(R"({"b": 1, "a": [2, -0.0, "x"]})")),
            R"({"a":[2.0,0.0,"x"],"b":1.0})");
  EXPECT_EQ(run_id(json::object()), "08f44b07b5901a25");  // FNV-1a 64 of "{}"
  EXPECT_EQ(run_id(json::parse(R"({"rho": 20})")), run_id(json::parse(R"({"rho": 20.0})")));
  EXPECT_NE(run_id(json::parse(R"({"rho": 20})")), run_id(json::parse(R"({"rho": 21})")));
}

TEST(SweepConfig, AddingGridValuesKeepsExistingIds) {
  const Sweep a = parse_text(kSweep);
  const Sweep b = parse_text(R"({
    "name": "t",
    "base": {"shell": "rigid", "l_max": 1, "numerics": {"element_length": 1e-3}},
    "grid": {"rho": [8, 10, 12], "mu_s": [0, 0.5, 1, 2]},
    "seeds": 3
  })");
  EXPECT_EQ(b.runs.size(), 4u * 3u * 3u);
  std::set<std::string> ids;
  for (const auto& r : b.runs) ids.insert(r.file);
  for (const auto& r : a.runs) EXPECT_TRUE(ids.contains(r.file)) << r.file;
}

TEST(SweepConfig, SeedsCountListAndDefault) {
  const auto seeds = [](const std::string& s) {
    return parse_text(R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                          "grid": {})" +
                      s + "}")
        .seeds;
  };
  EXPECT_EQ(seeds(""), (std::vector<std::uint64_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(seeds(R"(, "seeds": 3)"), (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_EQ(seeds(R"(, "seeds": [7, 0, 3])"), (std::vector<std::uint64_t>{7, 0, 3}));
  // An empty grid is one point: the base scene times the seeds.
  const Sweep one = parse_text(R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                                   "grid": {}, "seeds": 2})");
  ASSERT_EQ(one.runs.size(), 2u);
  EXPECT_EQ(one.runs[1].file, "runs/s2_" + one.runs[1].id.substr(0, 12) + ".h5");
}

TEST(SweepConfig, NestedAxesByPointerAndFileNames) {
  const Sweep sw = parse_text(R"({"name": "acc", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
    "grid": {"/numerics/element_length": [1e-3, 5e-4], "/numerics/twist": ["off", "on"]},
    "seeds": [4]})");
  ASSERT_EQ(sw.runs.size(), 4u);
  EXPECT_EQ(sw.runs[1].scene.engine.numerics.element_length, 1e-3);
  EXPECT_EQ(sw.runs[1].scene.engine.numerics.twist, EffectMode::On);
  EXPECT_EQ(sw.runs[1].point_values["/numerics/twist"], "on");
  EXPECT_EQ(sw.runs[1].file.rfind("runs/element_length-0.001_twist-on_s4_", 0), 0u)
      << sw.runs[1].file;
  EXPECT_EQ(sw.runs[2].file.rfind("runs/element_length-5e-04_twist-off_s4_", 0), 0u)
      << sw.runs[2].file;
}

// An axis over a key that is resolved only where it acts (feeder_spin: "free" with twist): the
// runs where it does not act keep the grid's value as their point value, and the two variants get
// distinct ids.
TEST(SweepConfig, AxisOverAKeyResolvedOnlyWhereItActs) {
  const Sweep sw =
      parse_text(R"({"name": "spin", "base": {"rho": 10, "mu_s": 0.5, "shell": "rigid"},
    "grid": {"feeder_spin": ["held", "free"]}, "seeds": 1})");
  ASSERT_EQ(sw.runs.size(), 2u);
  EXPECT_EQ(sw.runs[0].point_values["feeder_spin"], "held");
  EXPECT_EQ(sw.runs[1].point_values["feeder_spin"], "free");
  EXPECT_EQ(sw.runs[0].scene.engine.feeder_spin, FeederSpin::Held);
  EXPECT_EQ(sw.runs[1].scene.engine.feeder_spin, FeederSpin::Free);
  EXPECT_NE(sw.runs[0].id, sw.runs[1].id);
  EXPECT_EQ(sw.runs[0].file.rfind("runs/feeder_spin-held_s1_", 0), 0u) << sw.runs[0].file;
}

struct BadSweep {
  const char* name;
  const char* text;
  const char* message;  // a part of one message
};

TEST(SweepConfig, InvalidSweepsNameThePointer) {
  const std::vector<BadSweep> cases = {
      {"empty_axis", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
                         "grid": {"mu_s": []}})",
       "sweep.json: /grid/mu_s: an axis must list at least one value"},
      {"unknown_key", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                          "grid": {"friction": [0, 1]}})",
       "sweep.json: /grid/friction: unknown scene key; valid axes: rho, xi, eps, mu_s"},
      {"unknown_pointer", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                              "grid": {"/numerics/dt": [0, 1]}})",
       "sweep.json: /grid/~1numerics~1dt: unknown scene key"},
      {"nested_without_slash", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                                   "grid": {"numerics/tolerance": [1e-4]}})",
       "/grid/numerics~1tolerance: unknown scene key; nested keys are JSON pointers"},
      {"not_array", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
                        "grid": {"mu_s": 0.5}})",
       "sweep.json: /grid/mu_s: an axis must be a list of values (got 0.5)"},
      {"duplicate_value", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
                              "grid": {"mu_s": [0, 0.5, 0.50]}})",
       "sweep.json: /grid/mu_s/2: duplicate value 0.5 (also at /grid/mu_s/1)"},
      {"duplicate_int_double", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
                                   "grid": {"mu_s": [1, 1.0]}})",
       "sweep.json: /grid/mu_s/1: duplicate value"},
      {"bad_value", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
                        "grid": {"mu_s": [0, 0.5, -1]}})",
       "sweep.json: /grid/mu_s/2: must be >= 0 (got -1)"},
      {"wrong_type_value", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
                               "grid": {"mu_s": [0, "high"]}})",
       "sweep.json: /grid/mu_s/1: must be a number"},
      {"nested_bad_value", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                               "grid": {"/numerics/twist": ["on", "maybe"]}})",
       "sweep.json: /grid/~1numerics~1twist/1: must be one of"},
      {"same_key_twice", R"({"name": "t", "base": {"mu_s": 0, "shell": "rigid"},
                             "grid": {"rho": [10], "/rho": [12]}})",
       "sweep.json: /grid/rho: the same scene key as /grid/~1rho"},
      {"seed_axis", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                        "grid": {"seed": [1, 2]}})",
       "sweep.json: /grid/seed: the seed is not a grid axis"},
      {"base_seed", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid", "seed": 3},
                        "grid": {}})",
       "sweep.json: /base/seed: the seeds of a sweep are set by /seeds"},
      {"base_unknown", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid",
                                                 "wire": {"diam": 1}}, "grid": {}})",
       "sweep.json: /base/wire/diam: unknown key"},
      {"base_bad_value", R"({"name": "t", "base": {"rho": 1, "mu_s": 0, "shell": "rigid"},
                             "grid": {}})",
       "sweep.json: /base/rho: must be > 2 (got 1)"},
      {"required_missing", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"}, "grid": {}})",
       "sweep.json: /base/mu_s: required key is missing (set it in /base or as a /grid axis)"},
      {"point_dependent", R"({"name": "t", "base": {"rho": 10, "mu_d": 0.4, "shell": "rigid"},
                              "grid": {"mu_s": [0.5, 0.3, 0.2]}})",
       "sweep.json: /base/mu_d: must be <= mu_s = 0.3 (got 0.4) (at grid point mu_s = 0.3)"},
      {"element_vs_rho", R"({"name": "t", "base": {"mu_s": 0, "shell": "rigid"},
          "grid": {"rho": [4, 20], "/numerics/element_length": [1e-3]}})",
       "sweep.json: /grid/~1numerics~1element_length/0: must be <= R/4"},
      {"seeds_zero", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                         "grid": {}, "seeds": 0})",
       "sweep.json: /seeds: a seed count must be in [1, "},
      {"seeds_duplicate", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                              "grid": {}, "seeds": [1, 2, 1]})",
       "sweep.json: /seeds/2: duplicate seed (also at /seeds/0)"},
      {"seeds_negative", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                             "grid": {}, "seeds": [-1]})",
       "sweep.json: /seeds/0: a seed must be an integer >= 0"},
      {"seeds_empty", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                          "grid": {}, "seeds": []})",
       "sweep.json: /seeds: the list of seeds must not be empty"},
      {"analysis_not_object", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                                  "grid": {}, "analysis": [1]})",
       "sweep.json: /analysis: must be an object"},
      {"unknown_top", R"({"name": "t", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                          "grid": {}, "sedes": 3})",
       "sweep.json: /sedes: unknown key; valid keys here: name, base, grid, seeds, analysis"},
      {"missing_name", R"({"base": {"rho": 10, "mu_s": 0, "shell": "rigid"}, "grid": {}})",
       "sweep.json: /name: required key is missing"},
      {"bad_name", R"({"name": "a b", "base": {"rho": 10, "mu_s": 0, "shell": "rigid"},
                       "grid": {}})",
       "sweep.json: /name: must be a non-empty string"},
      {"base_not_object", R"({"name": "t", "base": 3, "grid": {}})",
       "sweep.json: /base: must be a scene object"},
      {"grid_not_object", R"({"name": "t", "base": {"rho": 10, "mu_s": 0}, "grid": [1]})",
       "sweep.json: /grid: must be an object of axes"},
      {"too_many", R"({"name": "t", "base": {"rho": 10, "shell": "rigid"},
          "grid": {"mu_s": [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]}, "seeds": 20000})",
       "sweep.json: /grid: the grid times the seeds has more than"},
      {"not_object", R"([1])", "sweep.json: /: a sweep must be a JSON object"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto messages = errors_of(c.text);
    EXPECT_TRUE(has_message(messages, c.message)) << joined(messages);
  }
}

TEST(SweepConfig, EachProblemReportedOnce) {
  // The bad value is in every run (3 rho values x 4 seeds) but reported once; the good axis
  // values are not mentioned.
  const auto messages = errors_of(R"({"name": "t", "base": {"shell": "rigid"},
    "grid": {"mu_s": [0, -1], "rho": [8, 10, 12]}, "seeds": 4})");
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_EQ(messages[0], "sweep.json: /grid/mu_s/1: must be >= 0 (got -1)");
}

TEST(SweepConfig, LoadSweepReportsDuplicateKeysWithTheRest) {
  wirepack::testing::TempDir dir;
  const std::string path = dir.write("s.json", R"({"name": "t", "name": "u",
    "base": {"rho": 10, "shell": "rigid"}, "grid": {"mu_s": [-1]}})");
  try {
    load_sweep(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(has_message(e.messages(), path + ": /name: duplicate key")) << e.what();
    EXPECT_TRUE(has_message(e.messages(), path + ": /grid/mu_s/0: must be >= 0")) << e.what();
  }
}

TEST(SweepConfig, IsSweepJson) {
  EXPECT_TRUE(is_sweep_json(json::parse(R"({"grid": {}})")));
  EXPECT_FALSE(is_sweep_json(json::parse(R"({"rho": 20, "mu_s": 0})")));
  EXPECT_FALSE(is_sweep_json(json::parse(R"([{"grid": {}}])")));
}

TEST(SweepConfig, EmbeddedDefaultSweepIsTheSceneFile) {
  const json file = load_json_file(WIREPACK_SOURCE_DIR "/scenes/default.sweep.json");
  EXPECT_EQ(canonical_json(file), canonical_json(default_sweep_json()));
  const Sweep sw = parse_sweep(default_sweep_json(), "<default>");
  EXPECT_EQ(sw.name, "default");
  ASSERT_EQ(sw.runs.size(), 4u * 2u);
  for (const auto& r : sw.runs) {
    EXPECT_EQ(r.scene.engine.rho, 20);
    EXPECT_EQ(r.scene.engine.shell, ShellKind::Elastic);
    EXPECT_EQ(r.scene.engine.l_max, 14);
  }
  EXPECT_EQ(sw.runs.back().scene.engine.mu_s, 0.5);
}

TEST(SweepConfig, ExpectedCostFollowsTheWork) {
  SceneParams p;
  p.shell = ShellKind::Rigid;
  p.l_max = 10;
  const double base = expected_cost(p);
  SceneParams longer = p;
  longer.l_max = 20;
  EXPECT_NEAR(expected_cost(longer) / base, 4.0, 1e-12);  // ~ L^2
  SceneParams finer = p;
  finer.numerics.element_length /= 2;
  EXPECT_NEAR(expected_cost(finer) / base, 4.0, 1e-12);  // ~ 1 / ell^2
  SceneParams friction = p;
  friction.mu_s = 0.5;
  EXPECT_NEAR(expected_cost(friction) / base, 2.0, 1e-12);  // twist on
  SceneParams elastic = p;
  elastic.shell = ShellKind::Elastic;
  EXPECT_GT(expected_cost(elastic), base);
}

TEST(SweepConfig, PresetAxisAndNumericsKeysOverAPresetBase) {
  const Sweep sw = parse_text(R"({"name": "p", "base": {"rho": 20, "mu_s": 0, "shell": "rigid",
      "numerics": "fast"}, "grid": {"/numerics/preset": ["fast", "accurate"],
      "/numerics/tolerance": [1e-2]}, "seeds": 1})");
  ASSERT_EQ(sw.runs.size(), 2u);
  EXPECT_EQ(sw.runs[0].scene.numerics_preset, "fast");
  EXPECT_EQ(sw.runs[0].scene.engine.numerics.element_length, 1e-3);
  EXPECT_EQ(sw.runs[1].scene.numerics_preset, "accurate");
  EXPECT_EQ(sw.runs[1].scene.engine.numerics.element_length, 0.25e-3);
  for (const auto& r : sw.runs) EXPECT_EQ(r.scene.engine.numerics.tolerance, 1e-2);
  EXPECT_NE(sw.runs[0].id, sw.runs[1].id);
  EXPECT_EQ(sw.runs[0].point_values["/numerics/preset"], "fast");
  // The preset is not part of the run's identity: its resolved values are.
  for (const auto& r : sw.runs) EXPECT_FALSE(r.scene.resolved["numerics"].contains("preset"));
  const Sweep plain = parse_text(R"({"name": "q", "base": {"rho": 20, "mu_s": 0, "shell": "rigid",
      "numerics": {"element_length": 1e-3, "shell_mesh_size": 2e-3, "quasistatic_ratio": 0.02,
      "tolerance": 1e-2}}, "grid": {}, "seeds": 1})");
  EXPECT_EQ(plain.runs[0].id, sw.runs[0].id);
}

}  // namespace
}  // namespace wirepack::sweep

namespace wirepack::sweep {
namespace {

// Listed points (/points, what `wirepack refine` adds): after the grid's points, with the same
// ids and file names as grid points of equal values would have.
TEST(SweepConfig, ListedPointsFollowTheGrid) {
  const Sweep sw = parse_text(R"({
    "name": "t", "base": {"shell": "rigid", "l_max": 1, "numerics": {"element_length": 1e-3}},
    "grid": {"mu_s": [0, 1], "rho": [8]},
    "points": [{"mu_s": 0.25, "rho": 8}, {"rho": 10, "mu_s": 0.5}],
    "seeds": 2})");
  ASSERT_EQ(sw.points(), 4u);
  ASSERT_EQ(sw.runs.size(), 8u);
  EXPECT_EQ(sw.runs[4].point, 2u);
  EXPECT_EQ(sw.runs[4].point_values, (json{{"mu_s", 0.25}, {"rho", 8.0}}));
  EXPECT_EQ(sw.runs[7].point_values, (json{{"mu_s", 0.5}, {"rho", 10.0}}));
  EXPECT_EQ(sw.runs[7].seed, 2u);
  EXPECT_EQ(sw.runs[4].file, "runs/mu_s-0.25_rho-8_s1_" + sw.runs[4].id.substr(0, 12) + ".h5");
  ASSERT_EQ(sw.listed_points.size(), 2u);
  EXPECT_EQ(sw.resolved["points"], json::parse(R"([{"mu_s": 0.25, "rho": 8}, {"mu_s": 0.5,
    "rho": 10}])"));
  // The resolved sweep parses to the same runs (the manifest keeps it).
  const Sweep again = parse_sweep(sw.resolved, "manifest");
  ASSERT_EQ(again.runs.size(), sw.runs.size());
  for (std::size_t i = 0; i < sw.runs.size(); ++i) EXPECT_EQ(again.runs[i].id, sw.runs[i].id);
  // The same point on the grid has the same id.
  const Sweep grid = parse_text(R"({
    "name": "t", "base": {"shell": "rigid", "l_max": 1, "numerics": {"element_length": 1e-3}},
    "grid": {"mu_s": [0.25], "rho": [8]}, "seeds": 2})");
  EXPECT_EQ(grid.runs[0].file, sw.runs[4].file);
  // Without listed points the resolved sweep has no "points" key (manifests unchanged).
  EXPECT_FALSE(grid.resolved.contains("points"));
}

TEST(SweepConfig, InvalidListedPointsNameThePointer) {
  const std::string head = R"({"name": "t", "base": {"shell": "rigid", "l_max": 1},
    "grid": {"mu_s": [0, 1]}, "seeds": 1, "points": )";
  auto e = errors_of(head + R"({"mu_s": 0.5}})");
  EXPECT_TRUE(has_message(e, "sweep.json: /points: must be a list")) << joined(e);
  e = errors_of(head + R"([{"mu_s": 1}]})");
  EXPECT_TRUE(has_message(e, "sweep.json: /points/0: repeats a point of /grid")) << joined(e);
  e = errors_of(head + R"([{"mu_s": 0.5}, {"mu_s": 0.5}]})");
  EXPECT_TRUE(has_message(e, "sweep.json: /points/1: repeats /points/0")) << joined(e);
  e = errors_of(head + R"([{"rho": 10}]})");
  EXPECT_TRUE(has_message(e, "sweep.json: /points/0/rho: not a grid axis")) << joined(e);
  EXPECT_TRUE(has_message(e, "sweep.json: /points/0/mu_s: required key is missing")) << joined(e);
  e = errors_of(head + R"([{"mu_s": -1}]})");
  EXPECT_TRUE(has_message(e, "sweep.json: /points/0/mu_s: must be >= 0")) << joined(e);
}

// Extra seeds at single points (what `wirepack refine` adds near x_c): their runs follow every
// point's, with the ids a sweep with those seeds in /seeds gives, and the resolved sweep keeps
// them.
TEST(SweepConfig, ExtraSeedsAddRunsAtNamedPoints) {
  const Sweep sw = parse_text(R"({
    "name": "t", "base": {"rho": 10, "shell": "rigid", "l_max": 1, "numerics": {"element_length": 1e-3}},
    "grid": {"mu_s": [0, 1]}, "points": [{"mu_s": 0.5}], "seeds": 2,
    "extra_seeds": [{"mu_s": 0.5, "seeds": [3, 4]}, {"mu_s": 0, "seeds": [7]},
                    {"mu_s": 0.5, "seeds": [5]}]})");
  EXPECT_EQ(sw.grid_points, 2u);
  EXPECT_EQ(sw.points(), 3u);
  ASSERT_EQ(sw.runs.size(), 3u * 2u + 4u);
  ASSERT_EQ(sw.extra_seeds.size(), 3u);
  EXPECT_EQ(sw.extra_seeds[0].point, 2u);
  EXPECT_EQ(sw.extra_seeds[1].point, 0u);
  const std::vector<std::pair<std::size_t, std::uint64_t>> tail = {{2, 3}, {2, 4}, {0, 7}, {2, 5}};
  for (std::size_t k = 0; k < tail.size(); ++k) {
    const SweepRun& r = sw.runs[6 + k];
    EXPECT_EQ(r.index, 6 + k);
    EXPECT_EQ(r.point, tail[k].first);
    EXPECT_EQ(r.seed, tail[k].second);
  }
  // The same (point, seed) as an ordinary run: the same id and file.
  const Sweep plain = parse_text(R"({
    "name": "t", "base": {"rho": 10, "shell": "rigid", "l_max": 1, "numerics": {"element_length": 1e-3}},
    "grid": {"mu_s": [0.5]}, "seeds": [3, 4]})");
  EXPECT_EQ(sw.runs[6].id, plain.runs[0].id);
  EXPECT_EQ(sw.runs[7].file, plain.runs[1].file);
  // The resolved sweep (the manifest's) parses to the same runs.
  EXPECT_EQ(sw.resolved["extra_seeds"], json::parse(R"([{"mu_s": 0.5, "seeds": [3, 4]},
    {"mu_s": 0, "seeds": [7]}, {"mu_s": 0.5, "seeds": [5]}])"));
  const Sweep again = parse_sweep(sw.resolved, "manifest");
  ASSERT_EQ(again.runs.size(), sw.runs.size());
  for (std::size_t i = 0; i < sw.runs.size(); ++i) EXPECT_EQ(again.runs[i].file, sw.runs[i].file);
  // Without extra seeds the resolved sweep has no such key (manifests unchanged).
  EXPECT_FALSE(plain.resolved.contains("extra_seeds"));
}

TEST(SweepConfig, InvalidExtraSeedsNameThePointer) {
  const std::string head = R"({"name": "t", "base": {"rho": 10, "shell": "rigid", "l_max": 1},
    "grid": {"mu_s": [0, 1]}, "seeds": 2, "extra_seeds": )";
  auto e = errors_of(head + R"({"mu_s": 0}})");
  EXPECT_TRUE(has_message(e, "sweep.json: /extra_seeds: must be a list")) << joined(e);
  e = errors_of(head + R"([{"mu_s": 0.5, "seeds": [3]}]})");
  EXPECT_TRUE(has_message(e, "sweep.json: /extra_seeds/0: names no point of the sweep"))
      << joined(e);
  e = errors_of(head + R"([{"mu_s": 0, "seeds": [2, 3]}]})");
  EXPECT_TRUE(has_message(
      e, "sweep.json: /extra_seeds/0/seeds/0: the point already has seed 2 (from /seeds)"))
      << joined(e);
  e = errors_of(head + R"([{"mu_s": 1, "seeds": [3]}, {"mu_s": 1, "seeds": [4, 3]}]})");
  EXPECT_TRUE(has_message(e,
                          "sweep.json: /extra_seeds/1/seeds/1: the point already has seed 3 "
                          "(from /extra_seeds/0/seeds/0)"))
      << joined(e);
  e = errors_of(head + R"([{"mu_s": 1}, {"mu_s": 1, "seeds": []}, {"rho": 8, "seeds": [-1]}]})");
  EXPECT_TRUE(has_message(e, "sweep.json: /extra_seeds/0/seeds: required key is missing"))
      << joined(e);
  EXPECT_TRUE(has_message(e, "sweep.json: /extra_seeds/1/seeds: must be a non-empty list"))
      << joined(e);
  EXPECT_TRUE(has_message(e, "sweep.json: /extra_seeds/2/rho: not a grid axis")) << joined(e);
  EXPECT_TRUE(has_message(e, "sweep.json: /extra_seeds/2/mu_s: required key is missing"))
      << joined(e);
  // The same seed at another point is fine.
  EXPECT_EQ(
      parse_text(head + R"([{"mu_s": 0, "seeds": [3]}, {"mu_s": 1, "seeds": [3]}]})").runs.size(),
      6u);
}

}  // namespace
}  // namespace wirepack::sweep
