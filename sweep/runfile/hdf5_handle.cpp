#include "sweep/runfile/hdf5_handle.hpp"

namespace wirepack::sweep::h5 {

namespace {

struct ErrorWalk {
  std::string outer, inner;  // the API-level and the innermost description
};

herr_t walk_error(unsigned n, const H5E_error2_t* err, void* data) {
  auto* w = static_cast<ErrorWalk*>(data);
  if (err->desc && *err->desc) {
    if (n == 0) w->outer = err->desc;
    w->inner = err->desc;
  }
  return 0;
}

}  // namespace

void fail(const std::string& what) {
  ErrorWalk w;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, walk_error, &w);
  H5Eclear2(H5E_DEFAULT);
  std::string msg = what;
  if (!w.outer.empty()) msg += ": " + w.outer;
  if (!w.inner.empty() && w.inner != w.outer) msg += " (" + w.inner + ")";
  throw RunFileError(msg);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

Handle utf8_string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose, "copy string type");
  check(H5Tset_size(t.get(), H5T_VARIABLE), "set string size");
  check(H5Tset_cset(t.get(), H5T_CSET_UTF8), "set string charset");
  return t;
}

}  // namespace wirepack::sweep::h5
