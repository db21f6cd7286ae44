// Run checkpoints (docs/design.md §4.8): the file round-trips bit for bit; a damaged, cut, foreign
// or other-format file is refused with its reason; a run that finds an unusable checkpoint says
// why, starts at l = 0 and ends bitwise as a run without one; writing checkpoints (here every
// 10 ms) changes nothing of the run and leaves no checkpoint behind. Resuming after a
// SIGKILL is tested end to end in tests/app (test_cli_checkpoint.cpp, test_kill_campaign.cpp).
#include "sweep/runfile/run_checkpoint.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "engine/simulation.hpp"
#include "engine/state_archive.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/running/run.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using wirepack::testing::TempDir;

Scene short_elastic(double l_max) {
  return parse_scene({{"rho", 10},
                      {"shell", "elastic"},
                      {"xi", 10},
                      {"eps", 1000},
                      {"mu_s", 0.5},
                      {"l_max", l_max},
                      {"numerics", "fast"},
                      {"output", {{"every_l", 0.1}, {"snapshots_every_l", 0.5}}}},
                     "short.json");
}

RunCheckpoint sample_checkpoint() {
  RunCheckpoint c;
  c.config = R"({"rho":10})";
  c.record.version = "v";
  c.record.git = "g";
  c.record.started = "2026-12-02T00:00:00Z";
  c.record.series = {{"l", {0.0, 0.1, 0.2}}, {"D", {1.0, 0.5, -0.0}}};
  Snapshot s;
  s.l = 0.2;
  s.wire = {{1e-3, 2e-3, 3e-3}, {4e-3, 5e-3, 6e-3}};
  s.curvature = {0.0, 123.456};
  s.shell_vertices = {{1, 2, 3}};
  s.shell_triangles = {{0, 0, 0}};
  s.wire_contacts = {0, 2};
  s.shell_area_stretch = {1.25};
  s.shell_contact_force = {{0.5, -0.5, 1e-300}};
  s.shell_clamped = {1};
  c.record.snapshots = {s, Snapshot{}};
  c.wall_s = 12.5;
  c.next_row = 0.3;
  c.next_snapshot = 0.5;
  c.last_row_l = 0.2;
  c.last_snapshot_l = 0.2;
  c.engine = std::string("\0engine\xff bytes", 14);
  return c;
}

std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The reason of read_checkpoint's refusal ("" if it reads).
std::string refusal(const std::string& path) {
  try {
    read_checkpoint(path);
  } catch (const CheckpointError& e) {
    return e.what();
  }
  return "";
}

