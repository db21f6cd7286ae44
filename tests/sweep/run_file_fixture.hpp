#pragma once
// A small elastic run in run file layout 1 (triangles in every snapshot, nothing compressed):
// tests/sweep/data/run_layout1.h5 was written from layout1_record() by the write_run_file of
// wirepack 0.1.0 at commit 4820c39, the last one writing layout 1. Readers must keep reading it.
#include "sweep/runfile/run_file.hpp"

namespace wirepack::testing {

inline constexpr const char* kLayout1Fixture = "tests/sweep/data/run_layout1.h5";

inline sweep::RunRecord layout1_record() {
  sweep::RunRecord r;
  r.config = {{"rho", 20.0}, {"shell", "elastic"}};
  r.status = sweep::RunStatus::Complete;
  r.version = "0.1.0";
  r.git = "4820c39";
  r.started = "2026-12-01T22:00:00Z";
  r.finished = "2026-12-01T22:00:01Z";
  r.series = {{"l", {0.0, 0.5, 1.0}}, {"U_b_hat", {0.0, 1.5, 2.25}}};
  for (int k = 0; k < 3; ++k) {
    sweep::Snapshot s;
    s.l = 0.5 * k;
    s.wire = {{0, 0, -1e-2}, {0, 1e-3 * k, -9e-3}, {1e-3, 1e-3 * k, -8e-3}};
    s.curvature = {0, 2.5 * k, 0};
    s.shell_vertices = {{0, 0, 1e-2}, {1e-2, 0, 0}, {0, 1e-2, 0}, {-1e-2, 0, 1e-3 * k}};
    s.shell_triangles = {{0, 1, 2}, {0, 2, 3}};
    r.snapshots.push_back(s);
  }
  return r;
}

}  // namespace wirepack::testing
