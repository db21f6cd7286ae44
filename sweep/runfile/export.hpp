#pragma once
// `wirepack export` (docs/design.md §4.7): a run file's series as CSV, its snapshots as an XDMF
// sidecar for ParaView; the CSV also from a checkpoint, for a run part-way. Both are written to
// a temporary name and renamed when complete.
#include <string>

#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep {

// The record to export from `run_file`: a run file (HDF5), or the checkpoint of a run part-way
// (RUN.h5.ckpt: what it has recorded so far, status running). A `.part` file is refused even
// when readable: only a renamed file is known to be whole. Throws RunFileError with the file
// and what is wrong.
RunRecord read_run_for_export(const std::string& run_file);

// One header row with the run file's series names in recording order (the columns of
// recorded_series() when the run was made, docs/design.md §5.7), then one row per record;
// numbers in shortest round-trip form ("nan" where an observable is undefined).
// Throws RunFileError if the run file cannot be read or the CSV cannot be written.
void export_csv(const std::string& run_file, const std::string& csv_path);

// XDMF 3 temporal collection (from a run file only: it references the file's datasets), one time
// step (Time = l) per snapshot: the wire as a Polyline with node attributes `curvature` and
// `wire_contacts` and, where the snapshot has one, the shell as a triangle mesh with cell attribute
// `shell_area_stretch` and node attributes `shell_contact_force` (vector) and `shell_clamped`; each
// field only where the run file has it. Heavy data stay in the run file, referenced by its path
// relative to the .xmf file; a mesh shared by all snapshots (run file layout 2) is referenced once,
// at /shell_triangles.
void export_xdmf(const std::string& run_file, const std::string& xmf_path);
// Throws RunFileError where `run_file` cannot back an XDMF file (a checkpoint), so that a caller
// writing several outputs can refuse before writing any.
void check_xdmf_source(const std::string& run_file);

}  // namespace wirepack::sweep
