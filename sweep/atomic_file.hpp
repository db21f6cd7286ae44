#pragma once
// The one atomic text-file writer (docs/design.md §6.3): manifests, analysis tables, gnuplot
// scripts, refine.json, accuracy.csv and the exported CSV and XDMF all go through it.
#include <stdexcept>
#include <string>

namespace wirepack::sweep {

// A file could not be written (the message names the file and the system's reason).
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes all of `text` to the open descriptor `fd`, retrying short writes; false on error
// (errno set).
bool write_all(int fd, const std::string& text);

// Writes `text` to PATH.tmp.<pid>, fsyncs and renames it to `path`, so readers see the old or
// the new file, never a partial one; on failure the temporary is removed. Throws WriteError.
void write_file_atomic(const std::string& path, const std::string& text);

}  // namespace wirepack::sweep
