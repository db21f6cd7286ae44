#include "report/csv_table.hpp"

#include <algorithm>

#include "sweep/config/json_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::report {

using json = nlohmann::json;

std::string text_of(const json& v) {
  if (v.is_number()) return sweep::csv_number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

void flatten(const json& j, const std::string& pointer, std::map<std::string, json>& out) {
  if (j.is_object() && !j.empty()) {
    for (const auto& [k, v] : j.items()) flatten(v, sweep::pointer_child(pointer, k), out);
  } else {
    out[pointer] = j;
  }
}

int compare_values(const json& a, const json& b) {
  const auto rank = [](const json& v) {
    return v.is_null() ? 0 : v.is_number() ? 1 : v.is_string() ? 2 : 3;
  };
  if (rank(a) != rank(b)) return rank(a) < rank(b) ? -1 : 1;
  if (a.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    return x < y ? -1 : y < x ? 1 : 0;
  }
  const std::string x = a.is_string() ? a.get<std::string>() : sweep::canonical_json(a);
  const std::string y = b.is_string() ? b.get<std::string>() : sweep::canonical_json(b);
  return x.compare(y) < 0 ? -1 : x.compare(y) > 0 ? 1 : 0;
}

std::string column_name(const std::string& pointer) {
  std::string s = pointer.substr(1);
  std::replace(s.begin(), s.end(), '/', '.');
  return s;
}

}  // namespace wirepack::report
