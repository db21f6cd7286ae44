#pragma once
// Numbers typed by a user on the command line (`--critical-range`, `--only`, ...).
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace wirepack::sweep {

// The whole of `text` as a finite double; empty when it is not one.
inline std::optional<double> to_double(const std::string& text) {
  if (text.empty()) return {};
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return {};
  return v;
}

}  // namespace wirepack::sweep
