// Sweep bookkeeping (docs/design.md §4.5): shards, SLURM job-array defaults, the manifest document,
// atomic writes, the joblog CSV and the per-shard lock.
#include "sweep/running/sweep_manifest.hpp"

#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "sweep/atomic_file.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

TEST(SweepManifest, ParseShard) {
  const Shard s = parse_shard("1/3", "--shard");
  EXPECT_EQ(s.index, 1u);
  EXPECT_EQ(s.count, 3u);
  EXPECT_EQ(s.text(), "1/3");
  EXPECT_EQ(s.suffix(), ".shard-1-of-3");
  EXPECT_EQ(Shard{}.suffix(), "");
  EXPECT_EQ(parse_shard("0/1", "--shard").suffix(), "");
  for (const char* bad : {"3/3", "1", "/3", "1/", "-1/3", "a/3", "1/0", "1/3x", " 1/3", ""}) {
    SCOPED_TRACE(bad);
    try {
      parse_shard(bad, "--shard");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--shard: must be K/N"), std::string::npos);
    }
  }
}

TEST(SweepManifest, ShardsPartitionTheRunOrder) {
  for (std::size_t i = 0; i < 20; ++i) {
    int owners = 0;
    for (std::size_t k = 0; k < 3; ++k) owners += Shard{k, 3}.contains(i);
    EXPECT_EQ(owners, 1) << i;
    EXPECT_TRUE(Shard{}.contains(i));
  }
  EXPECT_TRUE((Shard{2, 3}.contains(5)));
}

TEST(SweepManifest, ShardFromSlurmEnvironment) {
  const auto from = [](std::map<std::string, std::string> env) {
    return shard_from_env([env](const char* name) -> const char* {
      const auto it = env.find(name);
      return it == env.end() ? nullptr : it->second.c_str();
    });
  };
  EXPECT_FALSE(from({}).has_value());
  EXPECT_FALSE(from({{"SLURM_ARRAY_TASK_ID", "2"}}).has_value());
  auto s = from({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->text(), "2/4");
  // --array=1-4 (ids from 1), --array=0-9:3 (ids 0, 3, 6, 9).
  s = from({{"SLURM_ARRAY_TASK_ID", "4"},
            {"SLURM_ARRAY_TASK_COUNT", "4"},
            {"SLURM_ARRAY_TASK_MIN", "1"}});
  EXPECT_EQ(s->text(), "3/4");
  s = from({{"SLURM_ARRAY_TASK_ID", "6"},
            {"SLURM_ARRAY_TASK_COUNT", "4"},
            {"SLURM_ARRAY_TASK_MIN", "0"},
            {"SLURM_ARRAY_TASK_STEP", "3"}});
  EXPECT_EQ(s->text(), "2/4");
  EXPECT_THROW(from({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}), InputError);
  EXPECT_THROW(from({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}), InputError);
}

TEST(SweepManifest, PathsPerShard) {
  EXPECT_EQ(manifest_path("d", Shard{}), "d/manifest.json");
  EXPECT_EQ(joblog_path("d", Shard{}), "d/joblog.csv");
  EXPECT_EQ(lock_path("d", Shard{}), "d/.lock");
  EXPECT_EQ(manifest_path("d", Shard{0, 2}), "d/manifest.shard-0-of-2.json");
  EXPECT_EQ(joblog_path("d", Shard{1, 2}), "d/joblog.shard-1-of-2.csv");
  EXPECT_EQ(lock_path("d", Shard{1, 2}), "d/.lock.shard-1-of-2");
}

TEST(SweepManifest, ManifestDocument) {
  const Sweep sw = parse_sweep(json::parse(R"({"name": "m", "base": {"rho": 10, "shell": "rigid"},
                                               "grid": {"mu_s": [0, 1]}, "seeds": 1})"),
                               "m.json");
  std::vector<ManifestEntry> entries = {{&sw.runs[0]}, {&sw.runs[1]}};
  entries[0].status = EntryStatus::Complete;
  entries[0].wall_s = 1.5;
  entries[1].status = EntryStatus::Failed;
  entries[1].reason = "NaN";
  const json m = manifest_json(sw, Shard{}, entries);
  EXPECT_EQ(m["sweep"], sw.resolved);
  EXPECT_EQ(m["shard"], "0/1");
  EXPECT_EQ(m["counts"],
            (json{{"runs", 2}, {"pending", 0}, {"running", 0}, {"complete", 1}, {"failed", 1}}));
  ASSERT_EQ(m["runs"].size(), 2u);
  EXPECT_EQ(m["runs"][0]["id"], sw.runs[0].id);
  EXPECT_EQ(m["runs"][0]["file"], sw.runs[0].file);
  EXPECT_EQ(m["runs"][0]["point"], (json{{"mu_s", 0.0}}));
  EXPECT_EQ(m["runs"][0]["status"], "complete");
  EXPECT_EQ(m["runs"][0]["wall_s"], 1.5);
  EXPECT_EQ(m["runs"][1]["status"], "failed");
  EXPECT_EQ(m["runs"][1]["reason"], "NaN");
  EXPECT_TRUE(m["runs"][1]["wall_s"].is_null());
}

TEST(SweepManifest, AtomicWriteReplacesWhole) {
  TempDir dir;
  const std::string path = dir / "m.json";
  write_file_atomic(path, "first\n");
  write_file_atomic(path, "second\n");
  EXPECT_EQ(read_text(path), "second\n");
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) {
    (void)e;
    ++files;
  }
  EXPECT_EQ(files, 1u);  // no temporary left behind
  EXPECT_THROW(write_file_atomic(dir / "missing/m.json", "x"), std::runtime_error);
}

TEST(SweepManifest, JobLogAppendsAcrossOpens) {
  TempDir dir;
  const std::string path = dir / "joblog.csv";
  {
    JobLog log(path);
    log.append({"abc", "runs/a.h5", "2024-01-01T00:00:00Z", "2024-01-01T00:00:02Z", 2.0, "complete",
                "", "0/1"});
  }
  {
    JobLog log(path);  // a resumed sweep: no second header
    log.append(
        {"def", "runs/b.h5", "s", "e", 0.25, "failed", "step collapse, dt = 1e-20 \"x\"", "1/2"});
  }
  EXPECT_EQ(read_text(path),
            "id,file,start,end,wall_s,status,reason,shard\n"
            "abc,runs/a.h5,2024-01-01T00:00:00Z,2024-01-01T00:00:02Z,2.000,complete,,0/1\n"
            "def,runs/b.h5,s,e,0.250,failed,\"step collapse, dt = 1e-20 \"\"x\"\"\",1/2\n");
}

TEST(SweepManifest, LockRefusesASecondHolder) {
  TempDir dir;
  const std::string path = dir / ".lock";
  {
    DirLock first(path);
    EXPECT_TRUE(first.held());
    try {
      DirLock second(path);
      ADD_FAILURE() << "second lock acquired";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("another `wirepack sweep`"), std::string::npos);
    }
  }
  DirLock again(path);  // released with the first
  EXPECT_TRUE(again.held());
}

}  // namespace
}  // namespace wirepack::sweep