TEST(RunCheckpoint, RoundTripsBitForBit) {
  TempDir dir;
  const RunCheckpoint c = sample_checkpoint();
  const std::string path = dir / "run.h5.ckpt";
  write_checkpoint(c, path);
  const RunCheckpoint r = read_checkpoint(path);
  EXPECT_EQ(r.config, c.config);
  EXPECT_EQ(r.record.version, "v");
  EXPECT_EQ(r.record.git, "g");
  EXPECT_EQ(r.record.started, c.record.started);
  EXPECT_EQ(r.wall_s, 12.5);
  EXPECT_EQ(r.next_row, 0.3);
  EXPECT_EQ(r.next_snapshot, 0.5);
  EXPECT_EQ(r.last_row_l, 0.2);
  EXPECT_EQ(r.last_snapshot_l, 0.2);
  EXPECT_EQ(r.engine, c.engine);
  ASSERT_EQ(r.record.series.size(), 2u);
  EXPECT_EQ(r.record.series[1].name, "D");
  EXPECT_TRUE(std::signbit(r.record.series[1].values[2]));  // -0.0 kept
  EXPECT_EQ(r.record.series[1].values, c.record.series[1].values);
  ASSERT_EQ(r.record.snapshots.size(), 2u);
  const Snapshot& s = r.record.snapshots[0];
  const Snapshot& t = c.record.snapshots[0];
  EXPECT_EQ(s.l, t.l);
  EXPECT_EQ(s.wire, t.wire);
  EXPECT_EQ(s.curvature, t.curvature);
  EXPECT_EQ(s.shell_vertices, t.shell_vertices);
  EXPECT_EQ(s.shell_triangles, t.shell_triangles);
  EXPECT_EQ(s.wire_contacts, t.wire_contacts);
  EXPECT_EQ(s.shell_area_stretch, t.shell_area_stretch);
  EXPECT_EQ(s.shell_contact_force, t.shell_contact_force);
  EXPECT_EQ(s.shell_clamped, t.shell_clamped);
  EXPECT_TRUE(r.record.snapshots[1].wire.empty());
  // Written atomically: nothing but the file itself is left.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(RunCheckpoint, DamagedCutForeignOrNewerFilesAreRefused) {
  TempDir dir;
  const std::string path = dir / "run.h5.ckpt";
  write_checkpoint(sample_checkpoint(), path);
  const std::string good = read_bytes(path);

  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x10;
  write_bytes(path, flipped);
  EXPECT_NE(refusal(path).find("damaged (checksum mismatch)"), std::string::npos) << refusal(path);

  write_bytes(path, good.substr(0, good.size() - 3));
  EXPECT_NE(refusal(path).find("damaged"), std::string::npos) << refusal(path);

  write_bytes(path, "HDF5 or anything else, long enough to hold a header");
  EXPECT_NE(refusal(path).find("not a wirepack checkpoint"), std::string::npos) << refusal(path);

  std::string newer = good;  // the format number follows the 20-byte magic line
  const std::int32_t format = kCheckpointFormat + 1;
  std::memcpy(newer.data() + 20, &format, sizeof format);
  write_bytes(path, newer);
  EXPECT_NE(refusal(path).find("checkpoint format " + std::to_string(kCheckpointFormat + 1)),
            std::string::npos)
      << refusal(path);

  EXPECT_NE(refusal(dir / "missing.ckpt").find("cannot be opened"), std::string::npos);
}

// Reads a run file's series except wall time, for bitwise comparisons.
std::vector<Series> series_without_wall(const std::string& path) {
  RunRecord r = read_run_file(path);
  std::vector<Series> out;
  for (auto& s : r.series)
    if (s.name != "wall_s") out.push_back(std::move(s));
  return out;
}

void expect_same_series(const std::string& a, const std::string& b) {
  const auto x = series_without_wall(a), y = series_without_wall(b);
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t c = 0; c < x.size(); ++c) {
    ASSERT_EQ(x[c].name, y[c].name);
    ASSERT_EQ(x[c].values.size(), y[c].values.size()) << x[c].name;
    EXPECT_EQ(
        std::memcmp(x[c].values.data(), y[c].values.data(), x[c].values.size() * sizeof(double)), 0)
        << x[c].name;
  }
}

TEST(RunCheckpoint, FrequentCheckpointsChangeNothing) {
  TempDir dir;
  const Scene scene = short_elastic(2.2);
  const std::string plain = dir / "plain.h5", checked = dir / "checked.h5";
  ASSERT_EQ(run_scene(scene, plain, nullptr).status, RunStatus::Complete);
  const RunOutcome out =
      run_scene(scene, checked, nullptr, {}, recorded_series(), CheckpointOptions{0.01});
  ASSERT_EQ(out.status, RunStatus::Complete) << out.failure;
  EXPECT_EQ(out.checkpoint_note, "");
  EXPECT_EQ(out.resumed_l, -1);
  EXPECT_FALSE(fs::exists(checkpoint_path(checked)));
  expect_same_series(plain, checked);
}

