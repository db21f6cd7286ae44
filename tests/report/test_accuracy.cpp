// The accuracy-vs-time study (issue 7): the relative RMS error against known answers, and the
// study's small version on real runs (two element lengths x two seeds and two tolerances, rigid
// sphere, l = 2.5): ladders, references, the seed floor and the documented CSV columns.
#include "report/accuracy.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "sweep/config/json_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"
#include "sweep/running/sweep_runner.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::report {
namespace {

using namespace wirepack::sweep;

using wirepack::testing::TempDir;

TEST(Accuracy, RelativeRmsErrorKnownAnswers) {
  const std::vector<double> l = {0, 1, 2, 3, 4};
  const std::vector<double> y = {1, 2, 3, 4, 5};
  std::vector<double> y11;
  for (double v : y) y11.push_back(1.1 * v);
  EXPECT_NEAR(relative_rms_error(l, y11, l, y, 0, 4), 0.1, 1e-14);
  EXPECT_EQ(relative_rms_error(l, y, l, y, 0, 4), 0.0);
  // The reference on another grid: linear data interpolate exactly.
  const std::vector<double> lr = {0, 0.5, 1.5, 2.5, 3.5, 4.5};
  std::vector<double> yr;
  for (double x : lr) yr.push_back(1 + x);
  EXPECT_NEAR(relative_rms_error(l, y, lr, yr, 0, 4), 0.0, 1e-14);
  // Only rows in the window count: a difference outside it is not seen.
  std::vector<double> y_out = y;
  y_out[0] = 100;
  EXPECT_EQ(relative_rms_error(l, y_out, l, y, 1, 4), 0.0);
  EXPECT_TRUE(std::isnan(relative_rms_error(l, y, l, y, 10, 20)));
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

void run(const std::string& text, const std::string& dir) {
  const Sweep sw = parse_sweep(parse_json_text(text, "s.json"), "s.json");
  SweepOptions o;
  o.dir = dir;
  o.threads = 2;
  const SweepOutcome out = run_sweep(sw, o);
  ASSERT_EQ(out.complete, sw.runs.size());
}

TEST(Accuracy, SmallStudyWritesLaddersAndFloor) {
  TempDir tmp;
  const std::string base = R"("base": {"rho": 20, "shell": "rigid", "mu_s": 0, "l_max": 2.5,
      "output": {"snapshots_every_l": 10}})";
  run(R"({"name": "el", )" + base +
          R"(, "grid": {"/numerics/element_length": [1e-3, 5e-4]}, "seeds": [1, 2]})",
      tmp / "el");
  run(R"({"name": "tol", )" + base + R"(, "grid": {"/numerics/tolerance": [1e-3, 1e-4]},
      "seeds": [1]})",
      tmp / "tol");
  AccuracyOptions o;
  o.dirs = {tmp / "el", tmp / "tol"};
  o.window = {0.5, 50};
  o.gnuplot.clear();
  const AccuracyResult r = accuracy_study(o);
  // 5 runs (the centre el = 5e-4, tol = 1e-3, seed 1 is in both sweeps and read once).
  EXPECT_EQ(r.runs, 5u);
  EXPECT_EQ(r.ladders, 3u);  // element_length (seeds 1, 2), tolerance (seed 1)
  EXPECT_EQ(r.rows, 8u);     // 2 + 2 + 2 ladder rows, 2 floor rows
  EXPECT_TRUE(std::filesystem::exists(tmp / "el/accuracy/pareto.gp"));

  std::ifstream in(r.csv);
  std::string line;
  std::getline(in, line);
  std::string header;
  for (const auto& c : accuracy_columns()) header += (header.empty() ? "" : ",") + c;
  EXPECT_EQ(line, header);
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < accuracy_columns().size(); ++i) col[accuracy_columns()[i]] = i;
  int refs = 0, floors = 0;
  while (std::getline(in, line)) {
    const auto c = split(line);
    ASSERT_EQ(c.size(), accuracy_columns().size()) << line;
    const double err = std::stod(c[col["err_U_b_hat"]]);
    const bool is_ref = c[col["is_reference"]] == "1";
    EXPECT_GT(std::stod(c[col["wall_s"]]), 0);
    EXPECT_GT(std::stod(c[col["steps"]]), 0);
    EXPECT_NEAR(std::stod(c[col["l_end"]]), 2.5, 0.05);
    if (is_ref) {
      ++refs;
      EXPECT_EQ(err, 0.0);
      EXPECT_EQ(c[col["file"]], c[col["reference_file"]]);
      EXPECT_EQ(std::stod(c[col["wall_ratio"]]), 1.0);
    } else {
      // A coarser setting or another seed differs, and by less than 100 %.
      EXPECT_GT(err, 0) << line;
      EXPECT_LT(err, 1) << line;
      EXPECT_GE(std::stod(c[col["err_UK"]]), err);
    }
    if (c[col["knob"]] == "seed") {
      ++floors;
      EXPECT_EQ(std::stod(c[col["element_length"]]), 5e-4);  // floors compare the centres
      EXPECT_EQ(std::stod(c[col["tolerance"]]), 1e-3);
    }
    if (c[col["knob"]] != "seed" && !is_ref) {
      EXPECT_EQ(std::stod(c[col["value"]]), 1e-3);  // the coarser of each ladder
    }
  }
  EXPECT_EQ(refs, 4);  // the finest of each ladder and seed 1 of the floor
  EXPECT_EQ(floors, 2);
}

// Presets differ in several knobs at once: compared with the run finest in every knob.
TEST(Accuracy, PresetsAreComparedWithTheFinestRun) {
  TempDir tmp;
  run(R"({"name": "p", "base": {"rho": 20, "shell": "rigid", "mu_s": 0, "l_max": 2.5},
      "grid": {"/numerics/preset": ["fast", "default"]}, "seeds": [1]})",
      tmp / "p");
  AccuracyOptions o;
  o.dirs = {tmp / "p"};
  o.window = {0.5, 50};
  o.gnuplot.clear();
  const AccuracyResult r = accuracy_study(o);
  EXPECT_EQ(r.ladders, 0u);
  ASSERT_EQ(r.rows, 2u);
  std::ifstream in(r.csv);
  std::string line;
  std::getline(in, line);
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < accuracy_columns().size(); ++i) col[accuracy_columns()[i]] = i;
  int refs = 0;
  while (std::getline(in, line)) {
    const auto c = split(line);
    EXPECT_EQ(c[col["knob"]], "combined");
    const bool is_ref = c[col["is_reference"]] == "1";
    refs += is_ref;
    // The reference is the default preset (element r); fast has 2 r; both tolerance 1e-3.
    EXPECT_EQ(std::stod(c[col["element_length"]]), is_ref ? 5e-4 : 1e-3);
    EXPECT_EQ(std::stod(c[col["tolerance"]]), 1e-3);
    if (!is_ref) {
      EXPECT_GT(std::stod(c[col["err_U_b_hat"]]), 0);
    }
  }
  EXPECT_EQ(refs, 1);
}

TEST(Accuracy, BadInputIsAnInputError) {
  TempDir tmp;
  AccuracyOptions o;
  o.dirs = {tmp / "missing"};
  EXPECT_THROW(accuracy_study(o), InputError);
  std::filesystem::create_directories(tmp / "empty/runs");
  o.dirs = {tmp / "empty"};
  EXPECT_THROW(accuracy_study(o), InputError);
  EXPECT_FALSE(std::filesystem::exists(tmp / "empty/accuracy"));
}

}  // namespace
}  // namespace wirepack::report
