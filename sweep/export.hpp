#pragma once
// `wirepack export` (docs/design.md §4.7): a run file's series as CSV, its snapshots as an XDMF
// sidecar for ParaView. Both are written to a temporary name and renamed when complete.
#include <string>

namespace wirepack::sweep {

// One header row with the run file's series names in recording order (the columns of
// recorded_series() when the run was made, docs/design.md §5.7), then one row per record;
// numbers in shortest round-trip form ("nan" where an observable is undefined).
// Throws RunFileError if the run file cannot be read or the CSV cannot be written.
void export_csv(const std::string& run_file, const std::string& csv_path);

// XDMF 3 temporal collection, one time step (Time = l) per snapshot: the wire as a Polyline
// with node attributes `curvature` and `wire_contacts` and, where the snapshot has one, the
// shell as a triangle mesh with cell attribute `shell_area_stretch` and node attributes
// `shell_contact_force` (vector) and `shell_clamped`; each field only where the run file has it.
// Heavy data stay in the run file, referenced by its path relative to the .xmf file; a mesh shared
// by all snapshots (run file layout 2) is referenced once, at /shell_triangles.
void export_xdmf(const std::string& run_file, const std::string& xmf_path);

}  // namespace wirepack::sweep