TEST(RunCheckpoint, UnusableCheckpointIsReportedAndTheRunStartsAfresh) {
  TempDir dir;
  const Scene scene = short_elastic(1.6);
  const std::string plain = dir / "plain.h5";
  ASSERT_EQ(run_scene(scene, plain, nullptr).status, RunStatus::Complete);

  // Garbage where the checkpoint should be.
  const std::string run = dir / "run.h5";
  write_bytes(checkpoint_path(run), "garbage");
  std::ostringstream progress;
  RunOutcome out = run_scene(scene, run, &progress, {}, recorded_series(), CheckpointOptions{600});
  ASSERT_EQ(out.status, RunStatus::Complete) << out.failure;
  EXPECT_NE(out.checkpoint_note.find("checkpoint not used"), std::string::npos);
  EXPECT_NE(progress.str().find("not a wirepack checkpoint"), std::string::npos) << progress.str();
  EXPECT_EQ(out.resumed_l, -1);
  EXPECT_FALSE(fs::exists(checkpoint_path(run)));
  expect_same_series(plain, run);

  // A sound checkpoint of another scene (its engine state would not even fit).
  RunCheckpoint other = sample_checkpoint();
  write_checkpoint(other, checkpoint_path(run));
  out = run_scene(scene, run, nullptr, {}, recorded_series(), CheckpointOptions{600});
  ASSERT_EQ(out.status, RunStatus::Complete) << out.failure;
  EXPECT_NE(out.checkpoint_note.find("holds another configuration"), std::string::npos)
      << out.checkpoint_note;
  expect_same_series(plain, run);

  // The right configuration with an engine state that does not restore.
  other.config = canonical_json(scene.resolved);
  other.record.series.clear();
  for (const auto& name : series_names()) other.record.series.push_back({name, {}});
  write_checkpoint(other, checkpoint_path(run));
  out = run_scene(scene, run, nullptr, {}, recorded_series(), CheckpointOptions{600});
  ASSERT_EQ(out.status, RunStatus::Complete) << out.failure;
  EXPECT_NE(out.checkpoint_note.find("checkpoint state at byte"), std::string::npos)
      << out.checkpoint_note;
  expect_same_series(plain, run);

  // Checkpoints off: an existing file is neither read nor removed.
  write_bytes(checkpoint_path(run), "garbage");
  out = run_scene(scene, run, nullptr);
  EXPECT_EQ(out.checkpoint_note, "");
  EXPECT_TRUE(fs::exists(checkpoint_path(run)));
}

// A state saved at any step continues bitwise: every restore of the kill campaign's frictional
// rigid scene (tests/app/test_kill_campaign.cpp, mu_s = 0.5, seed 3), one per step over
// steps 1850-2000 and one every 25 steps to the end, is stepped 150 steps (or to the end) and
// compared byte for byte with the uninterrupted run's state at the same step. With the friction
// table's free-slot key taken for a contact (fixed 2026-12-04) the restores from step 1873 to
// 1993 of this scene's former trajectory parted at step 1993.
TEST(RunCheckpoint, RestoresAtManyStepsContinueBitwise) {
  const Scene scene = parse_scene({{"rho", 10},
                                   {"shell", "rigid"},
                                   {"l_max", 8},
                                   {"numerics", "fast"},
                                   {"mu_s", 0.5},
                                   {"seed", 3}},
                                  "kill.json");
  Simulation run(scene.engine);
  std::vector<std::uint64_t> hash{fnv1a64(run.save_state())};  // by step
  std::vector<std::pair<long, std::string>> saved;
  while (!run.finished()) {
    run.step();
    std::string bytes = run.save_state();
    hash.push_back(fnv1a64(bytes));
    const long k = run.steps();
    if ((k >= 1850 && k <= 2000) || k % 25 == 0) saved.emplace_back(k, std::move(bytes));
  }
  ASSERT_GT(run.steps(), 5000);
  int parted = 0;
  for (const auto& [k, bytes] : saved) {
    Simulation resumed(scene.engine);
    resumed.restore_state(bytes);
    for (int j = 0; j < 150 && !resumed.finished(); ++j) resumed.step();
    const long at = resumed.steps();
    if (fnv1a64(resumed.save_state()) != hash[at]) {
      if (++parted <= 5) ADD_FAILURE() << "restored at step " << k << ", parted by step " << at;
    }
  }
  EXPECT_EQ(parted, 0) << "of " << saved.size() << " restores";
}

}  // namespace
}  // namespace wirepack::sweep
