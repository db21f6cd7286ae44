#pragma once
// The HDF5 plumbing of the run file (run_file.cpp writes, run_file_read.cpp reads; nothing else
// includes it): HDF5 errors become RunFileError, handles close themselves.
#include <mutex>
#include <string>

#include <hdf5.h>

#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep::h5 {

// Throws RunFileError: `what`, then HDF5's outermost and innermost error descriptions.
[[noreturn]] void fail(const std::string& what);
// fail(what) if status < 0.
void check(herr_t status, const std::string& what);

// An HDF5 id, closed with `close` at scope exit; a negative id fails with `what`.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) fail(what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  hid_t get() const { return id_; }
  // Closes now and reports failure (a file's final flush happens here).
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    check(close_(id), what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Locks the HDF5 mutex and silences HDF5's automatic error printing (per thread in a
// thread-safe build, so it is set on every entry).
class Hdf5Lock {
 public:
  Hdf5Lock() : lock_(hdf5_mutex()) { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

 private:
  std::lock_guard<std::mutex> lock_;
};

// A variable-length UTF-8 string type.
Handle utf8_string_type();

}  // namespace wirepack::sweep::h5
