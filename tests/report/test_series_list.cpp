// The one list of recorded series (docs/design.md §5.7, sweep/runfile/series.hpp): its columns, the
// series the reports name, the table in docs/reference.md, and one extra series passed through
// the run loop, `wirepack export --csv` and `wirepack analyze`'s series.csv.
#include "sweep/runfile/series.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "report/analyze.hpp"
#include "report/reductions.hpp"
#include "sweep/runfile/export.hpp"
#include "sweep/running/run.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::report {
namespace {

using sweep::recorded_series;
using sweep::SeriesContext;
using sweep::SeriesList;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string c; std::getline(in, c, ',');) out.push_back(c);
  return out;
}

TEST(SeriesList, ColumnsAndFlags) {
  const SeriesList& list = recorded_series();
  EXPECT_EQ(sweep::series_names(), sweep::names_of(list));
  std::set<std::string> names;
  for (const auto& s : list) {
    EXPECT_TRUE(names.insert(s.name).second) << "twice: " << s.name;
    EXPECT_FALSE(s.unit.empty()) << s.name;
    EXPECT_FALSE(s.description.empty()) << s.name;
    EXPECT_TRUE(s.compute) << s.name;
  }
  // series.csv and accuracy.csv columns, in their order (tests/golden keeps their bytes).
  EXPECT_EQ(kept_series(), (std::vector<std::string>{"D", "U_b_hat", "K", "N", "R_t", "R_x", "R_y",
                                                     "S_kappa", "D_chord"}));
  EXPECT_EQ(sweep::accuracy_series(), (std::vector<std::string>{"U_b_hat", "K", "N"}));
}

// Every series a report names as a physics quantity is in the list and kept where it must be.
TEST(SeriesList, NamedSeriesAreInTheList) {
  EXPECT_NO_THROW(check_named_series(recorded_series()));
  for (const auto& e : exponent_specs()) {
    const auto* s = sweep::find_series_def(e.series);
    ASSERT_NE(s, nullptr) << e.name;
    EXPECT_GT(s->analysis_rank, 0) << e.series;
  }
  for (const char* name : {"l", "D", "N", "steps", "wall_s"})  // read by the accuracy study
    EXPECT_NE(sweep::find_series_def(name), nullptr) << name;

  SeriesList without_D = recorded_series();
  std::erase_if(without_D, [](const sweep::SeriesDef& s) { return s.name == "D"; });
  try {
    check_named_series(without_D);
    ADD_FAILURE() << "a list without D passed";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find(": D"), std::string::npos) << e.what();
  }
}

// The table of series in docs/reference.md (section "Run file (HDF5)") is the list's markdown
// (regenerate: copy it from this failure).
TEST(SeriesList, ReadmeTableIsGenerated) {
  const std::string readme = read_text(WIREPACK_SOURCE_DIR "/docs/reference.md");
  const std::string md = sweep::series_markdown();
  EXPECT_NE(readme.find("\n" + md + "\n"), std::string::npos)
      << "docs/reference.md's table of series differs from sweep::series_markdown():\n"
      << md;
  EXPECT_EQ(md.rfind("| name | unit | meaning |\n| --- | --- | --- |\n| `l` | - |", 0), 0u) << md;
  // A '|' in a description is escaped, so each row keeps three cells.
  const SeriesList piped = {{"x", "-", "|x|", {}}};
  EXPECT_NE(sweep::series_markdown(piped).find("| `x` | - | \\|x\\| |\n"), std::string::npos);
}

// Adding a series to the list adds a column to the run file, the CSV export and series.csv.
TEST(SeriesList, AnExtraSeriesReachesEveryTable) {
  SeriesList list = recorded_series();
  list.push_back(
      {"twice_l", "-", "2 l (test)", [](const SeriesContext& c) { return 2 * c.sim().l(); }, 100});
  TempDir dir;
  const sweep::Scene scene =
      sweep::parse_scene({{"rho", 20},
                          {"mu_s", 0},
                          {"shell", "rigid"},
                          {"l_max", 1.0},
                          {"numerics", {{"element_length", 1e-3}}},
                          {"output", {{"every_l", 0.1}, {"snapshots_every_l", 0.5}}}},
                         "short.json");
  const std::string run = dir / "runs/run.h5";
  std::filesystem::create_directories(dir / "runs");
  ASSERT_EQ(sweep::run_scene(scene, run, nullptr, {}, list).status, sweep::RunStatus::Complete);

  // (a) the run file: the extra column last, computed per row.
  const sweep::RunRecord r = sweep::read_run_file(run);
  ASSERT_EQ(r.series.size(), list.size());
  EXPECT_EQ(r.series.back().name, "twice_l");
  const auto& l = r.find_series("l")->values;
  ASSERT_GE(l.size(), 5u);
  for (std::size_t i = 0; i < l.size(); ++i) EXPECT_EQ(r.series.back().values[i], 2 * l[i]);

  // (b) the CSV export.
  sweep::export_csv(run, dir / "run.csv");
  std::istringstream csv(read_text(dir / "run.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  const auto cols = split(header);
  ASSERT_EQ(cols.size(), list.size());
  EXPECT_EQ(cols.back(), "twice_l");
  EXPECT_EQ(std::stod(split(row).back()), 2 * l[0]);

  // (c) the analysis's seed-averaged series: after the kept ones, before the Purohit predictions.
  AnalyzeOptions o;
  o.dir = dir.path().string();
  o.out = dir / "analysis";
  o.gnuplot = "";
  o.series = list;
  analyze_sweep(o);
  std::istringstream series(read_text(dir / "analysis/series.csv"));
  std::getline(series, header);
  EXPECT_NE(header.find("_sem,twice_l_mean,twice_l_sem,U_b_hat_purohit_mean,"), std::string::npos)
      << header;
  const auto names = split(header);
  const auto at = std::find(names.begin(), names.end(), "twice_l_mean") - names.begin();
  const auto l_at = std::find(names.begin(), names.end(), "l") - names.begin();
  std::size_t rows = 0;
  for (std::string line; std::getline(series, line); ++rows) {
    const auto cells = split(line);
    ASSERT_GT(cells.size(), static_cast<std::size_t>(at));
    EXPECT_NEAR(std::stod(cells[at]), 2 * std::stod(cells[l_at]), 0.01) << line;
  }
  EXPECT_GE(rows, 5u);
  EXPECT_LE(rows, l.size());

  // Without the extra series in the list, the analysis has no such column: it is the list, not
  // the run file, that says what the analysis keeps.
  o.series = recorded_series();
  analyze_sweep(o);
  EXPECT_EQ(read_text(dir / "analysis/series.csv").find("twice_l"), std::string::npos);
}

}  // namespace
}  // namespace wirepack::report
